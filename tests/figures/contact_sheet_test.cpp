// Contact sheets (contact_sheet.h): the sheet's size follows from cell size and label
// margins, each cell holds display_srgb8 of its image at the one shared exposure (so a
// brighter render looks brighter), the shared automatic exposure is that of all cells
// metered together, wide images are box-filtered, empty cells are grey, and the file
// contract holds (PNG only, InputError naming the path, nothing left behind).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../io/image_test_util.h"
#include "../io/png_read_util.h"
#include "skylit/core/error.h"
#include "skylit/figures/bitmap_font.h"
#include "skylit/figures/contact_sheet.h"
#include "skylit/io/image/tone_map.h"

namespace skylit {
namespace {

// An image with a gradient in luminance and colour, so that cells differ pixel by pixel.
XyzImage gradient_image(int width, int height, double luminance) {
  XyzImage image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double l = luminance * (0.2 + double(x + 2 * y) / (width + 2 * height));
      image.set(x, y, xyz_from_linear_srgb({l * 1.3, l, l * (0.5 + 0.5 * y / height)}));
    }
  return image;
}

// The pixels of the sheet's `width` × `height` region at (x0, y0), as 8-bit RGB.
std::vector<uint8_t> region(const Raster& r, int x0, int y0, int width, int height) {
  std::vector<uint8_t> out;
  for (int y = y0; y < y0 + height; ++y)
    for (int x = x0; x < x0 + width; ++x) {
      const Rgb8 p = r.at(x, y);
      out.insert(out.end(), {p.r, p.g, p.b});
    }
  return out;
}

TEST(ContactSheet, SizeFollowsFromCellsAndLabelMargins) {
  test::ScratchFolder dir("sheet-size");
  std::vector<XyzImage> images;
  for (int i = 0; i < 6; ++i) images.push_back(gradient_image(200, 30, 100.0 * (i + 1)));
  ContactSheet sheet;
  sheet.title = "T";
  sheet.row_labels = {"a", "bb"};
  sheet.column_labels = {"x", "y", "z"};
  sheet.cells = {{&images[0], &images[1], &images[2]}, {&images[3], &images[4], &images[5]}};
  write_contact_sheet(sheet, dir / "sheet.png");
  const Raster png = test::read_png_raster(dir / "sheet.png");
  // Across: margin, the widest row label ("bb": 2 characters at the label scale), a gap
  // either side of it... then three 200-px cells 8 px apart, and the margin.
  const int char_width = kFontCellWidth * kSheetLabelScale;
  const int expected_width = kSheetMargin + 2 * char_width + 2 * kSheetGap + 3 * 200 + 2 * kSheetGap + kSheetMargin;
  // Down: margin, title, its gap, the column labels and a gap, two 30-px rows each with
  // a gap, a gap, the caption and the margin.
  const int line = kFontCellHeight * kSheetLabelScale;
  const int expected_height = kSheetMargin + kFontCellHeight * kSheetTitleScale + 2 * kSheetGap + line + kSheetGap +
                              2 * (30 + kSheetGap) + kSheetGap + line + kSheetMargin;
  EXPECT_EQ(png.width, expected_width);
  EXPECT_EQ(png.height, expected_height);
  const ContactSheetLayout layout = contact_sheet_layout(sheet);
  EXPECT_EQ(layout.width, expected_width);
  EXPECT_EQ(layout.height, expected_height);
  EXPECT_EQ(layout.cell_width, 200);
  EXPECT_EQ(layout.cell_height, 30);
  EXPECT_EQ(layout.cell_x[1] - layout.cell_x[0], 200 + kSheetGap);
  EXPECT_EQ(layout.cell_y[1] - layout.cell_y[0], 30 + kSheetGap);
  // Labels are drawn: ink left of the first row and above the first column.
  bool ink_left = false, ink_above = false;
  for (int y = layout.cell_y[0]; y < layout.cell_y[0] + 30; ++y)
    for (int x = 0; x < layout.cell_x[0]; ++x) ink_left |= png.at(x, y) == kBlack;
  for (int y = layout.column_label_y; y < layout.cell_y[0]; ++y)
    for (int x = layout.cell_x[0]; x < layout.cell_x[0] + 200; ++x) ink_above |= png.at(x, y) == kBlack;
  EXPECT_TRUE(ink_left);
  EXPECT_TRUE(ink_above);
}

TEST(ContactSheet, CellsAreTheDisplayImagesAtOneSharedExposure) {
  test::ScratchFolder dir("sheet-cells");
  std::vector<XyzImage> images;
  for (int i = 0; i < 6; ++i) images.push_back(gradient_image(12 + i % 2, 9, 3.0 * std::pow(4.0, i)));
  images[4].set(3, 3, {std::nan(""), 1, 1});  // a renderer's NaN must not set the exposure
  ContactSheet sheet;
  sheet.row_labels = {"17°", "60°"};
  sheet.column_labels = {"tile", "aluminium", "glass"};
  sheet.row_heading = "sun altitude";
  sheet.cells = {{&images[0], &images[1], &images[2]}, {&images[3], &images[4], &images[5]}};
  write_contact_sheet(sheet, dir / "sheet.png");
  const Raster png = test::read_png_raster(dir / "sheet.png");

  // The shared exposure is the automatic exposure of all cells metered as one image:
  // the six stacked into one column, finite pixels only.
  XyzImage all(13, 6 * 9);
  for (std::size_t i = 0; i < images.size(); ++i)
    for (int y = 0; y < 9; ++y)
      for (int x = 0; x < 13; ++x)
        all.set(x, int(i) * 9 + y, x < images[i].width ? images[i].at(x, y) : Xyz{std::nan(""), 0, 0});
  const double ev = automatic_exposure_ev(all);
  EXPECT_NEAR(contact_sheet_exposure_ev(sheet), ev, 1e-9);

  const ContactSheetLayout layout = contact_sheet_layout(sheet);
  ASSERT_EQ(png.width, layout.width);
  ASSERT_EQ(png.height, layout.height);
  EXPECT_TRUE(layout.automatic_exposure);
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 3; ++c) {
      const XyzImage& image = images[3 * r + c];
      const int x0 = layout.cell_x[c] + (layout.cell_width - image.width) / 2;
      const int y0 = layout.cell_y[r] + (layout.cell_height - image.height) / 2;
      EXPECT_EQ(region(png, x0, y0, image.width, image.height), display_srgb8(image, DisplayOptions{ev}))
          << "cell " << r << "," << c;
    }
  // The caption states the exposure, once for the whole sheet.
  char expected[64];
  std::snprintf(expected, sizeof expected, "exposure EV %.1f for all cells (automatic)", ev);
  EXPECT_EQ(layout.caption, expected);
}

