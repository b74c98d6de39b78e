// The moon in a rendered image (scene `moon`, docs/night-sky.md): its disc where the
// ephemeris puts it, and its lit side toward the sun.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../test_support.h"
#include "skylit/core/angles.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/render/camera.h"
#include "skylit/render/renderer.h"
#include "skylit/sun/moon_position.h"
#include "skylit/sun/solar_position.h"
#include "skylit/sun/time.h"

namespace skylit {
namespace {

constexpr int kSize = 96;  // pixels across a 3° field: 0.031° a pixel, the disc ~17 across

struct MoonImage {
  XyzImage image;
  ImageCamera camera;
  Vec3 to_moon, to_sun;
};

// A narrow view of the moon over Amsterdam at `time`, aimed 0.4° off the disc's centre.
MoonImage render_moon(const std::string& time) {
  const SiteLocation site{52.37, 4.90, 0};
  const double jd = julian_day_ut(parse_offset_date_time(time, "test"));
  const MoonPosition moon = moon_position(site, jd);
  const SolarPosition sun = solar_position(site, jd);
  const Vec3 to_moon = direction_from_altitude_azimuth(moon.altitude_deg, moon.azimuth_deg);
  const Vec3 aim = direction_from_altitude_azimuth(moon.altitude_deg + 0.3, moon.azimuth_deg - 0.4);
  const std::string scene_text = R"({
    "camera": {"position": [0, 0, 1.6], "look_at": [)" +
                                 std::to_string(100 * aim.x) + ", " + std::to_string(100 * aim.y) + ", " +
                                 std::to_string(1.6 + 100 * aim.z) + R"(], "vertical_fov_deg": 3},
    "site": {"latitude_deg": 52.37, "longitude_deg": 4.90}, "time": ")" +
                                 time + R"(", "moon": "auto",
    "materials": {"ground": {"type": "diffuse", "reflectance": 0.1}},
    "objects": [{"type": "plane", "material": "ground", "size_m": 20}],
    "render": {"width": 96, "height": 96, "samples_per_axis": 2}})";
  testing::TempDir dir;
  const Scene scene = load_scene(dir.write("moon.json", scene_text));
  const Renderer renderer(scene);
  return {renderer.render(), ImageCamera(scene.camera, kSize, kSize), to_moon,
          direction_from_altitude_azimuth(sun.altitude_deg, sun.azimuth_deg)};
}

// The luminance-weighted centroid of the pixels brighter than 1 cd/m² (the disc is
// thousands of cd/m², the night sky around it below 0.1), in pixel coordinates.
std::pair<double, double> disc_centroid(const XyzImage& image) {
  double sum = 0, sx = 0, sy = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const double l = image.at(x, y).y;
      if (l < 1) continue;
      sum += l;
      sx += l * (x + 0.5);
      sy += l * (y + 0.5);
    }
  EXPECT_GT(sum, 0);
  return {sx / sum, sy / sum};
}

TEST(MoonRender, TheFullMoonsDiscIsWhereTheEphemerisPutsIt) {
  // 26 January 2024, 0h UT: the moon 6 h after full (phase angle about 3°), high in the
  // south. The centroid's direction within 0.1° (3 pixels) of the ephemeris, the issue's
  // tolerance; a near-full disc's lit centroid is within 0.01° of its centre.
  const MoonImage m = render_moon("2024-01-26T00:00:00+00:00");
  const auto [cx, cy] = disc_centroid(m.image);
  const Vec3 seen = m.camera.ray_through(cx, cy).direction;
  EXPECT_LT(degrees(std::acos(std::min(1.0, dot(normalize(seen), m.to_moon)))), 0.1);
}

TEST(MoonRender, TheLitSideOfAQuarterMoonFacesTheSun) {
  // 17 January 2024, 18h UT: a waxing moon near first quarter in the south, the sun set
  // in the west-south-west. The lit part's centroid lies off the disc's centre toward
  // the sun's place on the sky (the image direction of a small step from the moon toward
  // the sun), by about 4/(3π) of the radius (0.11°) for a half disc.
  const MoonImage m = render_moon("2024-01-17T18:00:00+00:00");
  const auto [cx, cy] = disc_centroid(m.image);
  const auto centre = m.camera.project(m.camera.ray_through(0, 0).origin + 1000 * m.to_moon);
  const Vec3 toward_sun = normalize(m.to_sun - m.to_moon * dot(m.to_sun, m.to_moon));
  const auto sunward =
      m.camera.project(m.camera.ray_through(0, 0).origin + 1000 * normalize(m.to_moon + 0.001 * toward_sun));
  ASSERT_TRUE(centre && sunward);
  const double ux = sunward->first - centre->first, uy = sunward->second - centre->second;
  const double norm = std::hypot(ux, uy);
  const double along = ((cx - centre->first) * ux + (cy - centre->second) * uy) / norm;
  const double across = ((cx - centre->first) * uy - (cy - centre->second) * ux) / norm;
  const double pixel_deg = 3.0 / kSize;
  EXPECT_GT(along * pixel_deg, 0.05);
  EXPECT_LT(along * pixel_deg, 0.2);
  EXPECT_LT(std::abs(across) * pixel_deg, 0.03);
}

}  // namespace
}  // namespace skylit
