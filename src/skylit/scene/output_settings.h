// How a render is shown and measured, beyond the image itself: the false-colour image's
// scale (docs/images.md, "False colour"), read from the scene's render block; the
// probes of the statistics (docs/statistics.md), read from the scene's top level.
#pragma once

#include <optional>
#include <string>

namespace skylit {

enum class FalseColourQuantity { luminance, illuminance };  // cd/m², or lx on the surface seen
enum class FalseColourScale { log, linear };

struct FalseColourSettings {
  FalseColourQuantity quantity = FalseColourQuantity::luminance;
  FalseColourScale scale = FalseColourScale::log;
  std::optional<double> max;  // the legend's top, in cd/m² or lx; empty: from the image
  int decades = 4;            // log scale: the legend runs from max / 10^decades to max
  bool contours = false;      // lines where the value crosses a legend step
  bool underlay = false;      // the display image shown faintly beneath the colours
};

// A pixel or a rectangle of pixels whose luminance the statistics report (`probes`).
struct Probe {
  std::string name;
  int x0 = 0, y0 = 0, x1 = 1, y1 = 1;  // pixels [x0, x1) × [y0, y1), (0, 0) top left
};

}  // namespace skylit
