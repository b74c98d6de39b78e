// The image loop of the path-traced reference: render.samples_per_pixel paths through
// random places in each pixel (a box filter), their mean into the film, and each
// pixel's standard error of that mean. Every path draws its numbers from a stream keyed
// by (seed, pixel, sample), so the bytes do not depend on the number of threads.
#pragma once

#include "skylit/render/image_loop.h"
#include "skylit/render/path_integrator.h"

namespace skylit {

struct PathImage {
  XyzImage image;
  // Per pixel, the standard error of the image's luminance, as a grey of that luminance
  // (Y in cd/m²; X and Z in proportion to D65's white).
  XyzImage standard_error;
};

PathImage render_path_image(const PreparedScene& scene, const PathIntegrator& integrator, const RenderOptions& options);

}  // namespace skylit
