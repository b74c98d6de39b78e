// The CIE standard general sky (ISO 15469:2004 / CIE S 011/E:2003): fifteen relative
// luminance distributions of real skies, from overcast (type 1) to cloudless (type 15),
// each a gradation function of the zenith angle times an indicatrix function of the
// angle from the sun, normalised to the zenith:
//
//   L(Z, χ) / L_z = f(χ) φ(Z) / (f(Z_s) φ(0)),
//   φ(Z) = 1 + a exp(b / cos Z)                    (φ(90°) = 1)
//   f(χ) = 1 + c [exp(d χ) − exp(d π/2)] + e cos²χ
//
// docs/weather.md says how skylit scales them and which spectrum it gives them.
#pragma once

#include "skylit/core/vec3.h"

namespace skylit {

inline constexpr int kCieSkyTypes = 15;

struct CieSkyParameters {
  double a, b;     // gradation
  double c, d, e;  // indicatrix
};

// Type 1 to 15, from the standard's Table 1 (gradation groups I–VI, indicatrix groups 1–6).
CieSkyParameters cie_sky_parameters(int type);

// What a scene asks for: a CIE sky in place of the atmosphere's own sky, scaled so that
// the unobstructed horizontal plane receives `diffuse_horizontal_lux` from it.
struct CieSkySettings {
  int type = 1;
  double diffuse_horizontal_lux = 10000.0;
  // The sun's direct beam from the atmosphere model (clear and intermediate skies) or
  // none (overcast: the default for types 1 to 6, where the sun is hidden).
  bool direct_sun = false;
};

// L/L_z toward the unit direction `view` (z up) for the unit direction `to_sun`; 0 below
// the horizon. The sun may be below the horizon (twilight types keep their formula).
double cie_relative_luminance(const CieSkyParameters& p, const Vec3& view, const Vec3& to_sun);

// ∫ (L/L_z) cos Z dω over the sky hemisphere: the horizontal illuminance of a sky whose
// zenith luminance is 1 cd/m², in lx. By a midpoint rule fine enough for 1e-4.
double cie_horizontal_illuminance_per_zenith_luminance(const CieSkyParameters& p, const Vec3& to_sun);

}  // namespace skylit
