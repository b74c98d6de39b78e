// The RGB → spectrum table against the direct Jakob–Hanika fit it stands in for: the
// embedded nodes must be the fit's (a stale data file fails here), and colours between
// the nodes must get spectra close to their own fit.
#include "skylit/spectrum/rgb_spectrum_table.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "skylit/core/embedded_data.h"
#include "skylit/core/error.h"
#include "skylit/spectrum/cie.h"
#include "skylit/spectrum/color_difference.h"
#include "skylit/spectrum/illuminants.h"

namespace skylit {
namespace {

Spectrum direct(const Rgb& rgb) { return reflectance_from_linear_srgb(rgb); }

std::array<float, 3> as_float(const Rgb& rgb) {
  return {static_cast<float>(rgb[0]), static_cast<float>(rgb[1]), static_cast<float>(rgb[2])};
}

// A spectrum's CIELAB colour under D65 from its bin means (40 bins): what the table's
// colours are compared by, on both sides alike.
Lab lab_of_bins(const Spectrum& s) {
  Xyz xyz, white;
  const Spectrum d65 = Spectrum::from_table(cie_d65_table());
  const ColourMatchingFunctions& cmf = cie1931();
  for (int k = 0; k < kSpectralBins; ++k) {
    const double lambda = kGrid.center_nm(k);
    const double e = d65[k];
    white.x += e * cmf.x(lambda), white.y += e * cmf.y(lambda), white.z += e * cmf.z(lambda);
    xyz.x += e * s[k] * cmf.x(lambda), xyz.y += e * s[k] * cmf.y(lambda), xyz.z += e * s[k] * cmf.z(lambda);
  }
  const double scale = 1.0 / white.y;
  for (Xyz* v : {&xyz, &white}) v->x *= scale, v->y *= scale, v->z *= scale;
  return lab_from_xyz(xyz, white);
}

TEST(RgbSpectrumTable, NodesAreTheDirectFit) {
  // Nodes on a coarse sub-grid (a full check would take 2 s): the table at a node is
  // that node's fit, to float rounding (1e-6).
  const RgbSpectrumTable& table = rgb_spectrum_table();
  for (int b = 0; b < kRgbTableNodes; b += 4)
    for (int g = 0; g < kRgbTableNodes; g += 4)
      for (int r = 1; r < kRgbTableNodes; r += 5) {
        const Rgb rgb{rgb_table_node_value(r), rgb_table_node_value(g), rgb_table_node_value(b)};
        const Spectrum expected = direct(rgb), got = table.reflectance(as_float(rgb));
        for (int k = 0; k < kSpectralBins; ++k) ASSERT_NEAR(got[k], expected[k], 1e-5) << r << "," << g << "," << b;
      }
}

TEST(RgbSpectrumTable, BetweenNodesCloseToTheDirectFit) {
  // Colours off the nodes (a fixed pseudo-random set across the cube): the table's
  // spectrum against the colour's own fit. Both are smooth reflectances of nearly the
  // same colour (a blend keeps the colour, see the header), so they differ only in
  // metameric shape, most for bright saturated colours whose fits are steep steps.
  // Measured over these 60 colours: largest bin difference 0.080, mean of the per-colour
  // largest 0.014, ΔE2000 at most 0.004. Bounds: 0.1, 0.02 and 0.05.
  const RgbSpectrumTable& table = rgb_spectrum_table();
  uint32_t state = 12345;
  auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) / 16777216.0;
  };
  double worst_bin = 0, worst_de = 0, sum_bin = 0;
  const int count = 60;
  for (int i = 0; i < count; ++i) {
    const Rgb rgb{next(), next(), next()};
    const Spectrum expected = direct(rgb), got = table.reflectance(as_float(rgb));
    double bin = 0;
    for (int k = 0; k < kSpectralBins; ++k) {
      ASSERT_GE(got[k], 0.0f);
      ASSERT_LE(got[k], 1.0f);
      bin = std::max(bin, static_cast<double>(std::abs(got[k] - expected[k])));
    }
    worst_bin = std::max(worst_bin, bin);
    sum_bin += bin;
    worst_de = std::max(worst_de, delta_e_2000(lab_of_bins(got), lab_of_bins(expected)));
  }
  std::cout << "table vs fit: worst bin " << worst_bin << ", mean worst bin " << sum_bin / count << ", worst ΔE2000 "
            << worst_de << "\n";
  EXPECT_LT(worst_bin, 0.1);
  EXPECT_LT(sum_bin / count, 0.02);
  EXPECT_LT(worst_de, 0.05);
}

TEST(RgbSpectrumTable, ClampsAndTakesNaNAsZero) {
  const RgbSpectrumTable& table = rgb_spectrum_table();
  const Spectrum black = table.reflectance({std::nanf(""), -1.0f, 0.0f});
  const Spectrum white = table.reflectance({2.0f, 1.0f, 5.0f});
  for (int k = 0; k < kSpectralBins; ++k) {
    EXPECT_NEAR(black[k], 0.0f, 1e-6);
    EXPECT_NEAR(white[k], 1.0f, 1e-6);
  }
}

TEST(RgbSpectrumTable, MalformedDataIsRefused) {
  EXPECT_THROW(parse_rgb_table_csv("r,g,b,c0,c1,c2\n0,0,0,1,2,3\n"), InputError);
  EXPECT_THROW(parse_rgb_table_csv("r,g,b,c0,c1,c2\n99,0,0,1,2,3\n"), InputError);
  EXPECT_EQ(parse_rgb_table_csv(data::embedded_file("rgb_spectrum_coefficients.csv")).size(),
            static_cast<size_t>(kRgbTableNodes * kRgbTableNodes * kRgbTableNodes));
}

}  // namespace
}  // namespace skylit
