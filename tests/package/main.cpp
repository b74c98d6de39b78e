// A scene built in code through the installed public API (no scene file): a ground
// plane and a box under the sun, rendered small. Exit status 0 only if every pixel's
// luminance is finite and non-negative and the image as a whole is lit.
#include <cmath>
#include <cstdio>

#include "skylit/geometry/primitives.h"
#include "skylit/render/renderer.h"
#include "skylit/scene/scene.h"
#include "skylit/spectrum/rgb_to_spectrum.h"

int main() {
  using namespace skylit;
  Scene scene;
  scene.camera = Camera{{0, -40, 1.6}, {0, 0, 8}, {0, 0, 1}, 50.0};
  scene.sun = Sun{30, 135};
  scene.materials.push_back({"ground", DiffuseMaterial{Spectrum(0.2f)}});
  scene.materials.push_back({"walls", DiffuseMaterial{reflectance_from_linear_srgb({0.5, 0.4, 0.3})}});
  scene.objects.push_back({"ground", make_ground_plane({0, 0, 0}, 2000), 0});
  scene.objects.push_back({"block", make_box({-6, -6, 0}, {6, 6, 20}), 1});
  scene.render = RenderSettings{32, 18, std::nullopt, 1};

  const XyzImage image = Renderer(scene).render();
  if (image.width != 32 || image.height != 18) {
    std::fprintf(stderr, "image is %dx%d, not 32x18\n", image.width, image.height);
    return 1;
  }
  double sum = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const double l = image.at(x, y).y;
      if (!std::isfinite(l) || l < 0) {
        std::fprintf(stderr, "pixel (%d, %d): luminance %g\n", x, y, l);
        return 1;
      }
      sum += l;
    }
  }
  const double mean = sum / (image.width * image.height);
  std::printf("mean luminance %.1f cd/m2\n", mean);
  if (!(mean > 0)) return 1;
  return 0;
}
