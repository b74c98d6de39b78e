// Writing a render's outputs by their names (render_outputs.h).
#include "render_outputs.h"

#include <filesystem>

#include "report_output.h"
#include "skylit/assess/render_statistics.h"
#include "skylit/core/error.h"
#include "skylit/core/file_names.h"
#include "skylit/figures/false_colour.h"
#include "skylit/io/image/exposure_meter.h"
#include "skylit/io/image/radiance_view.h"

namespace skylit::cli {

namespace {

bool is_statistics_path(const std::string& path) {
  const std::string ext = lower_case_extension(path);
  return ext == ".json" || ext == ".csv";
}

// The EXR data layers: object index (−1 for none), distance (m), normal (x, y, z).
ExrLayers exr_layers(const PixelLayers& layers, const Scene& scene) {
  ExrLayers out;
  std::vector<float> object(layers.object.begin(), layers.object.end());
  out.channels.emplace_back("object", std::move(object));
  out.channels.emplace_back("distance", layers.distance_m);
  if (!layers.illuminance_lx.empty()) out.channels.emplace_back("illuminance", layers.illuminance_lx);
  if (!layers.reflected_sun_lx.empty()) out.channels.emplace_back("reflected_sun", layers.reflected_sun_lx);
  const std::size_t n = layers.object.size();
  for (int c = 0; c < 3; ++c) {
    std::vector<float> component(n);
    for (std::size_t i = 0; i < n; ++i) component[i] = layers.normal[3 * i + c];
    out.channels.emplace_back(std::string("normal.") + "XYZ"[c], std::move(component));
  }
  for (const SceneObject& o : scene.objects) out.object_names.push_back(o.name);  // the loader names every object
  return out;
}

}  // namespace

void check_render_output(const std::string& path) {
  if (!is_statistics_path(path) && !is_report_path(path)) image_format_from_path(path);
}

bool outputs_need_layers(const std::vector<std::string>& paths, const Scene& scene) {
  for (const std::string& p : paths)
    if (is_statistics_path(p) || is_report_path(p) ||
        (is_false_colour_path(p) && scene.render.false_colour.quantity == FalseColourQuantity::illuminance) ||
        (scene.render.exr_layers && lower_case_extension(p) == ".exr"))
      return true;
  return false;
}

std::vector<uint8_t> render_output_bytes(const std::string& path, const XyzImage& image, const Scene& scene,
                                         const DisplayOptions& display, const PixelLayers* layers,
                                         const std::string& scene_file) {
  if (is_report_path(path))
    return report_bytes("skylit render of " + std::filesystem::path(scene_file).filename().string(), image, scene,
                        display, *layers);
  if (is_statistics_path(path)) {
    const RenderStatistics stats = render_statistics(image, *layers, scene);
    const std::string text = lower_case_extension(path) == ".csv" ? statistics_csv(stats) : statistics_json(stats);
    return {text.begin(), text.end()};
  }
  if (is_false_colour_path(path)) {
    check_pixels_finite(image, path);
    const bool lux = scene.render.false_colour.quantity == FalseColourQuantity::illuminance;
    return encode_false_colour(image, lux ? layers->illuminance_lx : pixel_luminances(image), scene.render.false_colour,
                               display);
  }
  DisplayOptions options = display;
  options.radiance_view = radiance_view_options(scene.camera, image.width, image.height);
  ExrLayers data;
  if (scene.render.exr_layers && layers) {
    data = exr_layers(*layers, scene);
    options.exr_layers = &data;
  }
  return encode_image(image, path, options);
}

}  // namespace skylit::cli
