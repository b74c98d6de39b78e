#include "skylit/clouds/cloud.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "skylit/atmosphere/phase_functions.h"
#include "skylit/media/fog_phase.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace skylit {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double finite_nonnegative(double x) { return std::isfinite(x) && x > 0 ? x : 0.0; }

// Steps per vertical thickness T_max and per the horizontal scale (docs/clouds.md).
constexpr double kStepsPerThickness = 32.0;
constexpr double kStepsPerSemiAxis = 64.0;
constexpr double kStepsPerWavelength = 32.0;
constexpr int kMinSteps = 4;
constexpr int kMaxSteps = 4096;

}  // namespace

double cloud_phase(double cos_theta) {
  static const DropletPhaseParameters params = DropletPhaseParameters::for_diameter(kCloudDropletDiameterUm);
  const double c = std::isfinite(cos_theta) ? std::clamp(cos_theta, -1.0, 1.0) : 0.0;
  return droplet_phase(c, params);
}

double cloud_mean_cosine() {
  // 2π ∫ μ F(μ) dμ with μ = 1 − x², which resolves the forward spike (as the test of the
  // normalisation does).
  static const double g = [] {
    const int n = 200000;
    const double dx = std::sqrt(2.0) / n;
    double sum = 0;
    for (int i = 0; i < n; ++i) {
      const double x = (i + 0.5) * dx;
      const double mu = 1 - x * x;
      sum += mu * cloud_phase(mu) * 2 * x * dx;
    }
    return 2 * kPi * sum;
  }();
  return g;
}

Spectrum default_cloud_ambient(const Spectrum& sun_at_cloud, const Vec3& to_sun) {
  const double len = length(to_sun);
  const double sin_h = len > 0 && std::isfinite(len) ? std::max(0.0, to_sun.z / len) : 0.0;
  return sun_at_cloud * static_cast<float>(kDefaultCloudAmbientFraction * sin_h / kPi);
}

Cloud::Cloud(const CloudShape& shape) : shape_(shape) {
  shape_.semi_axis_a = finite_nonnegative(shape_.semi_axis_a);
  shape_.semi_axis_b = finite_nonnegative(shape_.semi_axis_b);
  shape_.max_thickness = finite_nonnegative(shape_.max_thickness);
  shape_.extinction = finite_nonnegative(shape_.extinction);
  shape_.albedo = std::clamp(finite_nonnegative(shape_.albedo), 0.0, 1.0);
  if (!std::isfinite(shape_.falloff_exponent) || shape_.falloff_exponent < 0) shape_.falloff_exponent = 0.5;
  if (!std::isfinite(shape_.rotation)) shape_.rotation = 0;
  if (!std::isfinite(shape_.altitude)) shape_.altitude = 0;
  if (!std::isfinite(shape_.center_x)) shape_.center_x = 0;
  if (!std::isfinite(shape_.center_y)) shape_.center_y = 0;
  cos_r_ = std::cos(shape_.rotation);
  sin_r_ = std::sin(shape_.rotation);

  const double a = shape_.semi_axis_a, b = shape_.semi_axis_b;
  horizontal_scale_ = std::min(a, b) / kStepsPerSemiAxis;
  auto texture_norm = [&](std::vector<CloudWave>& waves) {
    double sum = 0;
    for (CloudWave& w : waves) {
      if (!std::isfinite(w.amplitude)) w.amplitude = 0;
      if (!std::isfinite(w.frequency)) w.frequency = 0;
      if (!std::isfinite(w.phase)) w.phase = 0;
      sum += std::abs(w.amplitude);
      if (w.amplitude != 0 && w.frequency != 0)
        horizontal_scale_ = std::min(horizontal_scale_, 2.0 * kPi / std::abs(w.frequency) / kStepsPerWavelength);
    }
    return 1.0 + sum;
  };
  norm_u_ = texture_norm(shape_.waves_u);
  norm_v_ = texture_norm(shape_.waves_v);
  // The finest wave has at most kStepsPerWavelength·(2a / horizontal_scale_) … samples:
  // 2048 over a diameter is over 100 per wavelength of Gardner's fourth wave.
  for (int i = 0; i <= kTextureSamples; ++i) {
    const double t = -1.0 + 2.0 * i / kTextureSamples;
    texture_u_.push_back(texture(t * a, shape_.waves_u, norm_u_));
    texture_v_.push_back(texture(t * b, shape_.waves_v, norm_v_));
  }
  // The tables are what the march samples: piecewise linear, so their slope is at most
  // the largest slope of one interval (margin_bounds uses it as a Lipschitz constant).
  auto table_slope = [](const std::vector<double>& table, double half_width) {
    double rise = 0;
    for (std::size_t i = 0; i + 1 < table.size(); ++i) rise = std::max(rise, std::abs(table[i + 1] - table[i]));
    return half_width > 0 ? rise / (2.0 * half_width / kTextureSamples) : 0.0;
  };
  texture_slope_u_ = table_slope(texture_u_, a);
  texture_slope_v_ = table_slope(texture_v_, b);
  // |f''| ≤ Σ |a_i| ω_i² / (1 + Σ |a_i|) where f is smooth, i.e. where max(0, ·) never
  // clips it: when Σ |a_i| < 1. Otherwise no curvature bound (infinite).
  auto texture_curvature = [](const std::vector<CloudWave>& waves, double norm) {
    double sum = 0;
    for (const CloudWave& w : waves) sum += std::abs(w.amplitude) * w.frequency * w.frequency;
    return norm < 2.0 ? sum / norm : kInf;
  };
  texture_curvature_u_ = texture_curvature(shape_.waves_u, norm_u_);
  texture_curvature_v_ = texture_curvature(shape_.waves_v, norm_v_);
  // Half-widths of the box around the rotated ellipse.
  extent_x_ = std::hypot(a * cos_r_, b * sin_r_);
  extent_y_ = std::hypot(a * sin_r_, b * cos_r_);
  empty_ = !(a > 0 && b > 0 && shape_.max_thickness > 0 && horizontal_scale_ > 0);
}

