// Type C intensity distributions (IES LM-63-02; CIE 121): the simple shapes, measured
// tables with their C symmetry folded back at look-up, bilinear interpolation and the
// luminous flux by numerical integration.
#include "skylit/lights/photometry.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "skylit/core/vec3.h"

namespace skylit {
namespace {

bool strictly_ascending(const std::vector<double>& v) {
  for (std::size_t i = 1; i < v.size(); ++i)
    if (!(v[i] > v[i - 1])) return false;
  return true;
}

bool near(double a, double b) { return std::abs(a - b) < 1e-6; }

std::string deg(double v) {
  std::string s = std::to_string(v);
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

// Interval index i with x[i] <= v <= x[i+1] for v inside [x.front(), x.back()].
std::size_t interval(const std::vector<double>& x, double v) {
  const auto it = std::upper_bound(x.begin(), x.end(), v);
  const std::size_t i = static_cast<std::size_t>(it - x.begin());
  return std::min(i == 0 ? 0 : i - 1, x.size() - 2);
}

}  // namespace

double TiltTable::multiplier(double tilt_deg) const {
  if (angles_deg.empty()) return 1.0;
  if (angles_deg.size() == 1 || tilt_deg <= angles_deg.front()) return multipliers.front();
  if (tilt_deg >= angles_deg.back()) return multipliers.back();
  const std::size_t i = interval(angles_deg, tilt_deg);
  const double t = (tilt_deg - angles_deg[i]) / (angles_deg[i + 1] - angles_deg[i]);
  return multipliers[i] + t * (multipliers[i + 1] - multipliers[i]);
}

IntensityDistribution IntensityDistribution::isotropic(double candela) {
  IntensityDistribution d;
  d.kind_ = Kind::kIsotropic;
  d.peak_ = candela;
  return d;
}

IntensityDistribution IntensityDistribution::cosine(double peak_candela) {
  IntensityDistribution d;
  d.kind_ = Kind::kCosine;
  d.peak_ = peak_candela;
  return d;
}

IntensityDistribution IntensityDistribution::spot(double peak_candela, double inner_deg, double outer_deg) {
  if (!(inner_deg >= 0 && inner_deg <= outer_deg && outer_deg <= 180))
    throw std::invalid_argument("spot cone angles must satisfy 0 <= inner <= outer <= 180 degrees");
  IntensityDistribution d;
  d.kind_ = Kind::kSpot;
  d.peak_ = peak_candela;
  d.inner_deg_ = inner_deg;
  d.outer_deg_ = outer_deg;
  return d;
}

IntensityDistribution IntensityDistribution::table(CSymmetry symmetry, std::vector<double> c_deg,
                                                   std::vector<double> gamma_deg, std::vector<double> candela) {
  if (gamma_deg.size() < 2) throw std::invalid_argument("at least two vertical (gamma) angles are needed");
  if (!strictly_ascending(gamma_deg)) throw std::invalid_argument("vertical (gamma) angles must increase strictly");
  if (gamma_deg.front() < 0 || gamma_deg.back() > 180)
    throw std::invalid_argument("vertical (gamma) angles must lie within 0-180 degrees");
  if (c_deg.empty()) throw std::invalid_argument("at least one horizontal (C) angle is needed");
  if (!strictly_ascending(c_deg)) throw std::invalid_argument("horizontal (C) angles must increase strictly");
  const std::string range = "horizontal (C) angles " + deg(c_deg.front()) + " to " + deg(c_deg.back());
  switch (symmetry) {
    case CSymmetry::kAxial:
      if (c_deg.size() != 1) throw std::invalid_argument("an axially symmetric table has exactly one C plane");
      break;
    case CSymmetry::kQuadrant:
      if (!near(c_deg.front(), 0) || !near(c_deg.back(), 90))
        throw std::invalid_argument(range + " do not span 0-90 (quadrant symmetry)");
      break;
    case CSymmetry::kBilateral0_180:
      if (!near(c_deg.front(), 0) || !near(c_deg.back(), 180))
        throw std::invalid_argument(range + " do not span 0-180 (bilateral symmetry)");
      break;
    case CSymmetry::kBilateral90_270:
      if (!near(c_deg.front(), -90) || !near(c_deg.back(), 90))
        throw std::invalid_argument(range + " do not span -90-90 (symmetry about the C90-C270 plane)");
      break;
    case CSymmetry::kNone:
      if (!near(c_deg.front(), 0) || c_deg.back() > 360 + 1e-6 || c_deg.size() < 2)
        throw std::invalid_argument(range + " do not start at 0 and end at most at 360 (no symmetry)");
      break;
  }
  if (candela.size() != c_deg.size() * gamma_deg.size())
    throw std::invalid_argument("the number of candela values does not match the angle counts");
  for (double v : candela)
    if (!std::isfinite(v) || v < 0) throw std::invalid_argument("candela values must be finite and not negative");
  IntensityDistribution d;
  d.kind_ = Kind::kTable;
  d.symmetry_ = symmetry;
  d.c_ = std::move(c_deg);
  d.gamma_ = std::move(gamma_deg);
  d.values_ = std::move(candela);
  d.peak_ = d.values_.empty() ? 0 : *std::max_element(d.values_.begin(), d.values_.end());
  return d;
}

double IntensityDistribution::candela(double c_deg, double gamma_deg) const {
  switch (kind_) {
    case Kind::kIsotropic:
      return peak_;
    case Kind::kCosine:
      return gamma_deg < 90 ? peak_ * std::cos(radians(gamma_deg)) : 0.0;
    case Kind::kSpot: {
      if (gamma_deg <= inner_deg_) return peak_;
      if (gamma_deg >= outer_deg_) return 0.0;
      const double t = (outer_deg_ - gamma_deg) / (outer_deg_ - inner_deg_);
      return peak_ * t * t * (3 - 2 * t);
    }
    case Kind::kTable:
      return table_candela(c_deg, gamma_deg);
  }
  return 0.0;
}

double IntensityDistribution::column_candela(std::size_t ic, double gamma_deg) const {
  const double* col = values_.data() + ic * gamma_.size();
  const std::size_t j = interval(gamma_, gamma_deg);
  const double t = (gamma_deg - gamma_[j]) / (gamma_[j + 1] - gamma_[j]);
  return col[j] + t * (col[j + 1] - col[j]);
}

double IntensityDistribution::table_candela(double c_deg, double gamma_deg) const {
  // Zero outside the measured γ range: a file that stops at 90° says nothing goes up.
  if (!(gamma_deg >= gamma_.front() - 1e-9 && gamma_deg <= gamma_.back() + 1e-9)) return 0.0;
  gamma_deg = std::clamp(gamma_deg, gamma_.front(), gamma_.back());
  if (symmetry_ == CSymmetry::kAxial) return column_candela(0, gamma_deg);

  // Fold C into the stored range by the symmetry's mirrors.
  double c = std::fmod(c_deg, 360.0);
  if (c < 0) c += 360.0;
  switch (symmetry_) {
    case CSymmetry::kQuadrant:
      if (c > 180) c = 360 - c;
      if (c > 90) c = 180 - c;
      break;
    case CSymmetry::kBilateral0_180:
      if (c > 180) c = 360 - c;
      break;
    case CSymmetry::kBilateral90_270:
      if (c > 180) c -= 360;  // (−180, 180]
      if (c > 90)
        c = 180 - c;
      else if (c < -90)
        c = -180 - c;
      break;
    default:
      break;
  }
  if (symmetry_ == CSymmetry::kNone && c > c_.back()) {
    // Between the last plane and C360 = C0.
    const double t = (c - c_.back()) / (360.0 - c_.back());
    const double a = column_candela(c_.size() - 1, gamma_deg), b = column_candela(0, gamma_deg);
    return a + t * (b - a);
  }
  c = std::clamp(c, c_.front(), c_.back());
  const std::size_t i = interval(c_, c);
  const double t = (c - c_[i]) / (c_[i + 1] - c_[i]);
  const double a = column_candela(i, gamma_deg), b = column_candela(i + 1, gamma_deg);
  return a + t * (b - a);
}

double IntensityDistribution::luminous_flux() const {
  const int n_gamma = 1440;  // 0.125°
  const bool varies_in_c = kind_ == Kind::kTable && symmetry_ != CSymmetry::kAxial;
  const int n_c = varies_in_c ? 720 : 1;  // 0.5°
  const double dg = 180.0 / n_gamma, dc = 360.0 / n_c;
  double sum = 0;
  for (int ic = 0; ic < n_c; ++ic) {
    const double c = (ic + 0.5) * dc;
    double ring = 0;
    for (int ig = 0; ig < n_gamma; ++ig) {
      const double g = (ig + 0.5) * dg;
      ring += candela(c, g) * std::sin(radians(g));
    }
    sum += ring;
  }
  return sum * radians(dg) * (2 * kPi / n_c);
}

double IntensityDistribution::peak_candela() const { return peak_; }

double IntensityDistribution::max_gamma_deg() const {
  switch (kind_) {
    case Kind::kIsotropic:
      return 180.0;
    case Kind::kCosine:
      return 90.0;
    case Kind::kSpot:
      return outer_deg_;
    case Kind::kTable:
      break;
  }
  // Bilinear interpolation reaches 0 only at the grid angle after the last non-zero
  // value; beyond the measured range the intensity is 0.
  const size_t n = gamma_.size();
  size_t last = 0;
  bool any = false;
  for (size_t ic = 0; ic < c_.size(); ++ic)
    for (size_t ig = 0; ig < n; ++ig)
      if (values_[ic * n + ig] > 0) {
        last = std::max(last, ig);
        any = true;
      }
  if (!any) return 0.0;
  return last + 1 < n ? gamma_[last + 1] : gamma_.back();
}

double IntensityDistribution::angular_detail_deg() const {
  constexpr double kSmooth = 30.0, kFinest = 1.0;
  switch (kind_) {
    case Kind::kIsotropic:
    case Kind::kCosine:
      return kSmooth;
    case Kind::kSpot:
      // A hard edge is where the lamp's cone is cut exactly; inside it is constant.
      return outer_deg_ > inner_deg_ ? std::clamp(0.5 * (outer_deg_ - inner_deg_), kFinest, kSmooth) : kSmooth;
    case Kind::kTable:
      break;
  }
  double step = kSmooth;
  for (size_t i = 1; i < gamma_.size(); ++i) step = std::min(step, gamma_[i] - gamma_[i - 1]);
  return std::clamp(3 * step, kFinest, kSmooth);
}

IntensityDistribution IntensityDistribution::scaled(double factor) const {
  IntensityDistribution d = *this;
  d.peak_ *= factor;
  for (double& v : d.values_) v *= factor;
  return d;
}

}  // namespace skylit
