// Reflectance spectra from what users give: an sRGB colour, up-sampled to a smooth
// spectrum by the method of W. Jakob and J. Hanika, "A low-dimensional function space
// for efficient spectral upsampling", Computer Graphics Forum 38(2) (Eurographics
// 2019) 147–155; or a measured spectrum given as (wavelength, value) samples.
#pragma once

#include <string_view>
#include <utility>
#include <vector>

#include "skylit/spectrum/color_difference.h"
#include "skylit/spectrum/color_space.h"
#include "skylit/spectrum/spectrum.h"
#include "skylit/spectrum/tabulated.h"

namespace skylit {

// s(λ) = S(c0 t² + c1 t + c2), t = (λ − 380 nm) / 400 nm, S(x) = ½ + x / (2√(1 + x²)):
// Jakob & Hanika's reflectance, smooth, within (0, 1) and with at most one extremum.
// Infinite c2 (with c0 = c1 = 0) stands for the flat spectra 0 and 1.
struct SigmoidPolynomial {
  double c0 = 0, c1 = 0, c2 = 0;

  double operator()(double lambda_nm) const;
};

// S(x) above, exact at x = ±∞.
double jakob_hanika_sigmoid(double x);

// The reflectance whose colour under D65 (the sRGB white), seen by the CIE 1931
// observer and integrated at 1 nm over 380–780 nm, is closest in CIELAB to the linear
// sRGB colour `linear_srgb` (components clamped to [0, 1]; NaN counts as 0). Grey
// inputs give the exact flat spectrum. Solved by Levenberg–Marquardt with continuation
// from the grey of the same luminance, as Jakob & Hanika solve their tables; bounded
// work, a fraction of a millisecond per colour.
SigmoidPolynomial fit_reflectance_to_linear_srgb(const Rgb& linear_srgb);

// The fit's colour (1 nm integration under D65, relative to D65's own white) and the
// target's colour (relative to the sRGB white): the two sides of the fit's objective.
Lab lab_under_d65(const SigmoidPolynomial& reflectance);
Lab lab_of_linear_srgb(const Rgb& linear_srgb);

// The reflectance sampled at every nm from 380 to 780 nm, linear in between: the
// curve whose bin means the renderer uses.
Tabulated tabulate_at_1nm(const SigmoidPolynomial& reflectance);

// fit_reflectance_to_linear_srgb, as bin means on kGrid of the 1 nm curve.
Spectrum reflectance_from_linear_srgb(const Rgb& linear_srgb);

// A measured reflectance given as (wavelength_nm, value) samples, linear between
// them. Outside the sampled range the end values are held (not zero): a spectrum
// measured over 400–700 nm should not turn black at its ends. Values must be within
// [0, 1] (a percentage is a common mistake and is reported as such) and wavelengths
// strictly increasing; otherwise InputError, whose message begins with `where` (the
// caller's file and JSON path).
Spectrum reflectance_from_samples(const std::vector<std::pair<double, double>>& samples_nm_value,
                                  std::string_view where);

}  // namespace skylit
