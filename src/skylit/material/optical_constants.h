// Complex refractive indices n + ik per wavelength bin, from the measured tables of
// data/ (their sources are in data/SOURCES.md) or from values a user gives.
#pragma once

#include <complex>
#include <string_view>
#include <utility>
#include <vector>

#include "skylit/spectrum/spectrum.h"

namespace skylit {

// n and k per bin of kGrid: the bin means of the tabulated n(λ) and k(λ). Fresnel
// reflectance is a nonlinear function of them, but over a 10 nm bin n and k of
// aluminium and glass change by a few per cent at most, so F(mean n, mean k) differs
// from the mean of F by far less than the measurements' own uncertainty.
struct ComplexIor {
  Spectrum n;
  Spectrum k;

  std::complex<double> at(int bin) const { return {n[bin], k[bin]}; }
  // Absorbs strongly enough to be opaque at any practical thickness (a metal).
  bool is_conductor() const;
};

// A. D. Rakić (1995), data/metal_aluminium_nk.csv. The table has only 10 points
// between 364 and 795 nm (30–50 nm apart); between them n and k are linear, which
// is what the bin means integrate. At 550 nm n ≈ 1.02, k ≈ 6.63: normal reflectance
// 0.915.
const ComplexIor& aluminium_ior();

// Soda-lime float glass with 703 ppm Fe₂O₃, M. R. Vogt et al. (2016),
// data/glass_soda_lime_nk.csv (10 nm steps): n ≈ 1.516, k ≈ 2.4e-7 at 550 nm.
const ComplexIor& soda_lime_glass_ior();

// The same n and k in every bin.
ComplexIor constant_ior(double n, double k = 0.0);

// From (wavelength_nm, n, k) samples with increasing wavelengths: linear between
// them, the end values held beyond them (like measured reflectances), bin means.
struct IorSample {
  double wavelength_nm;
  double n;
  double k;
};
ComplexIor ior_from_samples(const std::vector<IorSample>& samples);

}  // namespace skylit
