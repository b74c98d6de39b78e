// A spectrum as a function of the cosine of an angle, tabulated once and read by
// linear interpolation: the Fresnel terms of a material, so that shading does not
// evaluate complex square roots for 40 bins at every sample.
#pragma once

#include <functional>
#include <vector>

#include "skylit/spectrum/spectrum.h"

namespace skylit {

class AngularTable {
 public:
  // Nodes at cos = 0, 1/intervals, …, 1. With 512 intervals the interpolation error
  // of the Fresnel curves used here is below 1e-4 (tests/material/fresnel_test.cpp):
  // they are smooth in cos θ, steepest at grazing where they rise to 1.
  static constexpr int kIntervals = 512;

  AngularTable() = default;
  // f(cos θ) → spectrum, evaluated at the nodes.
  explicit AngularTable(const std::function<Spectrum(double)>& f);

  // At cos θ, clamped to [0, 1].
  Spectrum at(double cos_theta) const;
  // The mean over bins at cos θ: the same as averaging at(cos θ), for scalar
  // estimates (the renderer's search for where specular light matters).
  double mean_at(double cos_theta) const;
  // 2 ∫₀¹ f(μ) μ dμ: the cosine-weighted mean over a hemisphere of directions (for
  // a reflectance, the hemispherical one under uniform light). Simpson's rule on the
  // nodes.
  Spectrum hemispherical_mean() const;

 private:
  std::vector<Spectrum> nodes_;
  std::vector<double> means_;
};

}  // namespace skylit
