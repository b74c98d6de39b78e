// Contact sheets (contact_sheet.h): one shared exposure, box-filtered reduction in
// linear light, the grid laid out around its labels, written through an AtomicFile.
#include "skylit/figures/contact_sheet.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include "skylit/core/error.h"
#include "skylit/figures/figure_file.h"
#include "skylit/io/atomic_file.h"
#include "skylit/io/image/exposure_meter.h"
#include "skylit/io/image/image_encoders.h"
#include "skylit/io/image/tone_map.h"

namespace skylit {

int sheet_reduction_factor(int width, int max_width) {
  if (max_width < 1) throw std::invalid_argument("contact sheet: max_cell_width must be at least 1");
  return width <= max_width ? 1 : (width + max_width - 1) / max_width;
}

XyzImage reduce_by_box_filter(const XyzImage& image, int factor) {
  check_image_shape(image);
  if (factor < 1) throw std::invalid_argument("reduce_by_box_filter: factor must be at least 1");
  if (factor == 1) return image;
  XyzImage out((image.width + factor - 1) / factor, (image.height + factor - 1) / factor);
  for (int oy = 0; oy < out.height; ++oy)
    for (int ox = 0; ox < out.width; ++ox) {
      double sum[3] = {0, 0, 0};
      int count = 0;
      for (int y = oy * factor; y < std::min(image.height, (oy + 1) * factor); ++y)
        for (int x = ox * factor; x < std::min(image.width, (ox + 1) * factor); ++x) {
          const std::size_t i = static_cast<std::size_t>(y) * image.width + x;
          if (!pixel_is_finite(image, i)) continue;
          for (int c = 0; c < 3; ++c) sum[c] += image.xyz[3 * i + c];
          ++count;
        }
      if (count > 0) out.set(ox, oy, {sum[0] / count, sum[1] / count, sum[2] / count});
    }
  return out;
}

namespace {

bool has_pixels(const XyzImage* image) { return image && image->width > 0 && image->height > 0; }

std::size_t column_count(const ContactSheet& sheet) {
  std::size_t n = 0;
  for (const auto& row : sheet.cells) n = std::max(n, row.size());
  return n;
}

const XyzImage* cell(const ContactSheet& sheet, std::size_t row, std::size_t column) {
  return column < sheet.cells[row].size() ? sheet.cells[row][column] : nullptr;
}

std::string ev_text(double ev) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, ev, std::chars_format::fixed, 1);
  std::string s(buffer, result.ptr);
  return s == "-0.0" ? "0.0" : s;
}

}  // namespace

double contact_sheet_exposure_ev(const ContactSheet& sheet) {
  if (sheet.display.exposure_ev) {
    if (!std::isfinite(*sheet.display.exposure_ev))
      throw InputError("contact sheet: exposure_ev must be a finite number of stops");
    return *sheet.display.exposure_ev;
  }
  // One meter over the pixels of every cell, as if they were one image.
  std::vector<float> luminances;
  for (const auto& row : sheet.cells)
    for (const XyzImage* image : row) {
      if (!has_pixels(image)) continue;
      const std::vector<float> y = pixel_luminances(*image);
      luminances.insert(luminances.end(), y.begin(), y.end());
    }
  return exposure_ev_for_metered(metered_luminance(luminances));
}

