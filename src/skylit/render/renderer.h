// Renders a scene into an image of absolute CIE XYZ (Y in cd/m²).
//
// For now (the foundation): the sun is the extraterrestrial solar spectrum,
// unattenuated, as a directional light; surfaces are Lambertian with hard shadows;
// the sky is the placeholder of placeholder_sky.h. Pixels are computed independently
// on a fixed grid of samples, in tiles in parallel, so the output does not depend on
// the number of threads.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>

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
  // Builds the acceleration structure and the spectra the scene needs.
  explicit Renderer(const Scene& scene);

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
  Spectrum sun_irradiance_;  // on a plane normal to the sun, W m⁻² nm⁻¹
  Spectrum sky_radiance_;
  mutable std::atomic<uint64_t> rays_traced_{0};
};

}  // namespace skylit
