// Contact sheets: a grid of rendered images for a parameter sweep (rows = one
// parameter, columns = another, e.g. sun altitude × material), labelled, titled and
// written as one PNG. All cells share one exposure so that brightness compares across
// the sheet: the given one, or one automatic exposure metered over all cells together
// (log-average luminance, as for a single image; docs/images.md). A caption line at the
// bottom states it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "skylit/figures/raster.h"
#include "skylit/io/image/image.h"

namespace skylit {

struct ContactSheet {
  std::string title;
  std::vector<std::string> row_labels, column_labels;  // empty, or one per row / column
  std::string row_heading, column_heading;             // what the rows / columns vary
  // cells[row][column]; rows may be shorter than the widest one. A null image (or a
  // missing one) is an empty grey cell. The images must outlive the call.
  std::vector<std::vector<const XyzImage*>> cells;
  DisplayOptions display;    // exposure_ev empty = one automatic exposure for all cells
  int max_cell_width = 480;  // wider images are reduced by box filtering, pixels
};

// Where everything goes, in pixels, and the exposure used.
struct ContactSheetLayout {
  int width = 0, height = 0;
  int cell_width = 0, cell_height = 0;  // the box each (reduced) image is centred in
  std::vector<int> cell_x;              // left of each column's cell box
  std::vector<int> cell_y;              // top of each row's cell box
  int title_y = 0, column_heading_y = 0, column_label_y = 0, caption_y = 0;
  double exposure_ev = 0;  // shared by all cells
  bool automatic_exposure = false;
  std::string caption;  // "exposure EV 12.3 for all cells (automatic)"
};

inline constexpr int kSheetMargin = 16;     // around everything, pixels
inline constexpr int kSheetGap = 8;         // between cells, and between cells and labels
inline constexpr int kSheetTitleScale = 3;  // bitmap font scale of the title
inline constexpr int kSheetLabelScale = 2;  // of labels, headings and the caption
inline constexpr Rgb8 kSheetEmptyCell{150, 150, 150};

// The integer reduction factor for an image `width` pixels wide: ceil(width / max_width).
int sheet_reduction_factor(int width, int max_width);

// `image` reduced by `factor` in both directions, each output pixel the mean of a
// factor × factor block of input pixels (fewer at the right and bottom edges), in
// linear XYZ so that light adds as it does in a camera. Non-finite pixels are left out
// of the means. factor ≥ 1.
XyzImage reduce_by_box_filter(const XyzImage& image, int factor);

// The exposure of all cells: sheet.display.exposure_ev, or automatic exposure's meter
// (exposure_meter.h) over every pixel of every cell taken together. InputError if the given EV is not finite.
double contact_sheet_exposure_ev(const ContactSheet& sheet);

// std::invalid_argument for a caller's mistake: no cells, label counts that do not
// match, max_cell_width < 1, or a malformed image.
ContactSheetLayout contact_sheet_layout(const ContactSheet& sheet);

Raster render_contact_sheet(const ContactSheet& sheet);

// PNG only (any case): InputError naming the path for another extension or a missing
// or unwritable folder, leaving no file behind. Written through a temporary file.
void write_contact_sheet(const ContactSheet& sheet, const std::filesystem::path& path);

}  // namespace skylit
