// Renders a scene into an image of absolute CIE XYZ (Y in cd/m²).
//
// Light from the atmosphere model (atmosphere/atmosphere.h): the sun attenuated on its
// way to each surface, with hard shadows; the unobstructed sky and ground around as
// the diffuse light on Lambertian surfaces (obstruction by other objects comes with the
// band sources of §4); the sky and the sun's disc where pixels see no object; and the
// aerial perspective between the camera and every surface. Pixels are computed
// independently on a fixed grid of samples, in tiles in parallel, so the output does
// not depend on the number of threads.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>

#include "skylit/atmosphere/atmosphere.h"
#include "skylit/geometry/ray_tracer.h"
#include "skylit/io/image.h"
#include "skylit/render/camera.h"
#include "skylit/render/scene.h"
#include "skylit/spectrum/spectrum.h"

namespace skylit {

struct RenderOptions {
  int threads = 0;  // 0: as many as the machine has
  // Called now and then with the number of tiles done and the total; from any thread,
  // never concurrently.
  std::function<void(int done, int total)> on_progress;
};

class Renderer {
 public:
  // Builds the acceleration structure and the atmosphere's tables for the scene.
  explicit Renderer(const Scene& scene);

  const SkyModel& sky() const { return sky_; }

  XyzImage render(const RenderOptions& options = {}) const;

  // Spectral radiance arriving along the ray (W m⁻² sr⁻¹ nm⁻¹); adds the rays it
  // traces to `rays`.
  Spectrum radiance(const Ray& ray, uint64_t& rays) const;

  // Rays traced since construction (camera and shadow rays), for the benchmark.
  uint64_t rays_traced() const { return rays_traced_.load(std::memory_order_relaxed); }

 private:
  Spectrum shade(const Ray& ray, const Hit& hit, uint64_t& rays) const;

  const Scene& scene_;
  RayTracer tracer_;
  std::vector<uint32_t> material_of_mesh_;
  Vec3 to_sun_;
  Atmosphere atmosphere_;
  SkyModel sky_;
  mutable std::atomic<uint64_t> rays_traced_{0};
};

}  // namespace skylit
