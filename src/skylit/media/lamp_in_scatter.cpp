#include "skylit/media/lamp_in_scatter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace skylit {

namespace {

// The phase function tabulated on this many uniform steps of θ over [0, π]: 0.044°,
// well under the ~2° width of the droplets' forward peak.
constexpr int kPhaseSteps = 4096;
// The first Gauss–Legendre panel spans half the ray's first lit angle, but not less
// than half the forward peak's width; each further panel is kPanelGrowth times wider,
// up to kMaxPanel and the lamp distribution's angular detail: as the point runs along
// the ray, the direction from the lamp turns by exactly dθ, so a panel of width Δθ
// sweeps Δθ of the distribution.
constexpr double kPhasePeakWidth = 0.02;  // rad
constexpr double kPanelGrowth = 3.0;
constexpr double kMaxPanel = 0.5;  // rad
// Three-point Gauss–Legendre on [−1, 1] (Abramowitz & Stegun 25.4.30): with panels as
// narrow as the distribution's detail, within 3e-4 of adaptive quadrature (tests).
constexpr std::array<double, 3> kNodes{-0.7745966692414834, 0.0, 0.7745966692414834};
constexpr std::array<double, 3> kWeights{0.5555555555555556, 0.8888888888888888, 0.5555555555555556};

}  // namespace

LampInScatter::LampInScatter(const FogLayer& layer, const Luminaire& lamp, const Spectrum& spectrum_per_candela,
                             const IntensityMap* map)
    : layer_(layer),
      lamp_(lamp),
      own_map_(map ? nullptr : std::make_unique<IntensityMap>(lamp)),
      map_(map ? map : own_map_.get()),
      spectrum_(spectrum_per_candela) {
  const auto& sigma = layer.unit_density_extinction_bins();
  grey_ = true;
  for (int k = 0; k < kSpectralBins; ++k) {
    sigma_[k] = static_cast<float>(sigma[k]);
    grey_ = grey_ && sigma[k] == sigma[0];
  }
  const double z = lamp.position().z;
  lamp_inside_ = z >= layer.bottom_m() && z <= layer.top_m();
  lamp_density_ = layer.density(z);
  sigma_max_ = 0;
  for (int k = 0; k < kSpectralBins; ++k) sigma_max_ = std::max(sigma_max_, sigma[k]);
  max_panel_ = std::min(kMaxPanel, lamp.distribution().angular_detail_deg() * kPi / 180);
  cos_max_gamma_ = std::cos(lamp.distribution().max_gamma_deg() * kPi / 180);
  phase_table_.resize(kPhaseSteps + 1);
  for (int i = 0; i <= kPhaseSteps; ++i)
    phase_table_[i] = static_cast<float>(layer.phase(std::cos(kPi * i / kPhaseSteps)));
}

double LampInScatter::phase(double theta) const {
  const double x = std::clamp(theta / kPi, 0.0, 1.0) * kPhaseSteps;
  const int i = std::min(static_cast<int>(x), kPhaseSteps - 1);
  const double f = x - i;
  return (1 - f) * phase_table_[i] + f * phase_table_[i + 1];
}