double Cloud::texture(double w, const std::vector<CloudWave>& waves, double norm) const {
  double f = 1.0;
  for (const CloudWave& wave : waves) f += wave.amplitude * std::sin(wave.frequency * w + wave.phase);
  return std::max(0.0, f) / norm;
}

double Cloud::table_lookup(const std::vector<double>& table, double w, double half_width) {
  const double f = std::clamp((w / half_width + 1.0) * 0.5, 0.0, 1.0) * kTextureSamples;
  const int i = std::min(static_cast<int>(f), kTextureSamples - 1);
  const double t = f - i;
  return table[static_cast<size_t>(i)] * (1 - t) + table[static_cast<size_t>(i + 1)] * t;
}

double Cloud::envelope(double q) const {
  if (!(q > 0)) return 0.0;
  return shape_.falloff_exponent == 0.5 ? std::sqrt(q) : std::pow(q, shape_.falloff_exponent);
}

double Cloud::local_thickness(double u, double v) const {
  if (empty_) return 0.0;
  const double ua = u / shape_.semi_axis_a, vb = v / shape_.semi_axis_b;
  const double q = 1.0 - (ua * ua + vb * vb);
  if (!(q > 0)) return 0.0;
  return shape_.max_thickness * envelope(q) * table_lookup(texture_u_, u, shape_.semi_axis_a) *
         table_lookup(texture_v_, v, shape_.semi_axis_b);
}

double Cloud::thickness(double x, double y) const {
  const double dx = x - shape_.center_x, dy = y - shape_.center_y;
  return local_thickness(dx * cos_r_ + dy * sin_r_, -dx * sin_r_ + dy * cos_r_);
}

bool Cloud::contains(const Vec3& p) const {
  const double t = thickness(p.x, p.y);
  return t > 0 && std::abs(p.z - shape_.altitude) <= 0.5 * t;
}

// The same arithmetic as thickness() (so g is what it would be from there), keeping the
// texture factors, which are needed for bounds even where q ≤ 0.
Cloud::MarginSample Cloud::margin_sample(const Vec3& o, const Vec3& d, double t) const {
  const Vec3 p = o + d * t;
  const double dx = p.x - shape_.center_x, dy = p.y - shape_.center_y;
  const double u = dx * cos_r_ + dy * sin_r_, v = -dx * sin_r_ + dy * cos_r_;
  MarginSample s;
  s.fu = table_lookup(texture_u_, u, shape_.semi_axis_a);
  s.fv = table_lookup(texture_v_, v, shape_.semi_axis_b);
  const double ua = u / shape_.semi_axis_a, vb = v / shape_.semi_axis_b;
  const double q = 1.0 - (ua * ua + vb * vb);
  const double t_here = q > 0 ? shape_.max_thickness * envelope(q) * s.fu * s.fv : 0.0;
  s.g = 0.5 * t_here - std::abs(p.z - shape_.altitude);
  return s;
}

