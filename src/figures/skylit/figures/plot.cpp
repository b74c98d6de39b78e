// write_plot (plot.h): the format from the extension, the inputs checked before a
// temporary file exists, then the rendering written through an AtomicFile.
#include "skylit/figures/plot.h"

#include <string>

#include "skylit/figures/figure_file.h"
#include "skylit/figures/plot_layout.h"
#include "skylit/io/atomic_file.h"
#include "skylit/io/image/image_encoders.h"

namespace skylit {

void write_plot(const Plot& plot, const std::filesystem::path& path) {
  const std::string ext = figure_extension(path, {".svg", ".png"}, "a plot");
  plot_layout(plot);  // throws for malformed series before any file exists
  AtomicFile file(path);
  if (ext == ".svg") {
    const std::string svg = render_plot_svg(plot);
    file.commit({reinterpret_cast<const uint8_t*>(svg.data()), svg.size()});
  } else {
    const Raster raster = render_plot_png(plot);
    file.commit(encode_png_rgb8(raster.width, raster.height, raster.rgb));
  }
}

}  // namespace skylit
