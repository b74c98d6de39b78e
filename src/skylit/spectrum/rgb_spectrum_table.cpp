#include "skylit/spectrum/rgb_spectrum_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include <tbb/parallel_for.h>

#include "skylit/core/embedded_data.h"
#include "skylit/core/error.h"

namespace skylit {
namespace {

constexpr int kLast = kRgbTableNodes - 1;
constexpr size_t kNodeCount = static_cast<size_t>(kRgbTableNodes) * kRgbTableNodes * kRgbTableNodes;

size_t node_index(int r, int g, int b) { return (static_cast<size_t>(b) * kRgbTableNodes + g) * kRgbTableNodes + r; }

// The cell below a linear value and the place in it, in linear units (so that the
// blend of the corners' colours is the colour asked for).
void locate(float value, int& cell, float& t) {
  const double v = value >= 0.0f ? std::min(static_cast<double>(value), 1.0) : 0.0;  // NaN → 0
  static const std::array<double, kRgbTableNodes> nodes = [] {
    std::array<double, kRgbTableNodes> values{};
    for (int i = 0; i < kRgbTableNodes; ++i) values[static_cast<size_t>(i)] = rgb_table_node_value(i);
    return values;
  }();
  cell =
      std::clamp(static_cast<int>(std::upper_bound(nodes.begin(), nodes.end(), v) - nodes.begin()) - 1, 0, kLast - 1);
  const double lo = rgb_table_node_value(cell), hi = rgb_table_node_value(cell + 1);
  t = static_cast<float>(std::clamp((v - lo) / (hi - lo), 0.0, 1.0));
}

}  // namespace

double rgb_table_node_value(int i) {
  const double x = static_cast<double>(i) / kLast;
  return x * x * (3 - 2 * x);
}

std::vector<SigmoidPolynomial> fit_rgb_table_nodes() {
  std::vector<SigmoidPolynomial> nodes(kNodeCount);
  tbb::parallel_for(0, kRgbTableNodes, [&](int b) {
    for (int g = 0; g < kRgbTableNodes; ++g)
      for (int r = 0; r < kRgbTableNodes; ++r)
        nodes[node_index(r, g, b)] =
            fit_reflectance_to_linear_srgb({rgb_table_node_value(r), rgb_table_node_value(g), rgb_table_node_value(b)});
  });
  return nodes;
}

std::string rgb_table_csv(const std::vector<SigmoidPolynomial>& nodes) {
  std::string out = "r,g,b,c0,c1,c2\n";
  char line[160];
  for (int b = 0; b < kRgbTableNodes; ++b)
    for (int g = 0; g < kRgbTableNodes; ++g)
      for (int r = 0; r < kRgbTableNodes; ++r) {
        const SigmoidPolynomial& c = nodes[node_index(r, g, b)];
        // %.9g round-trips the fit to well below its own accuracy; "inf" marks the flat
        // black and white spectra.
        std::snprintf(line, sizeof line, "%d,%d,%d,%.9g,%.9g,%.9g\n", r, g, b, c.c0, c.c1, c.c2);
        out += line;
      }
  return out;
}

std::vector<SigmoidPolynomial> parse_rgb_table_csv(std::string_view text) {
  std::vector<SigmoidPolynomial> nodes(kNodeCount);
  std::vector<bool> seen(kNodeCount, false);
  std::istringstream lines{std::string(text)};
  std::string line;
  std::getline(lines, line);  // header
  size_t count = 0;
  while (std::getline(lines, line)) {
    if (line.empty()) continue;
    int r = -1, g = -1, b = -1;
    char c0[40], c1[40], c2[40];
    if (std::sscanf(line.c_str(), "%d,%d,%d,%39[^,],%39[^,],%39s", &r, &g, &b, c0, c1, c2) != 6 || r < 0 || g < 0 ||
        b < 0 || r > kLast || g > kLast || b > kLast)
      throw InputError("rgb_spectrum_coefficients.csv: malformed line: " + line.substr(0, 60));
    const size_t i = node_index(r, g, b);
    nodes[i] = {std::strtod(c0, nullptr), std::strtod(c1, nullptr), std::strtod(c2, nullptr)};
    if (!seen[i]) ++count;
    seen[i] = true;
  }
  if (count != kNodeCount)
    throw InputError("rgb_spectrum_coefficients.csv: " + std::to_string(count) + " nodes, not " +
                     std::to_string(kNodeCount));
  return nodes;
}

RgbSpectrumTable::RgbSpectrumTable(const std::vector<SigmoidPolynomial>& nodes) : spectra_(nodes.size()) {
  tbb::parallel_for(size_t{0}, nodes.size(),
                    [&](size_t i) { spectra_[i] = Spectrum::from_table(tabulate_at_1nm(nodes[i])); });
}

Spectrum RgbSpectrumTable::reflectance(const std::array<float, 3>& linear_srgb) const {
  int cell[3];
  float t[3];
  for (int k = 0; k < 3; ++k) locate(linear_srgb[static_cast<size_t>(k)], cell[k], t[k]);
  Spectrum out;
  for (int db = 0; db <= 1; ++db)
    for (int dg = 0; dg <= 1; ++dg)
      for (int dr = 0; dr <= 1; ++dr) {
        const float w = (dr ? t[0] : 1 - t[0]) * (dg ? t[1] : 1 - t[1]) * (db ? t[2] : 1 - t[2]);
        if (w == 0.0f) continue;
        const Spectrum& s = spectra_[node_index(cell[0] + dr, cell[1] + dg, cell[2] + db)];
        for (int k = 0; k < kSpectralBins; ++k) out[k] += w * s[k];
      }
  return out;
}

const RgbSpectrumTable& rgb_spectrum_table() {
  static const RgbSpectrumTable table(parse_rgb_table_csv(data::embedded_file("rgb_spectrum_coefficients.csv")));
  return table;
}

}  // namespace skylit