Cloud::RayFrame Cloud::ray_frame(const Vec3& o, const Vec3& d, double t_far) const {
  const double ox = o.x - shape_.center_x, oy = o.y - shape_.center_y;
  const double a = shape_.semi_axis_a, b = shape_.semi_axis_b;
  const double du = d.x * cos_r_ + d.y * sin_r_, dv = -d.x * sin_r_ + d.y * cos_r_;  // m per unit t
  RayFrame r;
  r.u0 = (ox * cos_r_ + oy * sin_r_) / a;
  r.v0 = (-ox * sin_r_ + oy * cos_r_) / b;
  r.du = du / a;
  r.dv = dv / b;
  const double speed2 = r.du * r.du + r.dv * r.dv;
  r.inv_speed2 = speed2 > 0 ? 1.0 / speed2 : 0.0;
  r.w0 = o.z - shape_.altitude;
  r.dw = d.z;
  r.slope_u = texture_slope_u_ * std::abs(du);
  r.slope_v = texture_slope_v_ * std::abs(dv);
  // f's deviation from its chord over a stretch of length s: curvature·(extent² + 2·spacing²)/8
  // with extent = |du|·s along the axis and spacing that of the table's nodes.
  auto bend = [](double curvature, double speed, double half_width, double& per_s2, double& constant) {
    const double spacing = 2 * half_width / kTextureSamples;
    per_s2 = curvature < kInf ? 0.125 * curvature * speed * speed : kInf;
    constant = curvature < kInf ? 0.25 * curvature * spacing * spacing : kInf;
  };
  bend(texture_curvature_u_, du, a, r.bend_u, r.bend0_u);
  bend(texture_curvature_v_, dv, b, r.bend_v, r.bend0_v);
  // Rounding. A sample's position o + d·t is off by ~1e-16 of the coordinates, its q by
  // that over the semi-axis, its g by that times g's slope (away from the rim) plus
  // ~1e-16 of T_max; the slacks are orders of magnitude above.
  const double coordinates = std::abs(o.x) + std::abs(o.y) + std::abs(o.z) + t_far * length(d);
  const double slope = 1.0 + 0.5 * shape_.max_thickness * (texture_slope_u_ + texture_slope_v_);
  r.eps = 1e-6 + 1e-12 * (coordinates * slope + shape_.max_thickness);
  r.q_slack = 1e-10 + 1e-13 * coordinates / std::min(a, b);
  return r;
}

bool Cloud::clip(const Vec3& o, const Vec3& d, double t_min, double t_max, double& t0, double& t1) const {
  if (empty_ || !(t_max > t_min)) return false;
  double lo = t_min, hi = t_max;
  // Slab |z − z_mid| ≤ T_max/2.
  const double half = 0.5 * shape_.max_thickness;
  const double z0 = shape_.altitude - half, z1 = shape_.altitude + half;
  if (std::abs(d.z) < 1e-300) {
    if (o.z < z0 || o.z > z1) return false;
  } else {
    double a = (z0 - o.z) / d.z, b = (z1 - o.z) / d.z;
    if (a > b) std::swap(a, b);
    lo = std::max(lo, a);
    hi = std::min(hi, b);
  }
  if (!(hi > lo)) return false;
  // Elliptic cylinder r < 1, in coordinates scaled by the semi-axes.
  const double dx = o.x - shape_.center_x, dy = o.y - shape_.center_y;
  const double u = (dx * cos_r_ + dy * sin_r_) / shape_.semi_axis_a;
  const double v = (-dx * sin_r_ + dy * cos_r_) / shape_.semi_axis_b;
  const double du = (d.x * cos_r_ + d.y * sin_r_) / shape_.semi_axis_a;
  const double dv = (-d.x * sin_r_ + d.y * cos_r_) / shape_.semi_axis_b;
  const double qa = du * du + dv * dv, qb = u * du + v * dv, qc = u * u + v * v - 1.0;
  if (!(qa > 1e-300)) {
    if (qc >= 0) return false;
  } else {
    const double disc = qb * qb - qa * qc;
    if (!(disc > 0)) return false;
    const double root = std::sqrt(disc);
    const double q = qb >= 0 ? -(qb + root) : -(qb - root);  // stable roots of qa t² + 2 qb t + qc
    double ta = q / qa, tb = q != 0 ? qc / q : -ta;
    if (ta > tb) std::swap(ta, tb);
    lo = std::max(lo, ta);
    hi = std::min(hi, tb);
  }
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return false;
  t0 = lo;
  t1 = hi;
  return true;
}

