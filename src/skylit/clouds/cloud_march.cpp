// The bounded march (cloud_march.h): margin samples and bounds along a ray, the steps,
// and the recursive skipping of runs whose sign the bounds prove.
#include "skylit/clouds/cloud_march.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace skylit {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Steps per vertical thickness T_max (the horizontal step is the cloud's
// horizontal_scale()), and the limits on their number (docs/clouds.md).
constexpr double kStepsPerThickness = 32.0;
constexpr int kMinSteps = 4;
constexpr int kMaxSteps = 4096;

// The margin g = T/2 − |z − z_mid| at o + t·d (≥ 0 inside), with the two texture
// factors f_u, f_v there (the march bounds g near t from them).
struct MarginSample {
  double g, fu, fv;
};

// A ray in the cloud's frame, for margin_bound: u(t)/a = u0 + du·t, v(t)/b likewise,
// z(t) − z_mid = w0 + dw·t; bounds on |df_u/dt|, |df_v/dt| along it, and on f_u's
// deviation from its chord over a stretch of length s (bend_u·s² + bend0_u; infinite
// where the texture has no curvature bound), f_v likewise; the margins for the
// rounding of g and q in samples up to t_far.
struct RayFrame {
  double u0, v0, du, dv, inv_speed2, w0, dw;
  double slope_u, slope_v, bend_u, bend0_u, bend_v, bend0_v;
  double eps, q_slack;
};

// The same arithmetic as thickness() (so g is what it would be from there), keeping the
// texture factors, which are needed for bounds even where q ≤ 0.
MarginSample margin_sample(const CloudGeometry& c, const Vec3& o, const Vec3& d, double t) {
  const Vec3 p = o + d * t;
  const double dx = p.x - c.shape().center_x, dy = p.y - c.shape().center_y;
  const double u = c.along_u(dx, dy), v = c.along_v(dx, dy);
  MarginSample s;
  s.fu = c.texture_u(u);
  s.fv = c.texture_v(v);
  const double ua = u / c.shape().semi_axis_a, vb = v / c.shape().semi_axis_b;
  const double q = 1.0 - (ua * ua + vb * vb);
  const double t_here = q > 0 ? c.shape().max_thickness * c.envelope(q) * s.fu * s.fv : 0.0;
  s.g = 0.5 * t_here - std::abs(p.z - c.shape().altitude);
  return s;
}

RayFrame ray_frame(const CloudGeometry& c, const Vec3& o, const Vec3& d, double t_far) {
  const double ox = o.x - c.shape().center_x, oy = o.y - c.shape().center_y;
  const double a = c.shape().semi_axis_a, b = c.shape().semi_axis_b;
  const double du = c.along_u(d.x, d.y), dv = c.along_v(d.x, d.y);  // m per unit t
  RayFrame r;
  r.u0 = c.along_u(ox, oy) / a;
  r.v0 = c.along_v(ox, oy) / b;
  r.du = du / a;
  r.dv = dv / b;
  const double speed2 = r.du * r.du + r.dv * r.dv;
  r.inv_speed2 = speed2 > 0 ? 1.0 / speed2 : 0.0;
  r.w0 = o.z - c.shape().altitude;
  r.dw = d.z;
  r.slope_u = c.texture_slope_u() * std::abs(du);
  r.slope_v = c.texture_slope_v() * std::abs(dv);
  // f's deviation from its chord over a stretch of length s: curvature·(extent² + 2·spacing²)/8
  // with extent = |du|·s along the axis and spacing that of the table's nodes.
  auto bend = [](double curvature, double speed, double half_width, double& per_s2, double& constant) {
    const double spacing = 2 * half_width / CloudGeometry::kTextureSamples;
    per_s2 = curvature < kInf ? 0.125 * curvature * speed * speed : kInf;
    constant = curvature < kInf ? 0.25 * curvature * spacing * spacing : kInf;
  };
  bend(c.texture_curvature_u(), du, a, r.bend_u, r.bend0_u);
  bend(c.texture_curvature_v(), dv, b, r.bend_v, r.bend0_v);
  // Rounding. A sample's position o + d·t is off by ~1e-16 of the coordinates, its q by
  // that over the semi-axis, its g by that times g's slope (away from the rim) plus
  // ~1e-16 of T_max; the slacks are orders of magnitude above.
  const double coordinates = std::abs(o.x) + std::abs(o.y) + std::abs(o.z) + t_far * length(d);
  const double slope = 1.0 + 0.5 * c.shape().max_thickness * (c.texture_slope_u() + c.texture_slope_v());
  r.eps = 1e-6 + 1e-12 * (coordinates * slope + c.shape().max_thickness);
  r.q_slack = 1e-10 + 1e-13 * coordinates / std::min(a, b);
  return r;
}

