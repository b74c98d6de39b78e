// How a render is shown and measured, beyond the image itself: the false-colour image's
// scale (docs/images.md, "False colour"). Read from the scene's render block.
#pragma once

#include <optional>

namespace skylit {

enum class FalseColourQuantity { luminance };
enum class FalseColourScale { log, linear };

struct FalseColourSettings {
  FalseColourQuantity quantity = FalseColourQuantity::luminance;
  FalseColourScale scale = FalseColourScale::log;
  std::optional<double> max;  // the legend's top, in cd/m² or lx; empty: from the image
  int decades = 4;            // log scale: the legend runs from max / 10^decades to max
  bool contours = false;      // lines where the value crosses a legend step
  bool underlay = false;      // the display image shown faintly beneath the colours
};

}  // namespace skylit
