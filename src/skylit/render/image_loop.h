// The image loop: primary visibility once per frame (primary_hits.h), the caches built
// from it (the sky light on surfaces, the lamps' glow), then the pixels in tiles in
// parallel, in two passes (adaptive antialiasing), into the film. Every sample's light
// comes from the one per-ray function, BandsIntegrator::radiance. Pixels are computed
// independently on a fixed grid of samples, so the output does not depend on the
// number of threads.
#pragma once

#include <functional>

#include "skylit/render/bands_integrator.h"
#include "skylit/spectrum/xyz_image.h"

namespace skylit {

struct RenderOptions {
  int threads = 0;  // 0: as many as the machine has
  // Called now and then with the number of tiles done and the total; from any thread,
  // never concurrently.
  std::function<void(int done, int total)> on_progress;
};

XyzImage render_image(const PreparedScene& scene, const BandsIntegrator& integrator, const RenderOptions& options);

}  // namespace skylit