TEST(ContactSheet, SharedExposureKeepsBrightnessDifferences) {
  // Alone, each grey meters to the key: both show as sRGB 118, indistinguishable.
  const XyzImage dim = test::grey_image(8, 6, 100), bright = test::grey_image(8, 6, 400);
  EXPECT_EQ(display_srgb8(dim, {}), display_srgb8(bright, {}));
  ContactSheet sheet;
  sheet.cells = {{&dim, &bright}};
  const Raster r = render_contact_sheet(sheet);
  const ContactSheetLayout layout = contact_sheet_layout(sheet);
  const Rgb8 a = r.at(layout.cell_x[0] + 4, layout.cell_y[0] + 3), b = r.at(layout.cell_x[1] + 4, layout.cell_y[0] + 3);
  // Together the log-average is 200 cd/m² and maps to 0.18: 100 → 0.09, 400 → 0.36,
  // both below the tone curve's knee, so sRGB-encoded exactly.
  const auto code = [](double v) { return int(std::lround(255 * (1.055 * std::pow(v, 1 / 2.4) - 0.055))); };
  EXPECT_EQ(a.g, code(0.09));
  EXPECT_EQ(b.g, code(0.36));
  EXPECT_LT(a.g, b.g);
  // A given exposure is used as it is, for every cell.
  sheet.display.exposure_ev = 10;
  const ContactSheetLayout given = contact_sheet_layout(sheet);
  EXPECT_EQ(given.exposure_ev, 10);
  EXPECT_EQ(given.caption, "exposure EV 10.0 for all cells");
  const Raster g = render_contact_sheet(sheet);
  EXPECT_EQ(region(g, given.cell_x[1], given.cell_y[0], 8, 6), display_srgb8(bright, DisplayOptions{10.0}));
}

