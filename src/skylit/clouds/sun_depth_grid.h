// The optical depth t' toward the sun through one cloud, tabulated: Eq. 16 needs t' at
// every step of every viewing ray, and marching toward the sun from each would cost a
// march per step. The grid holds t' at kSunGridU × kSunGridV × kSunGridZ nodes over the
// cloud's bounding volume in its frame (u, v, z − z_mid); look-ups interpolate it
// trilinearly (docs/clouds.md gives the measured error and speed-up). A node is marched
// when a look-up first needs it, by whichever thread asks: the value depends on the node
// alone, so images do not depend on the order; a cloud that few rays meet (the sky-light
// nodes' rays reach clouds 8 km away) costs a few nodes, not all 98,304 of them.
#pragma once

#include <vector>

#include "skylit/clouds/cloud_shape.h"
#include "skylit/core/vec3.h"

namespace skylit {

// Nodes of the grid: along u, v (the ellipse's axes, over [−A, A] × [−B, B]) and z (over
// the slab |z − z_mid| ≤ T_max/2).
inline constexpr int kSunGridU = 64;
inline constexpr int kSunGridV = 64;
inline constexpr int kSunGridZ = 24;

// The optical depth on both sides of a point along the sun's line: toward the sun (t',
// Eq. 16) and away from it (together, the depth of the slab the two-stream light of
// cloud_scattering.h puts the point in).
struct SunLineDepth {
  double toward_sun = 0, away_from_sun = 0;
};

// The grid of one cloud, both depths at each node side by side (a look-up that needs
// both reads each of its cells' memory once: the two grids apart were 10 % of Fig. 10a's
// run, most of it waiting on memory). Every call takes the geometry it was built from (the
// grid does not keep a reference, so the cloud holding both can be copied and moved).
class SunDepthGrid {
 public:
  // Makes room for the depths along to_sun (normalised here), no node marched yet. A
  // zero or non-finite direction, or an empty cloud, leaves the grid cleared.
  void prepare(const CloudGeometry& cloud, const Vec3& to_sun);
  void clear() { depths_.clear(); }
  // Whether a grid is prepared for this (unit or not) sun direction.
  bool prepared_for(const Vec3& to_sun) const;
  // The depths at p by trilinear interpolation (p inside the bounding volume or clamped
  // onto it), marching the nodes it needs that are not yet; the depth away from the sun
  // only if `away` (else 0); both 0 when nothing is prepared. Safe to call from several
  // threads at once.
  SunLineDepth depths_at(const CloudGeometry& cloud, const Vec3& p, bool away) const;
  // t' alone.
  double depth_at(const CloudGeometry& cloud, const Vec3& p) const { return depths_at(cloud, p, false).toward_sun; }
  // Depths marched so far, of both lines (for the tests).
  int marched_nodes() const;

 private:
  // The depth at node (i, j, k) along line 0 (toward the sun) or 1 (away), marched if it
  // is not yet.
  double node(const CloudGeometry& cloud, int i, int j, int k, int line) const;

  // Line l's depth at node (i, j, k), index 2·((k·V + j)·U + i) + l, or kNotMarched;
  // empty when not prepared. Written through std::atomic_ref (threads may march the same
  // node at once and store the same value); `mutable`: a look-up fills it.
  static constexpr float kNotMarched = -1.0f;
  mutable std::vector<float> depths_;
  Vec3 to_sun_{0, 0, 0};  // unit
};

}  // namespace skylit