void LampInScatter::emitting_intervals(const Ray& ray, double s_min, double s_max, std::vector<Interval>& out) const {
  out.clear();
  if (!(s_max > s_min)) return;
  if (cos_max_gamma_ <= -1 + 1e-12) {
    out.push_back({s_min, s_max});
    return;
  }
  const Vec3& a = lamp_.aim();
  const Vec3 w0 = ray.origin - lamp_.position();
  const Vec3& d = ray.direction;
  const double c2 = cos_max_gamma_ * cos_max_gamma_;
  auto inside = [&](double s) {
    const Vec3 v = w0 + s * d;
    return dot(v, a) >= length(v) * cos_max_gamma_;
  };
  // The cone's surface: (v·a)² = cos²γ |v|², a quadratic in s; its roots split the ray
  // into pieces wholly inside or outside (tested at their middles).
  const double da = dot(d, a), wa = dot(w0, a);
  const double qa = da * da - c2, qb = 2 * (da * wa - c2 * dot(d, w0)), qc = wa * wa - c2 * dot(w0, w0);
  std::array<double, 4> cuts{};
  int n = 0;
  cuts[n++] = s_min;
  if (std::abs(qa) > 1e-12) {
    double disc = qb * qb - 4 * qa * qc;
    // A cone of 90° is a plane: a double root, which rounding may push below zero.
    if (disc < 0 && disc > -1e-12 * (qb * qb + std::abs(4 * qa * qc))) disc = 0;
    if (disc >= 0) {
      const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
      double r1 = q / qa, r2 = q != 0 ? qc / q : r1;
      if (r1 > r2) std::swap(r1, r2);
      for (double r : {r1, r2})
        if (r > s_min && r < s_max) cuts[n++] = r;
    }
  } else if (qb != 0) {
    const double r = -qc / qb;
    if (r > s_min && r < s_max) cuts[n++] = r;
  }
  cuts[n++] = s_max;
  for (int i = 0; i + 1 < n; ++i) {
    const double lo = cuts[i], hi = cuts[i + 1];
    if (!(hi > lo)) continue;
    const double middle = std::isfinite(hi) ? 0.5 * (lo + hi) : lo + std::max(1.0, std::abs(lo));
    if (!inside(middle)) continue;
    if (!out.empty() && out.back().end >= lo)
      out.back().end = hi;
    else
      out.push_back({lo, hi});
  }
}

namespace {

// (1 − e^(−x))/x with e = e^(−x) given, continued to 1 at x = 0: the mean of e^(−t) over
// [0, x], which turns an exponential density into a column.
double mean_decay(double x, double e) { return std::abs(x) < 1e-6 ? 1 - 0.5 * x : (1 - e) / x; }

}  // namespace

void LampInScatter::integrate(const Ray& ray, const RayInLayer& in, double s0, double h, double theta_lo,
                              double theta_hi, double tail_scale, double& grey, Spectrum& spectral) const {
  const Vec3& o = ray.origin;
  const Vec3& d = ray.direction;
  const Vec3& lamp = lamp_.position();
  const double eta = layer_.inverse_scale_height_per_m();
  // One Gauss–Legendre panel over [lo, hi].
  auto panel = [&](double lo, double hi) {
    const double half = 0.5 * (hi - lo), middle = 0.5 * (hi + lo);
    for (int k = 0; k < 3; ++k) {
      const double theta = middle + half * kNodes[k];
      const double s = s0 - h / std::tan(theta);
      if (!(s >= in.lo && s <= in.hi)) continue;  // outside the layer: no fog
      const Vec3 p = o + s * d;
      const double intensity = map_->candela(p - lamp);
      if (!(intensity > 0)) continue;
      // Along the view ray inside the layer ρ falls as e^(−η z_v (s − s_in)): one
      // exponential gives the density here and the column back to where the ray
      // entered (Eq. 10 in closed form).
      const double x = in.decay_per_m * (s - in.lo), e = std::exp(-x);
      const double rho = in.entry_density * e;
      if (!(rho > 0)) continue;
      const double view_column = in.entry_density * (s - in.lo) * mean_decay(x, e);
      double lamp_column;
      if (lamp_inside_) {
        const double r = length(p - lamp), y = eta * (p.z - lamp.z);
        lamp_column = lamp_density_ * r * mean_decay(y, std::exp(-y));
      } else {
        lamp_column = layer_.column_between(lamp, p);
      }
      const double weight = half * kWeights[k] * rho * intensity * phase(theta);
      const double column = view_column + lamp_column;
      if (grey_) {
        grey += weight * std::exp(-sigma_[0] * column);
      } else {
        for (int b = 0; b < kSpectralBins; ++b)
          spectral[b] += static_cast<float>(weight * std::exp(-sigma_[b] * column));
      }
    }
  };
  // The far tail: where the lit part runs on beyond the lamp for more than an optical
  // depth, the light fades as e^(−σh/(π − θ)) near θ = π, within an angle of about σh
  // of it; panels shrink geometrically toward θ_hi there, from a tenth of that angle.
  double end = theta_hi;
  if (tail_scale > 0 && theta_hi > 0.5 * kPi) {
    const double split = std::max(theta_lo, 0.5 * kPi);
    double width = std::max(kPi - theta_hi, 0.1 * tail_scale * h);
    for (double hi = theta_hi; hi > split; width = std::min(width * kPanelGrowth, max_panel_)) {
      const double lo = std::max(split, hi - width);
      panel(lo, hi);
      hi = lo;
    }
    end = split;
  }
  double width = std::min(0.5 * std::max(theta_lo, kPhasePeakWidth), max_panel_);
  for (double lo = theta_lo; lo < end; width = std::min(width * kPanelGrowth, max_panel_)) {
    const double hi = std::min(end, lo + width);
    panel(lo, hi);
    lo = hi;
  }
}

