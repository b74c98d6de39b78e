// cool_warm (cool_warm.h): Moreland's published 33-entry table, interpolated.
#include "skylit/figures/cool_warm.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace skylit {
namespace {

// CoolWarmUChar33.csv, kennethmoreland.com/color-maps/: entry k is at t = k / 32.
constexpr std::array<Rgb8, 33> kTable = {{
    {59, 76, 192},   {68, 90, 204},   {77, 104, 215},  {87, 117, 225},  {98, 130, 234},  {108, 142, 241},
    {119, 154, 247}, {130, 165, 251}, {141, 176, 254}, {152, 185, 255}, {163, 194, 255}, {174, 201, 253},
    {184, 208, 249}, {194, 213, 244}, {204, 217, 238}, {213, 219, 230}, {221, 221, 221}, {229, 216, 209},
    {236, 211, 197}, {241, 204, 185}, {245, 196, 173}, {247, 187, 160}, {247, 177, 148}, {247, 166, 135},
    {244, 154, 123}, {241, 141, 111}, {236, 127, 99},  {229, 112, 88},  {222, 96, 77},   {213, 80, 66},
    {203, 62, 56},   {192, 40, 47},   {180, 4, 38},
}};

uint8_t mix(uint8_t from, uint8_t to, double weight) {
  return static_cast<uint8_t>(std::lround(from + weight * (double(to) - double(from))));
}

}  // namespace

Rgb8 cool_warm(double t) {
  if (std::isnan(t)) t = 0.5;
  const double position = std::clamp(t, 0.0, 1.0) * (kTable.size() - 1);
  const auto k = std::min(static_cast<std::size_t>(position), kTable.size() - 2);
  const double w = position - static_cast<double>(k);
  const Rgb8 a = kTable[k], b = kTable[k + 1];
  return {mix(a.r, b.r, w), mix(a.g, b.g, w), mix(a.b, b.b, w)};
}

}  // namespace skylit