int step_count(const CloudGeometry& c, const Vec3& d, double length, double resolution) {
  const double horizontal = std::hypot(d.x, d.y), vertical = std::abs(d.z);
  double h = kInf;
  if (vertical > 0) h = std::min(h, c.shape().max_thickness / kStepsPerThickness / vertical);
  if (horizontal > 0) h = std::min(h, c.horizontal_scale() / horizontal);
  double n = h < kInf && h > 0 ? std::ceil(resolution * length / h) : kMinSteps;
  if (!std::isfinite(n)) n = kMaxSteps;
  return static_cast<int>(std::clamp(n, static_cast<double>(kMinSteps), static_cast<double>(kMaxSteps)));
}

// g = (T_max/2)·E(q)·f_u·f_v − |z − z_mid| with E(q) = q^p for q > 0, else 0, bounded
// over [ta, tb] from the samples at both ends (the upper bound if `upper`, else the lower):
// - q = 1 − r² is a concave quadratic in t: its range is exact (the ends and the vertex);
//   E is non-decreasing in q, so E's range follows from q's with no slope of E needed
//   (p = 1/2 has an infinite one at the rim);
// - f_u moves at most slope_u per unit t (the table's largest slope times the ray's speed
//   along u), so between the ends it lies within (f_a + f_b ± slope_u·(tb − ta))/2 (where
//   the two Lipschitz cones meet), and in [0, 1]; where the sine sum is smooth it also
//   lies within `bend` of its chord (|f''| ≤ Σ|a_i|ω_i²/(1 + Σ|a_i|)), so between the
//   smaller end value − bend and the larger + bend; f_v likewise;
// - z is linear, so |z − z_mid| lies between its values at the ends, or reaches 0 if z
//   crosses z_mid.
// Products of bounds on non-negative factors bound the product. Where both T and z
// move, bounding them apart pays for both; so, where the chords apply, the bound is also
// taken with them together along the stretch (see below), and the tighter one kept.
double margin_bound(const CloudGeometry& c, const RayFrame& r, double ta, const MarginSample& a, double tb,
                    const MarginSample& b, bool upper) {
  const double s = tb - ta;
  // q = 1 − U² − V² with U = u/a, V = v/b linear in t.
  const double U0 = r.u0 + r.du * ta, V0 = r.v0 + r.dv * ta, U1 = r.u0 + r.du * tb, V1 = r.v0 + r.dv * tb;
  const double q0 = 1.0 - (U0 * U0 + V0 * V0), q1 = 1.0 - (U1 * U1 + V1 * V1);
  double q = upper ? std::max(q0, q1) : std::min(q0, q1);
  if (upper) {
    const double vertex = -(U0 * r.du + V0 * r.dv) * r.inv_speed2;  // where dq/dt = 0, from ta
    if (vertex > 0 && vertex < s) {
      const double uu = U0 + r.du * vertex, vv = V0 + r.dv * vertex;
      q = std::max(q, 1.0 - (uu * uu + vv * vv));
    }
  }
  // With slack for the rounding of q in the samples: at the rim q^p (p < 1) magnifies it.
  const double half_e = 0.5 * c.shape().max_thickness * c.envelope(upper ? q + r.q_slack : q - r.q_slack);
  // f is smooth only on [−a, a] (the table is clamped beyond): the chord needs both ends there.
  const double bend_u = std::abs(U0) <= 1 && std::abs(U1) <= 1 ? r.bend_u * s * s + r.bend0_u : kInf;
  const double bend_v = std::abs(V0) <= 1 && std::abs(V1) <= 1 ? r.bend_v * s * s + r.bend0_v : kInf;
  auto factor = [&](double fa, double fb, double slope, double bend) {
    return upper ? std::min({1.0, 0.5 * (fa + fb + slope * s), std::max(fa, fb) + bend})
                 : std::max({0.0, 0.5 * (fa + fb - slope * s), std::min(fa, fb) - bend});
  };
  const double fu = factor(a.fu, b.fu, r.slope_u, bend_u), fv = factor(a.fv, b.fv, r.slope_v, bend_v);
  const double w0 = r.w0 + r.dw * ta, w1 = r.w0 + r.dw * tb;
  const bool crosses_mid_plane = (w0 < 0) != (w1 < 0);
  const double w_near = crosses_mid_plane ? 0.0 : std::min(std::abs(w0), std::abs(w1));
  const double w_far = std::max(std::abs(w0), std::abs(w1));
  double bound = half_e * fu * fv - (upper ? w_near : w_far);
  if (crosses_mid_plane || !(bend_u < kInf && bend_v < kInf)) return bound;
  // Together: with x = t − ta, f_u lies within bend_u of its chord a.fu + (b.fu − a.fu)·x/s
  // (the lower side needs chord − bend ≥ 0, checked at the ends as it is linear), f_v
  // likewise, and |z − z_mid| is linear, so
  //   half_e·(chord_u ± bend_u)·(chord_v ± bend_v) − |z − z_mid|
  // is a quadratic c0 + c1·x + c2·x² bounding g; its extremes are at the ends or its vertex.
  if (!upper && (std::min(a.fu, b.fu) < bend_u || std::min(a.fv, b.fv) < bend_v)) return bound;
  const double sign = upper ? 1.0 : -1.0;
  const double fu0 = a.fu + sign * bend_u, fv0 = a.fv + sign * bend_v;  // at x = 0
  const double rise_u = (b.fu - a.fu) / s, rise_v = (b.fv - a.fv) / s, rise_w = (std::abs(w1) - std::abs(w0)) / s;
  const double c0 = half_e * fu0 * fv0 - std::abs(w0);
  const double c1 = half_e * (fu0 * rise_v + fv0 * rise_u) - rise_w;
  const double c2 = half_e * rise_u * rise_v;
  auto at = [&](double x) { return c0 + (c1 + c2 * x) * x; };
  double together = upper ? std::max(c0, at(s)) : std::min(c0, at(s));
  const double x = c2 != 0 ? -c1 / (2 * c2) : -1.0;
  if (x > 0 && x < s) together = upper ? std::max(together, at(x)) : std::min(together, at(x));
  return upper ? std::min(bound, together) : std::max(bound, together);
}

