// viridis (viridis.h): matplotlib's 256-entry table sampled every 8th entry, interpolated.
#include "skylit/figures/viridis.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace skylit {
namespace {

struct Entry {
  int index;  // in matplotlib's 256-entry table: t = index / 255
  Rgb8 colour;
};

constexpr std::array<Entry, 33> kTable = {{
    {0, {68, 1, 84}},      {8, {71, 13, 96}},     {16, {72, 24, 106}},   {24, {72, 35, 116}},   {32, {71, 45, 123}},
    {40, {69, 55, 129}},   {48, {66, 64, 134}},   {56, {62, 73, 137}},   {64, {59, 82, 139}},   {72, {55, 91, 141}},
    {80, {51, 99, 141}},   {88, {47, 107, 142}},  {96, {44, 114, 142}},  {104, {41, 122, 142}}, {112, {38, 130, 142}},
    {120, {35, 137, 142}}, {128, {33, 145, 140}}, {136, {31, 152, 139}}, {144, {31, 160, 136}}, {152, {34, 167, 133}},
    {160, {40, 174, 128}}, {168, {50, 182, 122}}, {176, {63, 188, 115}}, {184, {78, 195, 107}}, {192, {94, 201, 98}},
    {200, {112, 207, 87}}, {208, {132, 212, 75}}, {216, {152, 216, 62}}, {224, {173, 220, 48}}, {232, {194, 223, 35}},
    {240, {216, 226, 25}}, {248, {236, 229, 27}}, {255, {253, 231, 37}},
}};

uint8_t mix(uint8_t from, uint8_t to, double weight) {
  return static_cast<uint8_t>(std::lround(from + weight * (double(to) - double(from))));
}

}  // namespace

Rgb8 viridis(double t) {
  if (std::isnan(t)) t = 0;
  const double index = std::clamp(t, 0.0, 1.0) * 255.0;
  std::size_t k = 0;
  while (k + 2 < kTable.size() && kTable[k + 1].index <= index) ++k;
  const Entry& a = kTable[k];
  const Entry& b = kTable[k + 1];
  const double w = std::clamp((index - a.index) / double(b.index - a.index), 0.0, 1.0);
  return {mix(a.colour.r, b.colour.r, w), mix(a.colour.g, b.colour.g, w), mix(a.colour.b, b.colour.b, w)};
}

}  // namespace skylit
