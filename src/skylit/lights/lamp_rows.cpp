// Placing the luminaires of a lamp row (lamp_rows.h).
#include "skylit/lights/lamp_rows.h"

#include <cmath>
#include <stdexcept>

#include "skylit/core/angles.h"

namespace skylit {

namespace {

// A point of the centre line at distance s along it, and the unit direction there.
struct Station {
  Vec3 point;
  Vec3 along;
};

std::vector<double> cumulative_lengths(const std::vector<Vec3>& line) {
  std::vector<double> out{0};
  for (size_t i = 1; i < line.size(); ++i) out.push_back(out.back() + length(line[i] - line[i - 1]));
  return out;
}

Station station_at(const std::vector<Vec3>& line, const std::vector<double>& lengths, double s) {
  size_t i = 1;
  while (i + 1 < line.size() && lengths[i] < s) ++i;
  // Skip zero-length segments backwards so that the direction is defined.
  size_t a = i - 1, b = i;
  while (lengths[b] - lengths[a] <= 0 && b + 1 < line.size()) ++b;
  const double t = (s - lengths[a]) / (lengths[b] - lengths[a]);
  const Vec3 d = line[b] - line[a];
  Vec3 along{d.x, d.y, 0};
  along = length(along) > 0 ? normalize(along) : Vec3{0, 1, 0};
  return {line[a] + d * t, along};
}

}  // namespace

std::vector<LampPlacement> place_lamp_row(const LampRowSettings& row) {
  if (row.centre_line.size() < 2) throw std::invalid_argument("a lamp row's centre line needs two points");
  if (!(row.spacing_m > 0)) throw std::invalid_argument("a lamp row's spacing must be > 0");
  const std::vector<double> lengths = cumulative_lengths(row.centre_line);
  const double total = lengths.back();
  if (!(total > 0)) throw std::invalid_argument("a lamp row's centre line has no length");
  std::vector<LampPlacement> out;
  const double lateral = row.road_width_m / 2 - row.overhang_m;  // from the centre line
  const auto place = [&](const Station& st, RoadSide side) {
    const Vec3 left{-st.along.y, st.along.x, 0};
    const double sign = side == RoadSide::left ? 1.0 : -1.0;
    const Vec3 toward_road = left * -sign;
    const Vec3 position = st.point + left * (sign * lateral) + Vec3{0, 0, row.height_m};
    const double tilt = radians(row.tilt_deg);
    const Vec3 aim = normalize(Vec3{0, 0, -std::cos(tilt)} + toward_road * std::sin(tilt));
    // C90 onto toward_road: the default frame has C0 east and C90 north, and a turn by
    // R takes C90 to (−sin R, cos R).
    const double rotation = degrees(std::atan2(-toward_road.x, toward_road.y));
    out.push_back({position, aim, rotation});
  };
  int k = 0;
  for (double s = row.first_at_m; s <= total + 1e-9; s = row.first_at_m + (++k) * row.spacing_m) {
    const Station st = station_at(row.centre_line, lengths, s);
    const RoadSide other = row.side == RoadSide::left ? RoadSide::right : RoadSide::left;
    switch (row.arrangement) {
      case LampArrangement::single_sided:
        place(st, row.side);
        break;
      case LampArrangement::opposite:
        place(st, row.side);
        place(st, other);
        break;
      case LampArrangement::staggered:
        place(st, k % 2 == 0 ? row.side : other);
        break;
    }
    if (out.size() > 100000) throw std::invalid_argument("a lamp row would hold more than 100000 luminaires");
  }
  return out;
}

}  // namespace skylit