// The march: [t0, t1] is split where the ray crosses the mid-plane, so that on each part
// g(t) = T/2 − |z − z_mid| is T/2 ∓ (z − z_mid) with no kink; each part is cut into
// equal steps, g is sampled at their ends, and where g changes sign within a step the
// boundary is put at the root of its linear interpolation. The sink gets the inside
// part of each step. Where T is constant along the ray (vertical rays) g is linear and
// the result exact; elsewhere the error falls as the square of the step.
//
// Skipping (march_span): the steps' ends are fixed as above, but g is only evaluated
// where its sign is not already known. Both ends of the whole part are sampled; a run of
// steps between two sampled ends is bounded by margin_bound, and if that proves g < 0
// throughout (nothing inside) or g ≥ 0 throughout (each step goes to the sink whole, as
// the plain march would send it), no end inside the run is evaluated; otherwise the run
// is halved at a step end, which is sampled, down to single steps, which are handled
// as above. The proof asks for |g| > eps, far above the rounding of g, so every end not
// evaluated has the sign the plain march would have found there, and the sink gets
// exactly the same stretches: only T is evaluated less often (docs/clouds.md).
struct MarchPart {
  const CloudGeometry& cloud;
  const Vec3& o;
  const Vec3& d;
  const RayFrame& frame;
  double a, b, h;
  int n;
  bool whole_runs, skip;
  FunctionRef<void(double, double)> sink;
  double end(int i) const { return i == n ? b : a + i * h; }
};

