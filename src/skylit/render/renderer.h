// Renders a scene into an image of absolute CIE XYZ (Y in cd/m²): the scene prepared
// once (prepared_scene.h), then by the scene's render.integrator either the paper's
// method for each ray (bands_integrator.h) in its image loop (image_loop.h), or the
// path-traced reference (path_integrator.h, path_image_loop.h).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>

#include "skylit/render/bands_integrator.h"
#include "skylit/render/image_loop.h"
#include "skylit/render/path_image_loop.h"
#include "skylit/render/path_integrator.h"
#include "skylit/render/prepared_scene.h"
#include "skylit/scene/scene.h"
#include "skylit/spectrum/xyz_image.h"

namespace skylit {

class Renderer {
 public:
  // Builds the acceleration structure and the atmosphere's tables for the scene, which
  // it keeps by reference: the scene must outlive the renderer.
  explicit Renderer(const Scene& scene) : prepared_(scene), integrator_(prepared_) {
    if (scene.render.integrator == Integrator::path) path_ = std::make_unique<PathIntegrator>(prepared_);
  }
  Renderer(Scene&&) = delete;

  const SkyModel& sky() const { return prepared_.sky(); }
  const SkyLight& sky_light() const { return integrator_.sky_light(); }
  const PreparedScene& prepared() const { return prepared_; }
  const BandsIntegrator& bands() const { return integrator_; }

  struct Result {
    XyzImage image;
    std::optional<XyzImage> standard_error;  // the path integrator's, per pixel
  };
  Result render_with_error(const RenderOptions& options = {}) const {
    if (!path_) return {render_image(prepared_, integrator_, options), std::nullopt};
    PathImage path = render_path_image(prepared_, *path_, options);
    return {std::move(path.image), std::move(path.standard_error)};
  }
  XyzImage render(const RenderOptions& options = {}) const { return render_with_error(options).image; }

  // Spectral radiance arriving along the ray, exactly (no cache): the function every
  // sample of render() calls.
  Radiance radiance(const Ray& ray) const { return integrator_.radiance(ray); }

  // Rays traced since construction, for the benchmark.
  uint64_t rays_traced() const { return prepared_.tracer().rays_traced(); }

 private:
  PreparedScene prepared_;
  BandsIntegrator integrator_;
  std::unique_ptr<PathIntegrator> path_;  // with render.integrator "path" only
};

}  // namespace skylit