Spectrum LampInScatter::along(const Ray& ray, const std::vector<Interval>& lit) const {
  if (lit.empty()) return Spectrum(0.0f);
  thread_local std::vector<Interval> emitting;  // reused: no allocation per ray
  emitting_intervals(ray, lit.front().begin, lit.back().end, emitting);
  return along(ray, lit, emitting);
}

Spectrum LampInScatter::along(const Ray& ray, const std::vector<Interval>& lit,
                              const std::vector<Interval>& emitting) const {
  const Vec3 to_lamp = lamp_.position() - ray.origin;
  const double s0 = dot(to_lamp, ray.direction);
  const double h = std::max(length(to_lamp - s0 * ray.direction), kLampSourceRadiusM);
  auto angle_at = [&](double s) { return std::isfinite(s) ? std::atan2(h, s0 - s) : kPi; };
  // Where the view ray is in the layer, and the density where it enters.
  const RaySpan span = layer_.clip(ray.origin.z, ray.direction.z, 0.0, std::numeric_limits<double>::infinity());
  if (span.empty()) return Spectrum(0.0f);
  const double z_in = std::clamp(ray.origin.z + ray.direction.z * span.lo, layer_.bottom_m(), layer_.top_m());
  const RayInLayer in{span.lo, span.hi, layer_.density(z_in), layer_.inverse_scale_height_per_m() * ray.direction.z};
  double grey = 0;
  Spectrum spectral;
  // The pieces both lit and inside the emission cone: both lists are sorted, so one
  // pass over them finds their overlaps.
  for (size_t i = 0, j = 0; i < lit.size() && j < emitting.size();) {
    const Interval e{std::max(lit[i].begin, emitting[j].begin), std::min(lit[i].end, emitting[j].end)};
    if (lit[i].end < emitting[j].end)
      ++i;
    else
      ++j;
    if (!(e.end > e.begin)) continue;
    // The extinction where the piece ends, if the fog beyond the lamp is more than an
    // optical depth deep (then the far tail needs graded panels).
    double tail_scale = 0;
    if (e.end > s0) {
      const double s_end = std::min(e.end, in.hi);
      const double rho_end = in.entry_density * std::exp(-in.decay_per_m * (std::min(s_end, 1e12) - in.lo));
      const double sigma_end = sigma_max_ * std::max(rho_end, 0.0);
      if (sigma_end * (s_end - std::max(s0, e.begin)) > 1) tail_scale = sigma_end;
    }
    integrate(ray, in, s0, h, angle_at(e.begin), angle_at(e.end), tail_scale, grey, spectral);
  }
  const float scale = static_cast<float>(layer_.single_scattering_albedo() / h);
  if (grey_) return spectrum_ * (sigma_ * static_cast<float>(grey * scale));
  return spectrum_ * sigma_ * spectral * scale;
}

}  // namespace skylit