// The run of steps from end i to end j of a part, both ends sampled.
void march_span(const MarchPart& m, int i, const MarginSample& si, int j, const MarginSample& sj) {
  const double ti = m.end(i), tj = m.end(j);
  const bool in_i = si.g >= 0, in_j = sj.g >= 0;
  // Only a run of two steps or more (for one, its end costs no more than its bound) whose
  // ends have the same sign, with room to spare, can be proven.
  const double eps = m.frame.eps;
  if (m.skip && j - i >= 2 && in_i == in_j && std::min(std::abs(si.g), std::abs(sj.g)) > eps) {
    if (!in_i && margin_bound(m.cloud, m.frame, ti, si, tj, sj, true) < -eps) return;  // outside throughout
    if (in_i && margin_bound(m.cloud, m.frame, ti, si, tj, sj, false) > eps) {         // inside throughout
      if (m.whole_runs) {
        m.sink(ti, tj);
      } else {
        for (int k = i + 1; k <= j; ++k) m.sink(m.end(k - 1), m.end(k));
      }
      return;
    }
  }
  if (j - i > 1) {
    const int mid = i + (j - i) / 2;
    const MarginSample sm = margin_sample(m.cloud, m.o, m.d, m.end(mid));
    march_span(m, i, si, mid, sm);
    march_span(m, mid, sm, j, sj);
    return;
  }
  // One step: inside, outside, or crossing the surface at the root of g's interpolation.
  if (in_i && in_j) {
    m.sink(ti, tj);
  } else if (in_i != in_j) {
    const double root = ti + (tj - ti) * si.g / (si.g - sj.g);
    if (in_i && root > ti) m.sink(ti, root);
    if (in_j && tj > root) m.sink(root, tj);
  }
}

}  // namespace

void cloud_margin_bounds(const CloudGeometry& c, const Vec3& o, const Vec3& d, double t0, double t1, double& lo,
                         double& hi) {
  if (t1 < t0) std::swap(t0, t1);
  if (c.empty()) {  // T = 0: g = −|z − z_mid|, linear in t
    const double w0 = o.z + d.z * t0 - c.shape().altitude, w1 = o.z + d.z * t1 - c.shape().altitude;
    lo = -std::max(std::abs(w0), std::abs(w1));
    hi = (w0 < 0) != (w1 < 0) ? 0.0 : -std::min(std::abs(w0), std::abs(w1));
    return;
  }
  const RayFrame r = ray_frame(c, o, d, std::max(std::abs(t0), std::abs(t1)));
  const MarginSample a = margin_sample(c, o, d, t0), b = margin_sample(c, o, d, t1);
  lo = margin_bound(c, r, t0, a, t1, b, false);
  hi = margin_bound(c, r, t0, a, t1, b, true);
}

void march_cloud_inside(const CloudGeometry& c, const Vec3& o, const Vec3& d, double t0, double t1,
                        FunctionRef<void(double, double)> inside, const CloudMarchOptions& options) {
  if (c.empty() || !(t1 > t0)) return;
  double cuts[3] = {t0, t1, t1};
  int parts = 1;
  if (std::abs(d.z) > 0) {
    const double tm = (c.shape().altitude - o.z) / d.z;
    if (tm > t0 && tm < t1) {
      cuts[1] = tm;
      cuts[2] = t1;
      parts = 2;
    }
  }
  const RayFrame frame = ray_frame(c, o, d, std::max(std::abs(t0), std::abs(t1)));
  const int total = step_count(c, d, t1 - t0, options.resolution);
  for (int part = 0; part < parts; ++part) {
    const double a = cuts[part], b = cuts[part + 1];
    if (!(b > a)) continue;
    const int n = std::max(2, static_cast<int>(std::ceil(total * (b - a) / (t1 - t0))));
    const MarchPart m{c, o, d, frame, a, b, (b - a) / n, n, options.whole_runs, !options.every_step, inside};
    march_span(m, 0, margin_sample(c, o, d, a), n, margin_sample(c, o, d, b));
  }
}

double cloud_optical_depth(const CloudGeometry& c, const Vec3& o, const Vec3& d, double t_min, double t_max) {
  double t0, t1;
  if (!c.clip(o, d, t_min, t_max, t0, t1)) return 0.0;
  double length = 0;
  // Runs proven inside come whole: the sum is that of the steps up to rounding.
  march_cloud_inside(c, o, d, t0, t1, [&](double s0, double s1) { length += s1 - s0; }, {.whole_runs = true});
  return c.shape().extinction * length;
}

}  // namespace skylit
