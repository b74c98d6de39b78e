// Automatic exposure (io/image/exposure_meter.h) on rendered day, dusk and night
// scenes: mid-tones land mid whatever the light's level, a lamp-lit street is not burnt
// to white by its dark sky, and a moonless street without lamps stays dark.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "skylit/io/image/image.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/render/camera.h"
#include "skylit/render/renderer.h"

namespace skylit {
namespace {

constexpr int kWidth = 160, kHeight = 90;  // enough pixels for the regions below

Scene small_scene(const std::string& example, std::vector<std::string> overrides = {}) {
  overrides.push_back("render.width=" + std::to_string(kWidth));
  overrides.push_back("render.height=" + std::to_string(kHeight));
  overrides.push_back("render.samples_per_axis=1");
  return load_scene(std::string(SKYLIT_SOURCE_DIR) + "/examples/" + example + ".json", overrides);
}

// The green channel's sRGB code values of the automatically exposed PNG pixels.
std::vector<int> codes(const Scene& scene, const std::vector<std::pair<int, int>>* pixels = nullptr) {
  const XyzImage image = Renderer(scene).render();
  const std::vector<uint8_t> srgb = display_srgb8(image, {});
  std::vector<int> out;
  if (pixels == nullptr)
    for (std::size_t i = 0; i < srgb.size(); i += 3) out.push_back(srgb[i + 1]);
  else
    for (auto [x, y] : *pixels) out.push_back(srgb[3 * (std::size_t(y) * kWidth + x) + 1]);
  return out;
}

int percentile(std::vector<int> v, double p) {
  std::sort(v.begin(), v.end());
  return v[std::size_t(p * double(v.size() - 1))];
}

// Pixels of Fig. 9 that see the road (|x| < 3.5 m) from 8 to 22 m, under the first lamps
// and short of the car: the lit road. (Farther on, the road lies under the lamps' glow
// in the fog near the horizon.) Found by meeting each pixel centre's ray with the ground.
std::vector<std::pair<int, int>> lit_road_pixels(const Scene& scene) {
  const ImageCamera camera(scene.camera, kWidth, kHeight);
  std::vector<std::pair<int, int>> out;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const Ray ray = camera.ray_through(x + 0.5, y + 0.5);
      if (!(ray.direction.z < 0)) continue;
      const Vec3 p = ray.origin + (-ray.origin.z / ray.direction.z) * ray.direction;
      if (std::abs(p.x) < 3.5 && p.y > 8 && p.y < 22) out.emplace_back(x, y);
    }
  return out;
}

TEST(AutomaticExposure, DayAndDuskMidTonesLandMid) {
  // The frame's median code value between 60 and 200: neither murky nor washed out,
  // for a morning sun at 30° and a sun 4° below the horizon (a sky 100× darker).
  for (const char* sun : {"sun.altitude_deg=30", "sun.altitude_deg=-4"}) {
    const int median = percentile(codes(small_scene("building", {sun})), 0.5);
    EXPECT_GE(median, 60) << sun;
    EXPECT_LE(median, 200) << sun;
  }
}

TEST(AutomaticExposure, LampLitStreetAtNightIsNotBurntByItsDarkSky) {
  // The issue's own range for Fig. 9's lit road: median sRGB code value 80 … 200, in
  // light fog as in the paper and without fog, where the sky is 3–4 decades darker
  // than the road. (Measured: 129 and 124; the log-average over the whole frame
  // metered the clear street at 0.12 cd/m² and put its 0.5 cd/m² road at ~235.)
  Scene foggy = small_scene("fig9");
  Scene clear = foggy;
  clear.fog.reset();
  for (const Scene* scene : {&foggy, &clear}) {
    const std::vector<std::pair<int, int>> road = lit_road_pixels(*scene);
    ASSERT_GE(road.size(), 100u);
    const int median = percentile(codes(*scene, &road), 0.5);
    EXPECT_GE(median, 80) << (scene->fog ? "fog" : "clear");
    EXPECT_LE(median, 200) << (scene->fog ? "fog" : "clear");
  }
}

TEST(AutomaticExposure, MoonlessStreetWithoutLampsStaysDark) {
  // Sun 18° below the horizon (the sky ~4e-5 cd/m², docs/lights.md), no lamps: 99 % of
  // the frame below code value 40, where middle-grey metering would give ~118.
  Scene scene = small_scene("fig9", {"sun.altitude_deg=-18"});
  scene.lights.clear();
  EXPECT_LE(percentile(codes(scene), 0.99), 40);
}

}  // namespace
}  // namespace skylit