ContactSheetLayout contact_sheet_layout(const ContactSheet& sheet) {
  const std::size_t rows = sheet.cells.size(), columns = column_count(sheet);
  if (rows == 0 || columns == 0) throw std::invalid_argument("contact sheet: no cells");
  if (!sheet.row_labels.empty() && sheet.row_labels.size() != rows)
    throw std::invalid_argument("contact sheet: " + std::to_string(sheet.row_labels.size()) + " row labels for " +
                                std::to_string(rows) + " rows");
  if (!sheet.column_labels.empty() && sheet.column_labels.size() != columns)
    throw std::invalid_argument("contact sheet: " + std::to_string(sheet.column_labels.size()) + " column labels for " +
                                std::to_string(columns) + " columns");

  ContactSheetLayout layout;
  for (const auto& row : sheet.cells)
    for (const XyzImage* image : row) {
      if (!has_pixels(image)) continue;
      check_image_shape(*image);
      const int f = sheet_reduction_factor(image->width, sheet.max_cell_width);
      layout.cell_width = std::max(layout.cell_width, (image->width + f - 1) / f);
      layout.cell_height = std::max(layout.cell_height, (image->height + f - 1) / f);
    }
  sheet_reduction_factor(1, sheet.max_cell_width);  // checks max_cell_width even with no images
  if (layout.cell_width == 0) {                     // only empty cells: small grey squares
    layout.cell_width = layout.cell_height = std::min(64, sheet.max_cell_width);
  }
  layout.automatic_exposure = !sheet.display.exposure_ev;
  layout.exposure_ev = contact_sheet_exposure_ev(sheet);
  layout.caption = "exposure EV " + ev_text(layout.exposure_ev) + " for all cells" +
                   (layout.automatic_exposure ? " (automatic)" : "");

  const int s = kSheetLabelScale, th = text_height(s);
  // Left: the column of row labels (with the row heading at its top).
  int label_column = text_width(sheet.row_heading, s);
  for (const std::string& label : sheet.row_labels) label_column = std::max(label_column, text_width(label, s));
  const int grid_left = kSheetMargin + (label_column > 0 ? label_column + 2 * kSheetGap : 0);
  // Each column is as wide as its cell or its label, whichever is wider.
  int x = grid_left;
  for (std::size_t c = 0; c < columns; ++c) {
    const int label = sheet.column_labels.empty() ? 0 : text_width(sheet.column_labels[c], s);
    const int column_width = std::max(layout.cell_width, label);
    layout.cell_x.push_back(x + (column_width - layout.cell_width) / 2);
    x += column_width + kSheetGap;
  }
  const int grid_right = x - kSheetGap;

  int y = kSheetMargin;
  layout.title_y = y;
  if (!sheet.title.empty()) y += text_height(kSheetTitleScale) + 2 * kSheetGap;
  layout.column_heading_y = y;
  if (!sheet.column_heading.empty()) y += th + kSheetGap;
  layout.column_label_y = y;
  if (!sheet.column_labels.empty() || !sheet.row_heading.empty()) y += th + kSheetGap;
  for (std::size_t r = 0; r < rows; ++r) {
    layout.cell_y.push_back(y);
    y += layout.cell_height + kSheetGap;
  }
  layout.caption_y = y + kSheetGap;
  layout.height = layout.caption_y + th + kSheetMargin;

  const int widest_line = std::max({text_width(sheet.title, kSheetTitleScale), text_width(layout.caption, s),
                                    grid_left - kSheetMargin + text_width(sheet.column_heading, s)});
  layout.width = std::max(grid_right, kSheetMargin + widest_line) + kSheetMargin;
  return layout;
}

namespace {

Raster render(const ContactSheet& sheet, const ContactSheetLayout& layout) {
  Raster raster(layout.width, layout.height, kWhite);
  const int s = kSheetLabelScale, th = text_height(s);
  const int grid_left = layout.cell_x.front(), grid_right = layout.cell_x.back() + layout.cell_width;

  draw_text(raster, kSheetMargin, layout.title_y, sheet.title, kBlack, kSheetTitleScale);
  draw_text(raster, (grid_left + grid_right - text_width(sheet.column_heading, s)) / 2, layout.column_heading_y,
            sheet.column_heading, kBlack, s);
  draw_text(raster, kSheetMargin, layout.column_label_y, sheet.row_heading, kBlack, s);
  for (std::size_t c = 0; c < sheet.column_labels.size(); ++c)
    draw_text(raster, layout.cell_x[c] + (layout.cell_width - text_width(sheet.column_labels[c], s)) / 2,
              layout.column_label_y, sheet.column_labels[c], kBlack, s);

  DisplayOptions display = sheet.display;
  display.exposure_ev = layout.exposure_ev;  // the same for every cell
  for (std::size_t r = 0; r < sheet.cells.size(); ++r) {
    if (!sheet.row_labels.empty())
      draw_text(raster, kSheetMargin, layout.cell_y[r] + (layout.cell_height - th) / 2, sheet.row_labels[r], kBlack, s);
    for (std::size_t c = 0; c < layout.cell_x.size(); ++c) {
      const XyzImage* image = cell(sheet, r, c);
      if (!has_pixels(image)) {
        fill_rect(raster, layout.cell_x[c], layout.cell_y[r], layout.cell_width, layout.cell_height, kSheetEmptyCell);
        continue;
      }
      const XyzImage reduced = reduce_by_box_filter(*image, sheet_reduction_factor(image->width, sheet.max_cell_width));
      blit_rgb8(raster, layout.cell_x[c] + (layout.cell_width - reduced.width) / 2,
                layout.cell_y[r] + (layout.cell_height - reduced.height) / 2, reduced.width, reduced.height,
                display_srgb8(reduced, display));
    }
  }
  draw_text(raster, kSheetMargin, layout.caption_y, layout.caption, kBlack, s);
  return raster;
}

}  // namespace

Raster render_contact_sheet(const ContactSheet& sheet) { return render(sheet, contact_sheet_layout(sheet)); }

void write_contact_sheet(const ContactSheet& sheet, const std::filesystem::path& path) {
  figure_extension(path, {".png"}, "a contact sheet");
  if (sheet.display.exposure_ev && !std::isfinite(*sheet.display.exposure_ev))
    throw InputError("cannot write \"" + path.string() + "\": exposure_ev is not finite");
  const ContactSheetLayout layout = contact_sheet_layout(sheet);  // before any file exists
  AtomicFile file(path);
  const Raster raster = render(sheet, layout);
  file.commit(encode_png_rgb8(raster.width, raster.height, raster.rgb));
}

}  // namespace skylit
