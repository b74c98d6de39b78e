// Koschmieder's law in the rendered image, from the program: in a uniform fog of
// visibility V, a black target at distance d shows the contrast −e^(−3.912·d/V) against
// the fog horizon behind it (−0.02 at V), times the air's own transmittance over d,
// since the air is mixed with the fog and dims the target too (view_path.h). That
// holds for the paper's single scattering (the default). With the fog's multiple
// scattering (an option) the droplets' forward spike, a fraction f of their scattering
// within half a degree, sends on the light that arrives along the view, which in front
// of a target wider than the spike is the target's own: its contrast is
// −e^(−(1−f)·3.912·d/V) (δ-M's extinction; docs/fog.md measures one of these targets
// with the path tracer).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "../test_support.h"
#include "skylit/atmosphere/atmosphere.h"
#include "skylit/core/angles.h"
#include "skylit/io/image/image_reader.h"
#include "skylit/media/fog_diffuse_field.h"
#include "skylit/media/fog_layer.h"
#include "skylit/spectrum/cie.h"

namespace skylit {
namespace {

constexpr int kWidth = 120, kHeight = 16;
constexpr double kFovDeg = 1.0;           // vertical; the horizontal one is 7.5°
constexpr double kCameraHeightM = 1.6;    // looking level, north
constexpr double kSunAltitudeDeg = 40.0;  // behind the camera: the phase function is flat across the image
constexpr double kDistancesInV[] = {1, 2, 20};
constexpr int kTargets = 3;

double target_azimuth_deg(int i) { return (i - (kTargets - 1) / 2.0) * kFovDeg * kWidth / kHeight / (kTargets + 0.5); }
int target_column(int i) {
  return static_cast<int>(std::lround((target_azimuth_deg(i) / (kFovDeg * kWidth / kHeight) + 0.5) * kWidth - 0.5));
}
// Each target's half-width as an angle (rad), and so in pixels.
constexpr double kHalfWidthRad = kFovDeg * kWidth / kHeight / (kTargets + 0.5) / 4 * kPi / 180;
constexpr int kHalfWidthPx = static_cast<int>(kWidth / (kTargets + 0.5) / 4);

std::string koschmieder_scene(double visibility_m, double aod, bool multiple_scattering) {
  std::ostringstream s;
  s.precision(10);
  s << R"({"camera": {"position": [0, 0, 1.6], "look_at": [0, 1000, 1.6], "vertical_fov_deg": )" << kFovDeg
    << R"(}, "sun": {"altitude_deg": )" << kSunAltitudeDeg << R"(, "azimuth_deg": 180},
  "atmosphere": {"aod_550": )"
    << aod << R"(},
  "fog": {"visibility_m": )"
    << visibility_m << R"(, "scale_height_m": 1e6, "top_m": 400, "multiple_scattering": )"
    << (multiple_scattering ? "true" : "false") << R"(},
  "materials": {"black": {"type": "diffuse", "reflectance": 0}}, "objects": [)";
  // Black boxes whose near faces are at V, 2V and 20V, each 0.54° wide and 0.6° tall.
  for (int i = 0; i < kTargets; ++i) {
    const double d = kDistancesInV[i] * visibility_m, a = target_azimuth_deg(i) * kPi / 180;
    const double half = d * std::tan(kHalfWidthRad), tall = d * std::tan(0.3 * kPi / 180);
    const double x = d * std::sin(a), y = d * std::cos(a) + half;
    s << (i ? "," : "") << R"({"type": "box", "material": "black", "min": [)" << x - half << "," << y - half << ","
      << kCameraHeightM - tall << R"(], "max": [)" << x + half << "," << y + half << "," << kCameraHeightM + tall
      << "]}";
  }
  s << R"(], "render": {"width": )" << kWidth << R"(, "height": )" << kHeight << "}}";
  return s.str();
}

// The air's luminance-weighted transmittance along the level view over `distance`.
double air_transmittance(const SkyModel& sky, double distance) {
  const Vec3 level{0, 1, 0};
  const Radiance horizon = sky.sky_radiance(level);
  return luminance((horizon * sky.aerial_perspective(level, distance).transmittance).spectrum()) /
         luminance(horizon.spectrum());
}

// The fraction of the default droplets' scattering that δ-M takes as a forward spike:
// their phase function's Legendre moment χ_2N, N the field's streams per hemisphere.
double forward_spike_fraction() {
  const FogLayer layer{FogSettings{}};
  return phase_legendre_moments([&layer](double c) { return layer.phase(c); }, 2 * FogDiffuseField::kStreams + 1)
      .back();
}

TEST(FogContrast, BlackTargetsFollowKoschmiedersLawInTheRenderedImage) {
  // The tolerance is the issue's ±0.005 on the contrast. What limits it: the targets'
  // faces lie at their distance only to ±0.5 % (the boxes' pixels see their near faces);
  // the sky light gathered by the fog is read from the camera's table (≤ 1e-3 by
  // FogSkyLightTable below); the air's mixing with the fog is exact for a level ray.
  testing::TempDir dir;
  const double spike = forward_spike_fraction();
  ASSERT_GT(spike, 0.3);  // 15 µm droplets: about 0.45
  ASSERT_LT(spike, 0.6);
  for (const bool multiple : {false, true})
    for (const double aod : {0.01, 0.3}) {
      AtmosphereSettings settings;
      settings.aerosol.aod_550 = aod;
      const Atmosphere atmosphere(settings);
      const SkyModel sky(atmosphere, direction_from_altitude_azimuth(kSunAltitudeDeg, 180), kCameraHeightM);
      for (const double visibility : {100.0, 1000.0, 5000.0}) {
        // The air's factor is exact only where its light is a small part of the fog's:
        // its in-scattered light has its own colour and angles. Where the air over d is
        // itself thick (V = 5 km at AOD 0.3: transmittance 0.28) the contrast departs
        // from the product by about a fifth either way (single scattering −0.0066
        // against −0.0055, within the bound; multiple −0.042 against −0.032), so the
        // δ-M law is checked where the air lets through more than 0.6 (a scene whose
        // nearest target, at V, is beyond that is not rendered).
        auto checked = [&](double air) { return !multiple || air >= 0.6; };
        if (!checked(air_transmittance(sky, visibility))) continue;
        const auto scene = dir.write("scene.json", koschmieder_scene(visibility, aod, multiple));
        const auto image = dir.path() / "out.pfm";
        const auto run =
            testing::run_skylit("render " + testing::quoted(scene) + " --quiet -o " + testing::quoted(image));
        ASSERT_EQ(run.exit_status, 0) << run.output;
        const XyzImage xyz = read_image(image);
        // The two rows just above the horizon: 0.03° and 0.09° up.
        auto luminance_at = [&](int x) { return 0.5 * (xyz.at(x, kHeight / 2 - 1).y + xyz.at(x, kHeight / 2 - 2).y); };
        for (int i = 0; i < kTargets; ++i) {
          const int c = target_column(i);
          const double target = luminance_at(c);
          // The fog horizon just beside the target, on both sides.
          const double horizon = 0.5 * (luminance_at(c - kHalfWidthPx - 4) + luminance_at(c + kHalfWidthPx + 4));
          const double air = air_transmittance(sky, kDistancesInV[i] * visibility);
          if (!checked(air)) continue;
          const double extinction = multiple ? 1 - spike : 1;
          const double expected = -std::exp(-extinction * 3.912 * kDistancesInV[i]) * air;
          EXPECT_NEAR((target - horizon) / horizon, expected, 0.005)
              << "AOD " << aod << ", V = " << visibility << " m, target at " << kDistancesInV[i] << " V"
              << (multiple ? ", multiple scattering" : ", single scattering");
        }
      }
    }
}

}  // namespace
}  // namespace skylit
