// False-colour images (figures/false_colour.h), read back from the PNG file: every
// legend step's swatch has the colour its value gets in the image, and its label says
// that value; the scale's ends and steps; contour lines where a step is crossed.
#include "skylit/figures/false_colour.h"

#include <gtest/gtest.h>

#include <vector>

#include "../io/png_read_util.h"
#include "../test_support.h"
#include "skylit/figures/viridis.h"

namespace skylit {
namespace {

// Raster crop [x, x + w) × [y, y + h).
Raster crop(const Raster& r, int x, int y, int w, int h) {
  Raster out(w, h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) set_pixel(out, i, j, r.at(x + i, y + j));
  return out;
}

TEST(FalseColour, LegendStepsAndImageColoursAgreeInThePng) {
  FalseColourSettings settings;  // log scale, 4 decades
  settings.max = 1000;
  const FalseColourLegend legend = false_colour_legend({}, settings);
  const std::vector<double> expected{0.1, 0.2, 0.5, 1, 2, 5, 10, 20, 50, 100, 200, 500, 1000};
  ASSERT_EQ(legend.steps.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(legend.steps[i], expected[i], 1e-9 * expected[i]);

  // An image with a band of 4 rows at each step's value, written and read back.
  const int width = 40, band = 4, height = band * int(expected.size());
  XyzImage image(width, height);
  std::vector<float> values(std::size_t(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float v = static_cast<float>(expected[y / band]);
      values[std::size_t(y) * width + x] = v;
      image.set(x, y, {v, v, v});
    }
  testing::TempDir dir;
  const auto path = dir.path() / "lum.falsecolor.png";
  write_false_colour(image, values, path, settings, {});
  const Raster png = test::read_png_raster(path);
  FalseColourLayout layout;
  const Raster made = render_false_colour(values, width, height, settings, {}, &layout);
  ASSERT_EQ(png.width, made.width);
  ASSERT_EQ(png.height, made.height);

  for (std::size_t i = 0; i < expected.size(); ++i) {
    const int y_band = int(i) * band + band / 2;
    const Rgb8 in_image = png.at(width / 2, y_band);
    const Rgb8 swatch = png.at(layout.swatch_x + layout.swatch_size / 2, layout.swatch_y[i] + layout.swatch_size / 2);
    EXPECT_EQ(in_image, swatch) << expected[i];
    // Where the value sits on the log scale, by its own formula: log10(v / 0.1) / 4;
    // ±1 code value, as t computed another way can round a half the other way.
    const Rgb8 by_formula = viridis(std::log10(expected[i] / 0.1) / 4);
    EXPECT_NEAR(swatch.r, by_formula.r, 1) << expected[i];
    EXPECT_NEAR(swatch.g, by_formula.g, 1) << expected[i];
    EXPECT_NEAR(swatch.b, by_formula.b, 1) << expected[i];
    // The label beside the swatch reads the value: the same pixels as the text drawn alone.
    const std::string label = false_colour_label(expected[i]);
    const int label_x = layout.swatch_x + layout.swatch_size + 4;
    Raster alone(text_width(label), text_height());
    draw_text(alone, 0, 0, label, {40, 40, 40});
    EXPECT_EQ(crop(png, label_x, layout.swatch_y[i], alone.width, alone.height).rgb, alone.rgb) << label;
  }
  EXPECT_EQ(false_colour_label(0.5), "0.5");
  EXPECT_EQ(false_colour_label(1000), "1e+03");
}

TEST(FalseColour, AutomaticScalesRoundTheTopUp) {
  std::vector<float> values(200, 10.0f);
  values[0] = 730;  // one pixel in 200 above the 99th percentile: ignored
  values[1] = 73;
  values[2] = 73;
  FalseColourSettings log;
  FalseColourLegend legend = false_colour_legend(values, log);
  EXPECT_DOUBLE_EQ(legend.high, 100);  // 99th percentile 73 → the next power of ten
  EXPECT_DOUBLE_EQ(legend.low, 0.01);
  FalseColourSettings linear;
  linear.scale = FalseColourScale::linear;
  legend = false_colour_legend(values, linear);
  EXPECT_DOUBLE_EQ(legend.high, 100);  // 73 → 1, 2 or 5 × 10^k: 100
  ASSERT_EQ(legend.steps.size(), 11u);
  EXPECT_DOUBLE_EQ(legend.steps[3], 30);
  EXPECT_EQ(false_colour(50, legend), viridis(0.5));
  EXPECT_EQ(false_colour(-5, legend), viridis(0));
  EXPECT_EQ(false_colour(1e9, legend), viridis(1));
  EXPECT_EQ(false_colour(NAN, legend), viridis(0));
}

TEST(FalseColour, ContoursRunWhereAStepIsCrossed) {
  // 0.3 cd/m² on the left, 3 on the right: steps 0.5, 1 and 2 lie between, so a line
  // runs along the last left column; nowhere else.
  const int width = 20, height = 6;
  std::vector<float> values(std::size_t(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) values[std::size_t(y) * width + x] = x < width / 2 ? 0.3f : 3.0f;
  FalseColourSettings settings;
  settings.max = 100;
  settings.contours = true;
  const FalseColourLegend legend = false_colour_legend(values, settings);
  const Raster r = render_false_colour(values, width, height, settings, {});
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const bool line = x == width / 2 - 1;
      EXPECT_EQ(r.at(x, y) == false_colour(values[std::size_t(y) * width + x], legend), !line) << x << "," << y;
    }
}

TEST(FalseColour, PathsThatAskForIt) {
  EXPECT_TRUE(is_false_colour_path("out/lum.falsecolor.png"));
  EXPECT_TRUE(is_false_colour_path("LUM.FalseColour.PNG"));
  EXPECT_FALSE(is_false_colour_path("lum.png"));
  EXPECT_FALSE(is_false_colour_path(".falsecolor.png"));
}

}  // namespace
}  // namespace skylit
