// CIELAB from XYZ relative to a white (CIE 15:2018, §8.2.1) and the CIEDE2000 colour
// difference (CIE 142-2001, implemented as in G. Sharma, W. Wu, E. N. Dalal, "The
// CIEDE2000 color-difference formula: implementation notes, supplementary test data,
// and mathematical observations", Color Res. Appl. 30 (2005) 21–30).
//
// Colour errors in skylit (spectral up-sampling, bin count) are measured in ΔE2000:
// about 1 is a just-noticeable difference for surface colours side by side.
#pragma once

#include "skylit/spectrum/color_space.h"

namespace skylit {

struct Lab {
  double l = 0, a = 0, b = 0;
};

// CIE 1976 L*a*b* of `xyz` relative to the white `white` (any common scale: only the
// ratios X/Xn, Y/Yn, Z/Zn matter).
Lab lab_from_xyz(const Xyz& xyz, const Xyz& white);

// The CIE 1976 lightness function f(t) of CIE 15, and its derivative (for solvers
// that minimise CIELAB differences).
double cielab_f(double ratio);
double cielab_f_derivative(double ratio);

// CIEDE2000 ΔE00 with the parametric factors kL = kC = kH = 1 (reference conditions).
double delta_e_2000(const Lab& first, const Lab& second);

}  // namespace skylit