int Cloud::step_count(const Vec3& d, double length, double resolution) const {
  const double horizontal = std::hypot(d.x, d.y), vertical = std::abs(d.z);
  double h = kInf;
  if (vertical > 0) h = std::min(h, shape_.max_thickness / kStepsPerThickness / vertical);
  if (horizontal > 0) h = std::min(h, horizontal_scale_ / horizontal);
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
double Cloud::margin_bound(const RayFrame& r, double ta, const MarginSample& a, double tb, const MarginSample& b,
                           bool upper) const {
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
  const double half_e = 0.5 * shape_.max_thickness * envelope(upper ? q + r.q_slack : q - r.q_slack);
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

void Cloud::margin_bounds(const Vec3& o, const Vec3& d, double t0, double t1, double& lo, double& hi) const {
  if (t1 < t0) std::swap(t0, t1);
  if (empty_) {  // T = 0: g = −|z − z_mid|, linear in t
    const double w0 = o.z + d.z * t0 - shape_.altitude, w1 = o.z + d.z * t1 - shape_.altitude;
    lo = -std::max(std::abs(w0), std::abs(w1));
    hi = (w0 < 0) != (w1 < 0) ? 0.0 : -std::min(std::abs(w0), std::abs(w1));
    return;
  }
  const RayFrame r = ray_frame(o, d, std::max(std::abs(t0), std::abs(t1)));
  const MarginSample a = margin_sample(o, d, t0), b = margin_sample(o, d, t1);
  lo = margin_bound(r, t0, a, t1, b, false);
  hi = margin_bound(r, t0, a, t1, b, true);
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
struct Cloud::MarchPart {
  const Vec3& o;
  const Vec3& d;
  const RayFrame& frame;
  double a, b, h;
  int n;
  bool whole_runs, skip;
  void (*sink)(void*, double, double);
  void* ctx;
  double end(int i) const { return i == n ? b : a + i * h; }
};

void Cloud::march_span(const MarchPart& m, int i, const MarginSample& si, int j, const MarginSample& sj) const {
  const double ti = m.end(i), tj = m.end(j);
  const bool in_i = si.g >= 0, in_j = sj.g >= 0;
  // Only a run of two steps or more (for one, its end costs no more than its bound) whose
  // ends have the same sign, with room to spare, can be proven.
  const double eps = m.frame.eps;
  if (m.skip && j - i >= 2 && in_i == in_j && std::min(std::abs(si.g), std::abs(sj.g)) > eps) {
    if (!in_i && margin_bound(m.frame, ti, si, tj, sj, true) < -eps) return;  // outside throughout
    if (in_i && margin_bound(m.frame, ti, si, tj, sj, false) > eps) {        // inside throughout
      if (m.whole_runs) {
        m.sink(m.ctx, ti, tj);
      } else {
        for (int k = i + 1; k <= j; ++k) m.sink(m.ctx, m.end(k - 1), m.end(k));
      }
      return;
    }
  }
  if (j - i > 1) {
    const int mid = i + (j - i) / 2;
    const MarginSample sm = margin_sample(m.o, m.d, m.end(mid));
    march_span(m, i, si, mid, sm);
    march_span(m, mid, sm, j, sj);
    return;
  }
  // One step: inside, outside, or crossing the surface at the root of g's interpolation.
  if (in_i && in_j) {
    m.sink(m.ctx, ti, tj);
  } else if (in_i != in_j) {
    const double root = ti + (tj - ti) * si.g / (si.g - sj.g);
    if (in_i && root > ti) m.sink(m.ctx, ti, root);
    if (in_j && tj > root) m.sink(m.ctx, root, tj);
  }
}

void Cloud::march(const Vec3& o, const Vec3& d, double t0, double t1, double resolution, bool whole_runs,
                  bool every_step, void (*sink)(void*, double, double), void* ctx) const {
  if (empty_ || !(t1 > t0)) return;
  double cuts[3] = {t0, t1, t1};
  int parts = 1;
  if (std::abs(d.z) > 0) {
    const double tm = (shape_.altitude - o.z) / d.z;
    if (tm > t0 && tm < t1) {
      cuts[1] = tm;
      cuts[2] = t1;
      parts = 2;
    }
  }
  const RayFrame frame = ray_frame(o, d, std::max(std::abs(t0), std::abs(t1)));
  const int total = step_count(d, t1 - t0, resolution);
  for (int part = 0; part < parts; ++part) {
    const double a = cuts[part], b = cuts[part + 1];
    if (!(b > a)) continue;
    const int n = std::max(2, static_cast<int>(std::ceil(total * (b - a) / (t1 - t0))));
    const MarchPart m{o, d, frame, a, b, (b - a) / n, n, whole_runs, !every_step, sink, ctx};
    march_span(m, 0, margin_sample(o, d, a), n, margin_sample(o, d, b));
  }
}

double Cloud::optical_depth(const Vec3& o, const Vec3& d, double t_min, double t_max) const {
  double t0, t1;
  if (!clip(o, d, t_min, t_max, t0, t1)) return 0.0;
  double length = 0;
  // Runs proven inside come whole: the sum is that of the steps up to rounding.
  auto add = [](void* ctx, double s0, double s1) { *static_cast<double*>(ctx) += s1 - s0; };
  march(o, d, t0, t1, 1.0, true, false, add, &length);
  return shape_.extinction * length;
}

double Cloud::transmittance(const Vec3& o, const Vec3& d, double t_min, double t_max) const {
  return std::exp(-optical_depth(o, d, t_min, t_max));
}

double Cloud::sun_transmittance(const Vec3& p, const Vec3& to_sun) const {
  double t0, t1;
  if (!clip(p, to_sun, 0.0, kInf, t0, t1)) return 1.0;
  // With the sun prepared: the depth toward the sun from where the ray enters the
  // cloud's box is the whole depth along it (shadows on the ground, one look-up).
  if (sun_prepared_for(to_sun)) return std::exp(-interpolated_sun_depth(p + to_sun * t0));
  return std::exp(-optical_depth(p, to_sun, 0.0, kInf));
}

void Cloud::prepare_sun(const Vec3& to_sun) {
  sun_grid_.clear();
  const double len = length(to_sun);
  if (empty_ || !(len > 0) || !std::isfinite(len)) return;
  sun_dir_ = to_sun / len;
  std::vector<float> grid(static_cast<std::size_t>(kSunGridU) * kSunGridV * kSunGridZ);
  const double a = shape_.semi_axis_a, b = shape_.semi_axis_b, tm = shape_.max_thickness;
  tbb::parallel_for(tbb::blocked_range<int>(0, kSunGridV * kSunGridZ), [&](const tbb::blocked_range<int>& r) {
    for (int jk = r.begin(); jk != r.end(); ++jk) {
      const int j = jk % kSunGridV, k = jk / kSunGridV;
      const double v = -b + 2 * b * j / (kSunGridV - 1);
      const double z = shape_.altitude - 0.5 * tm + tm * k / (kSunGridZ - 1);
      for (int i = 0; i < kSunGridU; ++i) {
        const double u = -a + 2 * a * i / (kSunGridU - 1);
        const Vec3 p{shape_.center_x + u * cos_r_ - v * sin_r_, shape_.center_y + u * sin_r_ + v * cos_r_, z};
        const double value = optical_depth(p, sun_dir_, 0.0, kInf);
        grid[static_cast<std::size_t>(jk) * kSunGridU + i] = static_cast<float>(value);
      }
    }
  });
  sun_grid_ = std::move(grid);
}

bool Cloud::sun_prepared_for(const Vec3& to_sun) const {
  if (sun_grid_.empty()) return false;
  const double len = length(to_sun);
  if (!(len > 0) || !std::isfinite(len)) return false;
  const Vec3 d = to_sun / len;
  return std::abs(d.x - sun_dir_.x) <= 1e-12 && std::abs(d.y - sun_dir_.y) <= 1e-12 &&
         std::abs(d.z - sun_dir_.z) <= 1e-12;
}

double Cloud::interpolated_sun_depth(const Vec3& p) const {
  if (sun_grid_.empty()) return 0.0;
  const double dx = p.x - shape_.center_x, dy = p.y - shape_.center_y;
  const double u = dx * cos_r_ + dy * sin_r_, v = -dx * sin_r_ + dy * cos_r_;
  const double a = shape_.semi_axis_a, b = shape_.semi_axis_b, tm = shape_.max_thickness;
  auto cell = [](double x, int n, int& i0, double& f) {
    x = std::clamp(std::isfinite(x) ? x : 0.0, 0.0, static_cast<double>(n - 1));
    i0 = std::min(static_cast<int>(x), n - 2);
    f = x - i0;
  };
  int i, j, k;
  double fu, fv, fz;
  cell((u + a) / (2 * a) * (kSunGridU - 1), kSunGridU, i, fu);
  cell((v + b) / (2 * b) * (kSunGridV - 1), kSunGridV, j, fv);
  cell((p.z - shape_.altitude + 0.5 * tm) / tm * (kSunGridZ - 1), kSunGridZ, k, fz);
  auto at = [&](int ii, int jj, int kk) {
    return static_cast<double>(sun_grid_[(static_cast<std::size_t>(kk) * kSunGridV + jj) * kSunGridU + ii]);
  };
  auto plane = [&](int kk) {
    const double c0 = at(i, j, kk) + fu * (at(i + 1, j, kk) - at(i, j, kk));
    const double c1 = at(i, j + 1, kk) + fu * (at(i + 1, j + 1, kk) - at(i, j + 1, kk));
    return c0 + fv * (c1 - c0);
  };
  const double p0 = plane(k), p1 = plane(k + 1);
  return std::max(0.0, p0 + fz * (p1 - p0));
}

CloudScattering Cloud::scatter(const Vec3& o, const Vec3& d, double t_min, double t_max,
                               const CloudLighting& light) const {
  CloudScattering out;
  double t0, t1;
  if (!clip(o, d, t_min, t_max, t0, t1)) return out;
  const double sigma = shape_.extinction;
  const double sun_len = length(light.to_sun);
  const bool has_sun = sun_len > 0 && std::isfinite(sun_len) && !light.sun.is_black() && shape_.albedo > 0;
  const Vec3 to_sun = has_sun ? light.to_sun / sun_len : Vec3{0, 0, 1};
  const Spectrum sun_source =
      has_sun ? light.sun * static_cast<float>(shape_.albedo * cloud_phase(dot(d, to_sun) / std::max(length(d), 1e-300)))
              : Spectrum(0.0f);
  // With no usable sun direction t' is still taken straight up (as before).
  const bool use_grid = sun_prepared_for(to_sun);
  const double similarity = 1.0 - cloud_mean_cosine();  // (1 − g): van de Hulst's similarity
  double view_depth = 0;  // t(s): from the viewer's side of the cloud to s
  double view_transmittance = 1;  // e^{−t(s)}, kept as a product of the steps' e^{−τ}
  // Both sources are the same spectrum at every step: sum their scalar weights (in
  // double) and scale the spectra once.
  double sun_weight = 0, ambient_weight = 0;
  for_each_inside(o, d, t0, t1, 1.0, [&](double s0, double s1) {
    const double tau = sigma * (s1 - s0);
    const double absorbed = -std::expm1(-tau);
    const double weight = view_transmittance * absorbed;  // ∫ σ e^{−t(s)} ds over the stretch
    view_transmittance -= weight;
    const Vec3 mid = o + d * (0.5 * (s0 + s1));
    const double t_sun = use_grid ? interpolated_sun_depth(mid) : optical_depth(mid, to_sun, 0.0, kInf);
    // Single-scattered sun through e^{−t'} (Eq. 16); the multiple-scattering term I_a
    // through the similarity-scaled e^{−(1−g) t'} (docs/clouds.md).
    if (has_sun) sun_weight += weight * std::exp(-t_sun);
    ambient_weight += weight * std::exp(-similarity * t_sun);
    view_depth += tau;
  });
  if (has_sun) out.in_scattered += sun_source * static_cast<float>(sun_weight);
  out.in_scattered += light.ambient * static_cast<float>(ambient_weight);
  out.transmittance = std::exp(-view_depth);
  return out;
}

Spectrum Cloud::radiance(const Vec3& o, const Vec3& d, double t_min, double t_max, const Spectrum& behind,
                         const CloudLighting& light) const {
  const CloudScattering s = scatter(o, d, t_min, t_max, light);
  return behind * static_cast<float>(s.transmittance) + s.in_scattered;
}

}  // namespace skylit
