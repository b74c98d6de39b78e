// Interval algebra (intervals.h).
#include "skylit/geometry/intervals.h"

#include <algorithm>
#include <cstddef>

namespace skylit {

void complement_of_union(double t_min, double t_max, double tolerance, std::vector<Interval>& out) {
  // Union of the pieces; gaps within the tolerance are closed.
  std::sort(out.begin(), out.end(), [](const Interval& a, const Interval& b) {
    return a.begin < b.begin || (a.begin == b.begin && a.end < b.end);
  });
  size_t merged = 0;
  for (size_t i = 0; i < out.size(); ++i) {
    if (merged > 0 && out[i].begin <= out[merged - 1].end + tolerance)
      out[merged - 1].end = std::max(out[merged - 1].end, out[i].end);
    else
      out[merged++] = out[i];
  }
  out.resize(merged);

  // Complement within [t_min, t_max], in place: the k-th uncovered piece is written
  // before the k-th covered one is overwritten, since each covered piece adds at most one.
  size_t written = 0;
  double cursor = t_min;
  for (size_t i = 0; i < merged; ++i) {
    const Interval covered = out[i];
    if (!(covered.end - covered.begin > tolerance)) continue;
    if (covered.begin - cursor > tolerance) out[written++] = {cursor, covered.begin};
    cursor = std::max(cursor, covered.end);
  }
  out.resize(written);
  if (t_max - cursor > tolerance) out.push_back({cursor, t_max});
}

double total_length(const std::vector<Interval>& pieces) {
  double sum = 0;
  for (const Interval& i : pieces) sum += i.end - i.begin;
  return sum;
}

}  // namespace skylit
