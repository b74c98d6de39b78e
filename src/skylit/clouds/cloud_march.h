// The bounded march through a cloud's solid (cloud_shape.h): which stretches of a ray
// lie inside, and the optical depth along it. A cloud has no closed-form intersection
// (its thickness is a textured function), so the ray is cut into steps and the boundary
// found within each (docs/clouds.md). The march skips the evaluation of T wherever a
// bound on the margin g = T/2 − |z − z_mid| over a run of its steps
// (cloud_margin_bounds) proves that g keeps its sign there: its steps are those of the
// plain fixed-step march and the stretches it finds inside are the same, it only
// evaluates T less often. View rays, shadows and the sun-depth grid all march here.
#pragma once

#include "skylit/clouds/cloud_shape.h"
#include "skylit/core/function_ref.h"
#include "skylit/core/vec3.h"

namespace skylit {

struct CloudMarchOptions {
  // Scales the number of steps (1: the default density, docs/clouds.md).
  double resolution = 1.0;
  // A run of steps proven inside comes as one stretch instead of step by step (for sums
  // of lengths: the same sum up to rounding).
  bool whole_runs = false;
  // Evaluate T at every step's end instead of skipping where the margin bounds prove the
  // sign of g: the same stretches, slower (for tests of the skipping).
  bool every_step = false;
};

// Calls inside(s0, s1) for each stretch of [t0, t1] (already clipped, CloudGeometry::clip)
// of the ray o + t·d found inside the solid (the inside part of each step of the march),
// in order.
void march_cloud_inside(const CloudGeometry& cloud, const Vec3& o, const Vec3& d, double t0, double t1,
                        FunctionRef<void(double, double)> inside, const CloudMarchOptions& options = {});

// Optical depth (grey) along o + t·d, t in [t_min, t_max], d a unit vector: σ times the
// length marched inside.
double cloud_optical_depth(const CloudGeometry& cloud, const Vec3& o, const Vec3& d, double t_min, double t_max);

// Bounds lo ≤ g(t) ≤ hi on the margin g = T/2 − |z − z_mid| (≥ 0 inside) at every point
// o + t·d with t in [t0, t1], from samples at the two ends (up to rounding; d need not be
// unit). Rigorous, not an estimate: the envelope (1 − r²)^p is non-decreasing in 1 − r²,
// an exact quadratic along the ray (so the unbounded slope of p < 1 at the rim does not
// matter); each texture factor moves no faster than its table's largest slope and,
// where its sine sum is never clipped at 0, stays within |f''|·length²/8 of its chord;
// z is linear (cloud_march.cpp, margin_bound). The march uses them to skip runs of steps
// where g cannot change sign.
void cloud_margin_bounds(const CloudGeometry& cloud, const Vec3& o, const Vec3& d, double t0, double t1, double& lo,
                         double& hi);

}  // namespace skylit
