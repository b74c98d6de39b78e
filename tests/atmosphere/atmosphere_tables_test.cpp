// The process-wide sharing of the sun-independent tables: the same air shares them,
// any change of the air builds new ones, the sun's side (moon, distance, CIE sky,
// night sky) does not, and shared tables give exactly what a cold build gives.
#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <tbb/parallel_for.h>

#include "skylit/atmosphere/aerosol_types.h"
#include "skylit/atmosphere/atmosphere.h"
#include "skylit/core/vec3.h"

namespace skylit {
namespace {

bool share_tables(const Atmosphere& a, const Atmosphere& b) { return &a.integrator() == &b.integrator(); }

TEST(AtmosphereTables, TheSameAirSharesOneBuild) {
  const AtmosphereSettings settings;
  const Atmosphere first(settings), second(settings);
  EXPECT_TRUE(share_tables(first, second));
}

TEST(AtmosphereTables, EveryChangeOfTheAirBuildsItsOwn) {
  // One entry per field of the key: forgetting one in the key would hand the default
  // air's tables to this air.
  const std::vector<std::pair<std::string, std::function<void(AtmosphereSettings&)>>> changes = {
      {"model", [](AtmosphereSettings& s) { s.model = AtmosphereModel::paper; }},
      {"multiple_scattering",
       [](AtmosphereSettings& s) { s.multiple_scattering = MultipleScatteringMethod::hillaire; }},
      {"aerosol amount", [](AtmosphereSettings& s) { s.aerosol.aod_550 = 0.3; }},
      {"aerosol type",
       [](AtmosphereSettings& s) { s.aerosol = with_aerosol_type(s.aerosol, AerosolType::maritime_clean); }},
      {"aerosol asymmetry", [](AtmosphereSettings& s) { s.aerosol.asymmetry = 0.6; }},
      {"aerosol scale height", [](AtmosphereSettings& s) { s.aerosol.scale_height_m = 2000; }},
      {"ozone", [](AtmosphereSettings& s) { s.ozone_column_du = 250; }},
      {"ground albedo", [](AtmosphereSettings& s) { s.ground_albedo = 0.3; }},
      {"air density", [](AtmosphereSettings& s) { s.air_density = AirDensity::exponential; }},
      {"earth radius", [](AtmosphereSettings& s) { s.earth_radius_m = 6360e3; }},
      {"top altitude", [](AtmosphereSettings& s) { s.top_altitude_m = 80e3; }},
      {"site elevation", [](AtmosphereSettings& s) { s.site_elevation_m = 1500; }},
      {"refraction", [](AtmosphereSettings& s) { s.refraction = false; }},
  };
  const Atmosphere standard{AtmosphereSettings{}};
  for (const auto& [name, change] : changes) {
    AtmosphereSettings settings;
    change(settings);
    EXPECT_FALSE(share_tables(standard, Atmosphere(settings))) << name;
  }
  const Atmosphere other_bands(AtmosphereSettings{}, SpectralBands::consecutive(400, 5));
  EXPECT_FALSE(share_tables(standard, other_bands));
}

TEST(AtmosphereTables, TheSunsSideSharesTheAirsTables) {
  const Atmosphere standard{AtmosphereSettings{}};
  AtmosphereSettings settings;
  settings.earth_sun_distance_au = 1.0167;
  settings.moon = MoonSettings{};
  settings.night_sky.natural = false;
  settings.cie_sky = CieSkySettings{};
  EXPECT_TRUE(share_tables(standard, Atmosphere(settings)));
}

TEST(AtmosphereTables, SharedTablesGiveWhatAColdBuildGives) {
  AtmosphereSettings settings;
  settings.aerosol.aod_550 = 0.17;  // an air no other test uses, so the first build is cold here
  const Vec3 to_sun = normalize(Vec3{0.3, 0.4, 0.2});
  std::vector<Vec3> views;
  for (int i = 0; i < 24; ++i) views.push_back(normalize(Vec3{std::cos(0.7 * i), std::sin(0.7 * i), 0.05 * i - 0.3}));
  const auto sky_of = [&](const Atmosphere& atmosphere) {
    const SkyModel sky(atmosphere, to_sun, 1.6);
    std::vector<Spectrum> radiances;
    for (const Vec3& v : views) radiances.push_back(sky.sky_radiance(v).spectrum());
    radiances.push_back(sky.sky_irradiance(Vec3{1, 0, 0}).spectrum());
    return radiances;
  };
  const Atmosphere first(settings);
  const std::vector<Spectrum> shared = sky_of(Atmosphere(settings));
  forget_shared_atmosphere_tables();
  const Atmosphere cold(settings);
  ASSERT_FALSE(share_tables(first, cold));
  const std::vector<Spectrum> rebuilt = sky_of(cold);
  for (size_t i = 0; i < shared.size(); ++i)
    for (int k = 0; k < kSpectralBins; ++k) EXPECT_EQ(shared[i][k], rebuilt[i][k]) << "value " << i << " bin " << k;
}

TEST(AtmosphereTables, ThreadsAskingForAFewAirsAtOnceEachGetTheirAirs) {
  forget_shared_atmosphere_tables();
  constexpr int kRequests = 12, kAirs = 3;
  const auto settings_of = [](int i) {
    AtmosphereSettings settings;
    settings.ground_albedo = 0.1 + 0.1 * (i % kAirs);
    return settings;
  };
  std::vector<std::unique_ptr<Atmosphere>> atmospheres(kRequests);
  tbb::parallel_for(0, kRequests,
                    [&](int i) { atmospheres[static_cast<size_t>(i)] = std::make_unique<Atmosphere>(settings_of(i)); });
  const Vec3 to_sun = normalize(Vec3{0.2, 0.1, 0.5});
  const Vec3 view{0, 0, 1};
  for (int i = 0; i < kRequests; ++i) {
    // Each got the tables of its own air (two threads asking for a new air at once may
    // both build it: then they hold equal tables, not the same ones).
    const Atmosphere later(settings_of(i));
    EXPECT_EQ(SkyModel(*atmospheres[static_cast<size_t>(i)], to_sun, 1.6).sky_radiance(view)[5],
              SkyModel(later, to_sun, 1.6).sky_radiance(view)[5])
        << i;
    // From then on one table per air is handed out.
    EXPECT_TRUE(share_tables(later, Atmosphere(settings_of(i + kAirs)))) << i;
  }
}

}  // namespace
}  // namespace skylit
