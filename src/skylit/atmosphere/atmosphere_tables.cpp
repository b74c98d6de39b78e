#include "skylit/atmosphere/atmosphere_tables.h"

#include <algorithm>
#include <deque>
#include <mutex>
#include <utility>

namespace skylit {

AtmosphereTables::AtmosphereTables(const AtmosphereSettings& settings, const SpectralBands& bands)
    : medium(settings, bands),
      transmittance(medium, settings.earth_radius_m + settings.site_elevation_m,
                    settings.earth_radius_m + settings.top_altitude_m) {
  if (settings.model == AtmosphereModel::full) {
    if (settings.multiple_scattering == MultipleScatteringMethod::hillaire)
      hillaire = std::make_unique<MultipleScatteringTable>(medium, transmittance, settings.ground_albedo);
    else
      orders = std::make_unique<ScatteringOrdersTable>(medium, transmittance, settings.aerosol, settings.ground_albedo);
  }
  sky_only = std::make_unique<ScatteringIntegrator>(medium, transmittance, hillaire.get(), nullptr, settings.aerosol,
                                                    settings.ground_albedo, orders.get());
  ground_sky = std::make_unique<GroundIrradianceTable>(ScatteringIntegrator::ground_irradiance(*sky_only));
  integrator = std::make_unique<ScatteringIntegrator>(medium, transmittance, hillaire.get(), ground_sky.get(),
                                                      settings.aerosol, settings.ground_albedo, orders.get());
}

namespace {

// Every setting the tables are built from. The sun-side settings (the extraterrestrial
// spectrum's distance, the moon, a CIE sky, the night sky's emission) are left out:
// SkyModel applies them. A setting added to AtmosphereSettings that changes the air
// must be added here, or two different airs would share tables.
struct TablesKey {
  AtmosphereModel model;
  MultipleScatteringMethod multiple_scattering;
  AerosolSettings aerosol;
  double ozone_column_du, ground_albedo;
  AirDensity air_density;
  double rayleigh_scale_height_m, earth_radius_m, top_altitude_m, site_elevation_m;
  bool refraction;
  SpectralBands bands;
  bool operator==(const TablesKey&) const = default;
};

TablesKey key_of(const AtmosphereSettings& s, const SpectralBands& bands) {
  return {.model = s.model,
          .multiple_scattering = s.multiple_scattering,
          .aerosol = s.aerosol,
          .ozone_column_du = s.ozone_column_du,
          .ground_albedo = s.ground_albedo,
          .air_density = s.air_density,
          .rayleigh_scale_height_m = s.rayleigh_scale_height_m,
          .earth_radius_m = s.earth_radius_m,
          .top_altitude_m = s.top_altitude_m,
          .site_elevation_m = s.site_elevation_m,
          .refraction = s.refraction,
          .bands = bands};
}

// A handful: a sweep over aerosol amounts or a test suite alternates between a few
// airs; each entry is a few megabytes.
constexpr size_t kKeptTables = 8;

struct KeptTables {
  std::mutex mutex;
  std::deque<std::pair<TablesKey, std::shared_ptr<const AtmosphereTables>>> newest_first;

  std::shared_ptr<const AtmosphereTables> find(const TablesKey& key) {
    const auto it =
        std::find_if(newest_first.begin(), newest_first.end(), [&](const auto& entry) { return entry.first == key; });
    return it == newest_first.end() ? nullptr : it->second;
  }
};

KeptTables& kept_tables() {
  static KeptTables kept;
  return kept;
}

}  // namespace

std::shared_ptr<const AtmosphereTables> shared_atmosphere_tables(const AtmosphereSettings& settings,
                                                                 const SpectralBands& bands) {
  const TablesKey key = key_of(settings, bands);
  KeptTables& kept = kept_tables();
  {
    const std::lock_guard<std::mutex> lock(kept.mutex);
    if (auto found = kept.find(key)) return found;
  }
  // Built without the lock: the build runs parallel loops, and a thread waiting in one
  // may pick up another task that asks for tables. Two threads asking for the same new
  // air at once both build it; the first one kept is handed out from then on.
  auto built = std::make_shared<const AtmosphereTables>(settings, bands);
  const std::lock_guard<std::mutex> lock(kept.mutex);
  if (auto found = kept.find(key)) return found;
  kept.newest_first.emplace_front(key, built);
  if (kept.newest_first.size() > kKeptTables) kept.newest_first.pop_back();
  return built;
}

void forget_shared_atmosphere_tables() {
  KeptTables& kept = kept_tables();
  const std::lock_guard<std::mutex> lock(kept.mutex);
  kept.newest_first.clear();
}

}  // namespace skylit
