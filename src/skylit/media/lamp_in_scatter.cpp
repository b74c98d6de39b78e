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
// up to kMaxPanel (14°: the structure of street-lamp distributions) and a quarter of
// the lit piece (a narrow beam crossed by the ray gets at least four panels).
constexpr double kPhasePeakWidth = 0.02;  // rad
constexpr double kPanelGrowth = 3.0;
constexpr double kMaxPanel = 0.25;  // rad
// Four-point Gauss–Legendre on [−1, 1] (Abramowitz & Stegun 25.4.30).
constexpr std::array<double, 4> kNodes{-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                                       0.8611363115940526};
constexpr std::array<double, 4> kWeights{0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                         0.3478548451374538};

}  // namespace

LampInScatter::LampInScatter(const FogLayer& layer, const Luminaire& lamp, const Spectrum& spectrum_per_candela)
    : layer_(layer), lamp_(lamp), spectrum_(spectrum_per_candela) {
  const auto& sigma = layer.unit_density_extinction_bins();
  grey_ = true;
  for (int k = 0; k < kSpectralBins; ++k) {
    sigma_[k] = static_cast<float>(sigma[k]);
    grey_ = grey_ && sigma[k] == sigma[0];
  }
  cos_max_gamma_ = std::cos(lamp.distribution().max_gamma_deg() * kPi / 180);
  phase_table_.resize(kPhaseSteps + 1);
  for (int i = 0; i <= kPhaseSteps; ++i) phase_table_[i] = static_cast<float>(layer.phase(std::cos(kPi * i / kPhaseSteps)));
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
    if (!out.empty() && out.back().end >= lo) out.back().end = hi;
    else out.push_back({lo, hi});
  }
}

void LampInScatter::integrate(const Ray& ray, double s0, double h, double theta_lo, double theta_hi, double& grey,
                              Spectrum& spectral) const {
  const Vec3& o = ray.origin;
  const Vec3& d = ray.direction;
  const Vec3& lamp = lamp_.position();
  const double max_width = std::min(kMaxPanel, 0.25 * (theta_hi - theta_lo));
  double width = std::min(0.5 * std::max(theta_lo, kPhasePeakWidth), max_width);
  for (double lo = theta_lo; lo < theta_hi; width = std::min(width * kPanelGrowth, max_width)) {
    const double hi = std::min(theta_hi, lo + width);
    const double half = 0.5 * (hi - lo), middle = 0.5 * (hi + lo);
    for (int k = 0; k < 4; ++k) {
      const double theta = middle + half * kNodes[k];
      const double s = s0 - h / std::tan(theta);
      const Vec3 p = o + s * d;
      const double rho = layer_.density(p.z);
      if (!(rho > 0)) continue;
      const double intensity = lamp_.intensity(p - lamp);
      if (!(intensity > 0)) continue;
      const double weight = half * kWeights[k] * rho * intensity * phase(theta);
      const double column = layer_.column(o.z, d.z, 0.0, s) + layer_.column_between(lamp, p);
      if (grey_) {
        grey += weight * std::exp(-sigma_[0] * column);
      } else {
        for (int b = 0; b < kSpectralBins; ++b)
          spectral[b] += static_cast<float>(weight * std::exp(-sigma_[b] * column));
      }
    }
    lo = hi;
  }
}

Spectrum LampInScatter::along(const Ray& ray, const std::vector<Interval>& lit) const {
  const Vec3 to_lamp = lamp_.position() - ray.origin;
  const double s0 = dot(to_lamp, ray.direction);
  const double h = std::max(length(to_lamp - s0 * ray.direction), kLampSourceRadiusM);
  auto angle_at = [&](double s) { return std::isfinite(s) ? std::atan2(h, s0 - s) : kPi; };
  double grey = 0;
  Spectrum spectral;
  std::vector<Interval> emitting;
  for (const Interval& piece : lit) {
    emitting_intervals(ray, piece.begin, piece.end, emitting);
    for (const Interval& e : emitting) integrate(ray, s0, h, angle_at(e.begin), angle_at(e.end), grey, spectral);
  }
  const float scale = static_cast<float>(layer_.single_scattering_albedo() / h);
  if (grey_) return spectrum_ * (sigma_ * static_cast<float>(grey * scale));
  return spectrum_ * sigma_ * spectral * scale;
}

}  // namespace skylit
