// Closed ranges of a ray's parameter and the little algebra the shadow volumes need:
// the union of shadow pieces, its complement (the lit pieces), their total length.
// Shared by the sun's and the point lights' shadow volumes, and by the lamps' glow,
// which intersects lit pieces with the lamp's emission cone.
#pragma once

#include <vector>

namespace skylit {

// A closed range [begin, end] of the ray parameter t (units of the direction's length).
struct Interval {
  double begin;
  double end;
};

// Replaces the pieces (in any order, overlapping or not) by the parts of [t_min, t_max]
// that none of them covers, sorted and disjoint. Gaps between pieces, pieces, and
// uncovered parts no longer than `tolerance` are taken as rounding: closed, ignored
// and dropped. In place: no allocation beyond one more piece.
void complement_of_union(double t_min, double t_max, double tolerance, std::vector<Interval>& pieces);

// Sum of the pieces' lengths, in t units.
double total_length(const std::vector<Interval>& pieces);

}  // namespace skylit
