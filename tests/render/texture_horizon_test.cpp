// Texture filtering against aliasing: a checkerboard ground seen to the horizon must show
// its mean, row by row, where its squares are far smaller than a pixel. The reference is
// the same ground in the checkerboard's mean colour without a texture; with point
// sampling (no footprint filter) the far rows of this scene differ from it by up to
// ±45 % (measured), the moiré this guards against.
#include <gtest/gtest.h>

#include <cmath>

#include "../test_support.h"
#include "skylit/io/image/image_encoders.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/render/bands_integrator.h"
#include "skylit/render/image_loop.h"

namespace skylit {
namespace {

using testing::TempDir;

// A 4 km square ground whose texture repeats every metre: 8 × 8 black and white
// squares of 12.5 cm (64 × 64 texels).
void write_ground(const TempDir& dir) {
  const int n = 64;
  std::vector<uint8_t> rgb(static_cast<size_t>(n) * n * 3);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const uint8_t v = ((x / 8 + y / 8) % 2) ? 255 : 0;
      for (int c = 0; c < 3; ++c) rgb[(static_cast<size_t>(y) * n + x) * 3 + c] = v;
    }
  const Bytes png = encode_png_rgb8(n, n, rgb);
  dir.write("checker.png", std::string(png.begin(), png.end()));
  // Black and white average to linear 0.5: the reference's plain colour.
  dir.write("ground.mtl", "newmtl Checker\nKd 1 1 1\nmap_Kd checker.png\nnewmtl Plain\nKd 0.5 0.5 0.5\n");
  for (const char* m : {"Checker", "Plain"})
    dir.write(std::string(m) + ".obj", std::string("mtllib ground.mtl\nv -2000 -2000 0\nv 2000 -2000 0\n") +
                                           "v 2000 2000 0\nv -2000 2000 0\nvt -2000 -2000\nvt 2000 -2000\n" +
                                           "vt 2000 2000\nvt -2000 2000\nusemtl " + m + "\nf 1/1 2/2 3/3 4/4\n");
}

XyzImage render_ground(const TempDir& dir, const std::string& file) {
  const Scene scene = load_scene(dir.write(file + ".json", R"({
    "camera": {"position": [0.3, 0.2, 1.6], "look_at": [0.3, 100, 1.0], "vertical_fov_deg": 30},
    "sun": {"altitude_deg": 35, "azimuth_deg": 200}, "materials": {},
    "objects": [{"type": "mesh", "name": "ground", "file": ")" +
                                                               file +
                                                               R"(.obj", "up_axis": "z"}],
    "render": {"width": 96, "height": 64, "samples_per_axis": 1}})"));
  const PreparedScene prepared(scene);
  const BandsIntegrator integrator(prepared);
  return render_image(prepared, integrator, {});
}

TEST(TextureHorizon, DistantRowsShowTheCheckerboardsMean) {
  TempDir dir;
  write_ground(dir);
  const XyzImage checker = render_ground(dir, "Checker"), plain = render_ground(dir, "Plain");
  // Rows whose ground lies beyond 15 m, where a square of 12.5 cm spans under a pixel
  // (0.47 mrad × 15 m = 7 mm across, and far more along the view), to the ground's far
  // edge near the horizon: the camera looks 0.34° down, so that is row 31.
  int rows = 0;
  double worst = 0;
  for (int y = 0; y < checker.height; ++y) {
    double a = 0, b = 0;
    for (int x = 0; x < checker.width; ++x) a += checker.at(x, y).y, b += plain.at(x, y).y;
    // The row's angle below the horizontal, and where it meets the ground (a 4 km ground
    // ends 2 km away, 0.05° down).
    const double below_deg = std::atan((y + 0.5 - 32.0) / 32.0 * std::tan(15.0 * M_PI / 180)) * 180 / M_PI + 0.34;
    if (!(b > 0) || below_deg < 0.05 || 1.6 / std::tan(below_deg * M_PI / 180) < 15.0) continue;
    ++rows;
    worst = std::max(worst, std::abs(a / b - 1));
  }
  std::cout << rows << " distant rows, worst deviation " << worst << "\n";
  EXPECT_GE(rows, 3);
  // 2 %: the issue's bound. The checkerboard's mean itself is 0.6 % above 0.5 (its mip
  // levels are stored in 8-bit sRGB).
  EXPECT_LT(worst, 0.02);
}

}  // namespace
}  // namespace skylit
