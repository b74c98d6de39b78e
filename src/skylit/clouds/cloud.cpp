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

double Cloud::local_thickness(double u, double v) const {
  if (empty_) return 0.0;
  const double ua = u / shape_.semi_axis_a, vb = v / shape_.semi_axis_b;
  const double q = 1.0 - (ua * ua + vb * vb);
  if (!(q > 0)) return 0.0;
  const double falloff = shape_.falloff_exponent == 0.5 ? std::sqrt(q) : std::pow(q, shape_.falloff_exponent);
  return shape_.max_thickness * falloff * table_lookup(texture_u_, u, shape_.semi_axis_a) *
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

double Cloud::inside_margin(const Vec3& o, const Vec3& d, double t) const {
  const Vec3 p = o + d * t;
  return 0.5 * thickness(p.x, p.y) - std::abs(p.z - shape_.altitude);
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

// The march: [t0, t1] is split where the ray crosses the mid-plane, so that on each part
// g(t) = T/2 − |z − z_mid| is T/2 ∓ (z − z_mid) with no kink; each part is cut into
// equal steps, g is sampled at their ends, and where g changes sign within a step the
// boundary is put at the root of g's linear interpolation. The sink gets the inside
// part of each step. Where T is constant along
// the ray (vertical rays) g is linear and the result exact; elsewhere the error falls
// as the square of the step.
void Cloud::march(const Vec3& o, const Vec3& d, double t0, double t1, double resolution,
                  void (*sink)(void*, double, double), void* ctx) const {
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
  const int total = step_count(d, t1 - t0, resolution);
  for (int part = 0; part < parts; ++part) {
    const double a = cuts[part], b = cuts[part + 1];
    if (!(b > a)) continue;
    const int n = std::max(2, static_cast<int>(std::ceil(total * (b - a) / (t1 - t0))));
    const double h = (b - a) / n;
    double ta = a, ga = inside_margin(o, d, a);
    for (int i = 1; i <= n; ++i) {
      const double tb = i == n ? b : a + i * h;
      const double gb = inside_margin(o, d, tb);
      const bool in_a = ga >= 0, in_b = gb >= 0;
      if (in_a && in_b) {
        sink(ctx, ta, tb);
      } else if (in_a != in_b) {
        const double root = ta + (tb - ta) * ga / (ga - gb);
        if (in_a && root > ta) sink(ctx, ta, root);
        if (in_b && tb > root) sink(ctx, root, tb);
      }
      ta = tb;
      ga = gb;
    }
  }
}

double Cloud::optical_depth(const Vec3& o, const Vec3& d, double t_min, double t_max) const {
  double t0, t1;
  if (!clip(o, d, t_min, t_max, t0, t1)) return 0.0;
  double length = 0;
  for_each_inside(o, d, t0, t1, 1.0, [&](double s0, double s1) { length += s1 - s0; });
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
  for_each_inside(o, d, t0, t1, 1.0, [&](double s0, double s1) {
    const double tau = sigma * (s1 - s0);
    const double weight = std::exp(-view_depth) * -std::expm1(-tau);  // ∫ σ e^{−t(s)} ds over the stretch
    const Vec3 mid = o + d * (0.5 * (s0 + s1));
    const double t_sun = use_grid ? interpolated_sun_depth(mid) : optical_depth(mid, to_sun, 0.0, kInf);
    // Single-scattered sun through e^{−t'} (Eq. 16); the multiple-scattering term I_a
    // through the similarity-scaled e^{−(1−g) t'} (docs/clouds.md).
    if (has_sun) out.in_scattered += sun_source * static_cast<float>(weight * std::exp(-t_sun));
    out.in_scattered += light.ambient * static_cast<float>(weight * std::exp(-similarity * t_sun));
    view_depth += tau;
  });
  out.transmittance = std::exp(-view_depth);
  return out;
}

Spectrum Cloud::radiance(const Vec3& o, const Vec3& d, double t_min, double t_max, const Spectrum& behind,
                         const CloudLighting& light) const {
  const CloudScattering s = scatter(o, d, t_min, t_max, light);
  return behind * static_cast<float>(s.transmittance) + s.in_scattered;
}

}  // namespace skylit
