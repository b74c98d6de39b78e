// Writing a render's outputs by their names (render_outputs.h).
#include "render_outputs.h"

#include <vector>

#include "skylit/core/error.h"
#include "skylit/figures/false_colour.h"
#include "skylit/io/atomic_file.h"
#include "skylit/io/image/exposure_meter.h"
#include "skylit/io/image/radiance_view.h"

namespace skylit::cli {

void check_render_output(const std::string& path) {
  image_format_from_path(path);
  check_output_folder(path);
}

void write_render_output(const std::string& path, const XyzImage& image, const Scene& scene,
                         const DisplayOptions& display) {
  if (!is_false_colour_path(path)) {
    DisplayOptions with_view = display;
    with_view.radiance_view = radiance_view_options(scene.camera, image.width, image.height);
    write_image(image, path, with_view);
    return;
  }
  write_false_colour(image, pixel_luminances(image), path, scene.render.false_colour, display);
}

}  // namespace skylit::cli
