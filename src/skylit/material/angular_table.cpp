// Linear interpolation in cos θ of tabulated spectra (see angular_table.h).
#include "skylit/material/angular_table.h"

#include <algorithm>
#include <utility>

namespace skylit {

namespace {

// The interval and the weight of its upper node for cos θ.
std::pair<int, double> locate(double cos_theta) {
  const double x = std::clamp(cos_theta, 0.0, 1.0) * AngularTable::kIntervals;
  const int i = std::min(static_cast<int>(x), AngularTable::kIntervals - 1);
  return {i, x - i};
}

}  // namespace

AngularTable::AngularTable(const std::function<Spectrum(double)>& f) {
  nodes_.reserve(kIntervals + 1);
  for (int i = 0; i <= kIntervals; ++i) {
    nodes_.push_back(f(static_cast<double>(i) / kIntervals));
    means_.push_back(nodes_.back().mean_value());
  }
}

Spectrum AngularTable::at(double cos_theta) const {
  const auto [i, t] = locate(cos_theta);
  const float w = static_cast<float>(t);
  const Spectrum& a = nodes_[static_cast<size_t>(i)];
  const Spectrum& b = nodes_[static_cast<size_t>(i) + 1];
  Spectrum out;
  for (int k = 0; k < Spectrum::size(); ++k) out[k] = a[k] + w * (b[k] - a[k]);
  return out;
}

double AngularTable::mean_at(double cos_theta) const {
  const auto [i, t] = locate(cos_theta);
  const double a = means_[static_cast<size_t>(i)], b = means_[static_cast<size_t>(i) + 1];
  return a + t * (b - a);
}

Spectrum AngularTable::hemispherical_mean() const {
  static_assert(kIntervals % 2 == 0, "Simpson's rule needs an even number of intervals");
  Spectrum out;
  for (int i = 0; i <= kIntervals; ++i) {
    const double mu = static_cast<double>(i) / kIntervals;
    const double simpson = (i == 0 || i == kIntervals) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    const double w = 2.0 * mu * simpson / (3.0 * kIntervals);
    out += nodes_[static_cast<size_t>(i)] * static_cast<float>(w);
  }
  return out;
}

}  // namespace skylit
