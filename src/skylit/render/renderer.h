// Renders a scene into an image of absolute CIE XYZ (Y in cd/m²): the scene prepared
// once (prepared_scene.h), the paper's method for each ray (bands_integrator.h), and
// the image loop over the pixels (image_loop.h).
#pragma once

#include <cstdint>

#include "skylit/render/bands_integrator.h"
#include "skylit/render/image_loop.h"
#include "skylit/render/prepared_scene.h"
#include "skylit/scene/scene.h"
#include "skylit/spectrum/xyz_image.h"

namespace skylit {

class Renderer {
 public:
  // Builds the acceleration structure and the atmosphere's tables for the scene, which
  // it keeps by reference: the scene must outlive the renderer.
  explicit Renderer(const Scene& scene) : prepared_(scene), integrator_(prepared_) {}
  Renderer(Scene&&) = delete;

  const SkyModel& sky() const { return prepared_.sky(); }
  const SkyLight& sky_light() const { return integrator_.sky_light(); }
  const PreparedScene& prepared() const { return prepared_; }

  XyzImage render(const RenderOptions& options = {}) const { return render_image(prepared_, integrator_, options); }

  // Spectral radiance arriving along the ray, exactly (no cache): the function every
  // sample of render() calls.
  Radiance radiance(const Ray& ray) const { return integrator_.radiance(ray); }

  // Rays traced since construction, for the benchmark.
  uint64_t rays_traced() const { return prepared_.tracer().rays_traced(); }

 private:
  PreparedScene prepared_;
  BandsIntegrator integrator_;
};

}  // namespace skylit
