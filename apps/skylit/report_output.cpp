// The HTML report of a render (report_output.h).
#include "report_output.h"

#include "skylit/assess/render_statistics.h"
#include "skylit/core/file_names.h"
#include "skylit/figures/false_colour.h"
#include "skylit/figures/html_report.h"
#include "skylit/figures/report_luminance.h"
#include "skylit/io/image/exposure_meter.h"

namespace skylit::cli {

bool is_report_path(const std::string& path) {
  const std::string ext = lower_case_extension(path);
  return ext == ".html" || ext == ".htm";
}

std::vector<uint8_t> report_bytes(const std::string& title, const XyzImage& image, const Scene& scene,
                                  const DisplayOptions& display, const PixelLayers& layers) {
  ReportPage page;
  page.title = title;
  page.conditions = scene_conditions(scene);
  page.width = image.width;
  page.height = image.height;
  const std::vector<float> luminance = pixel_luminances(image);
  page.images.push_back({display.human ? "As a person would see it (human display)" : "Display image (photographic)",
                         encode_image(image, "display.png", display)});
  FalseColourSettings cd_m2 = scene.render.false_colour;
  if (cd_m2.quantity != FalseColourQuantity::luminance) {
    cd_m2.quantity = FalseColourQuantity::luminance;
    cd_m2.max.reset();
  }
  page.images.push_back({"Luminance in false colour", encode_false_colour(image, luminance, cd_m2, display)});
  page.layers.push_back({"luminance", "cd/m²", luminance_code_bytes(luminance)});
  if (!layers.illuminance_lx.empty()) {
    FalseColourSettings lux = scene.render.false_colour;
    lux.quantity = FalseColourQuantity::illuminance;
    lux.max.reset();  // the scene's max is for its own quantity
    page.images.push_back({"Illuminance on the surfaces seen, in false colour",
                           encode_false_colour(image, layers.illuminance_lx, lux, display)});
    page.layers.push_back({"illuminance", "lx", luminance_code_bytes(layers.illuminance_lx)});
  }
  page.statistics = render_statistics(image, layers, scene);
  const std::string html = html_report(page);
  return {html.begin(), html.end()};
}

}  // namespace skylit::cli
