// Reflectance spectra for many sRGB colours at once (texture texels): the Jakob–Hanika
// fit (rgb_to_spectrum.h) solved once at the nodes of a 3-D grid over linear sRGB and
// interpolated between them, as W. Jakob and J. Hanika, "A low-dimensional function
// space for efficient spectral upsampling" (Eurographics 2019, §4) do. The direct fit
// costs about 0.4 ms per colour; a look-up here costs eight spectra's worth of adds.
//
// The nodes' coefficients are data (data/rgb_spectrum_coefficients.csv, made by
// scripts/make-rgb-spectrum-table.sh with tools/make_rgb_spectrum_table.cpp); the
// spectra are made from them at first use. Where Jakob and Hanika interpolate the
// coefficients, we interpolate the spectra: a blend of smooth spectra within [0, 1] is
// smooth and within [0, 1], and since colour is linear in the spectrum, a colour inside
// a cell gets exactly the trilinear blend of its corners' colours, which is the colour
// asked for wherever the corners' fits are exact.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "skylit/spectrum/color_space.h"
#include "skylit/spectrum/rgb_to_spectrum.h"
#include "skylit/spectrum/spectrum.h"

namespace skylit {

// Nodes per axis; node i stands at linear value smoothstep(i / (kRgbTableNodes − 1)),
// denser toward black (where the eye tells colours apart on a finer scale) and toward
// full intensity (where the fitted spectra turn into steep steps and change shape
// fastest), as Jakob and Hanika space theirs.
inline constexpr int kRgbTableNodes = 17;

double rgb_table_node_value(int i);

// The fit at every node, index (b · n + g) · n + r: what the data file holds.
std::vector<SigmoidPolynomial> fit_rgb_table_nodes();
// The same as CSV text (header r,g,b,c0,c1,c2) and back; the reader throws InputError
// on a malformed or incomplete table.
std::string rgb_table_csv(const std::vector<SigmoidPolynomial>& nodes);
std::vector<SigmoidPolynomial> parse_rgb_table_csv(std::string_view text);

class RgbSpectrumTable {
 public:
  explicit RgbSpectrumTable(const std::vector<SigmoidPolynomial>& nodes);

  // The reflectance of a linear sRGB colour (components clamped to [0, 1], NaN as 0).
  Spectrum reflectance(const std::array<float, 3>& linear_srgb) const;

 private:
  std::vector<Spectrum> spectra_;
};

// The table made from the embedded data file, built on first use (thread-safe).
const RgbSpectrumTable& rgb_spectrum_table();

}  // namespace skylit