TEST(ContactSheet, WideImagesAreReducedByABoxFilterInLinearLight) {
  XyzImage wide(9, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 9; ++x) wide.set(x, y, {double(x), double(10 * y + x), 1});
  EXPECT_EQ(sheet_reduction_factor(9, 4), 3);
  EXPECT_EQ(sheet_reduction_factor(8, 4), 2);
  EXPECT_EQ(sheet_reduction_factor(4, 4), 1);
  const XyzImage small = reduce_by_box_filter(wide, 3);
  ASSERT_EQ(small.width, 3);
  ASSERT_EQ(small.height, 2);
  // Block (1, 0): x 3–5, y 0–2 → mean x 4, mean y 10 + 4; the bottom row of blocks has
  // only y = 3 to average.
  EXPECT_DOUBLE_EQ(small.at(1, 0).x, 4);
  EXPECT_DOUBLE_EQ(small.at(1, 0).y, 14);
  EXPECT_DOUBLE_EQ(small.at(2, 1).y, 37);
  ContactSheet sheet;
  sheet.max_cell_width = 4;
  sheet.cells = {{&wide}};
  const ContactSheetLayout layout = contact_sheet_layout(sheet);
  EXPECT_EQ(layout.cell_width, 3);
  EXPECT_EQ(layout.cell_height, 2);
  const Raster r = render_contact_sheet(sheet);
  EXPECT_EQ(region(r, layout.cell_x[0], layout.cell_y[0], 3, 2),
            display_srgb8(small, DisplayOptions{layout.exposure_ev}));
}

TEST(ContactSheet, MissingCellsAreGrey) {
  const XyzImage image = test::grey_image(5, 4, 50);
  ContactSheet sheet;
  sheet.cells = {{&image, nullptr}, {&image}};  // a null cell and a short row
  const Raster r = render_contact_sheet(sheet);
  const ContactSheetLayout layout = contact_sheet_layout(sheet);
  for (auto [row, column] : {std::pair{0, 1}, std::pair{1, 1}})
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 5; ++x) EXPECT_EQ(r.at(layout.cell_x[column] + x, layout.cell_y[row] + y), kSheetEmptyCell);
  EXPECT_NE(r.at(layout.cell_x[0], layout.cell_y[1]), kSheetEmptyCell);
  // Only empty cells: still a sheet.
  ContactSheet empty;
  empty.cells = {{nullptr}};
  EXPECT_NO_THROW(render_contact_sheet(empty));
}

TEST(ContactSheet, OnlyPngAndAWritableFolderElseInputErrorAndNoFile) {
  test::ScratchFolder dir("sheet-bad");
  const XyzImage image = test::grey_image(5, 4, 50);
  ContactSheet sheet;
  sheet.cells = {{&image}};
  for (const std::filesystem::path& path : {dir / "sheet.svg", dir / "sheet.exr", dir / "none" / "sheet.png"}) {
    try {
      write_contact_sheet(sheet, path);
      ADD_FAILURE() << "no InputError for " << path;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    }
  }
  sheet.display.exposure_ev = std::nan("");
  EXPECT_THROW(write_contact_sheet(sheet, dir / "sheet.png"), InputError);
  EXPECT_TRUE(test::listing(dir.path()).empty());
  sheet.display.exposure_ev.reset();
  write_contact_sheet(sheet, dir / "sheet.PNG");
  EXPECT_EQ(test::listing(dir.path()), std::vector<std::string>{"sheet.PNG"});
}

TEST(ContactSheet, CallerMistakesAreInvalidArgument) {
  const XyzImage image = test::grey_image(5, 4, 50);
  ContactSheet sheet;
  EXPECT_THROW(contact_sheet_layout(sheet), std::invalid_argument);  // no cells
  sheet.cells = {{&image, &image}};
  sheet.column_labels = {"only one"};
  EXPECT_THROW(contact_sheet_layout(sheet), std::invalid_argument);
  sheet.column_labels.clear();
  sheet.row_labels = {"a", "b"};
  EXPECT_THROW(contact_sheet_layout(sheet), std::invalid_argument);
  sheet.row_labels.clear();
  sheet.max_cell_width = 0;
  EXPECT_THROW(contact_sheet_layout(sheet), std::invalid_argument);
}

}  // namespace
}  // namespace skylit
