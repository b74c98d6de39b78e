// The light that reaches a surface inside a multiply scattering fog layer from each
// direction (issue 13): the layer's diffuse radiance field (fog_diffuse_field.h) read
// where the surface is, instead of the sky above scaled by the paper's J(z)/J.
//
// The paper lights a surface in the fog by the sky's band sources times the share of the
// sky light J(z) that reaches its altitude. With multiple scattering that share drops
// the light the fog scatters toward the surface, and surfaces in thick fog read a fifth
// to a half of the path-traced reference (docs/fog.md). Here:
//
// - The unobstructed irradiance on a plane of any orientation at altitude z is
//   E(n) = ∫ L(ω) max(0, n·ω) dω with L the field's radiance arriving from ω (the
//   attenuated sky, the fog's scattered light and, from below, the light of the
//   Lambertian ground at the layer's bottom). L is a Fourier series in azimuth about the
//   sunbeam, L = Σ_m cos(mφ)·R_m(−μ) for light arriving from upward cosine μ (R_m is
//   indexed by the direction of travel), and the clamped cosine is even in the azimuth
//   difference, so E(n) = Σ_m cos(mφ_n)·E_m(z, e_n) with
//   E_m(e_n) = ∫ R_m(−μ) K_m(e_n, μ) dμ and K_m = ∫ max(0, a cos ψ + b) cos mψ dψ in
//   closed form (a = cos e_n·√(1 − μ²), b = sin e_n·μ). E_m is tabulated over the
//   field's levels and 25 normal elevations; the μ integral is the midpoint rule over
//   256 elevations of the field's table (interpolated linearly between its directions).
// - A direction hidden by an obstacle d metres away changes the light from it by
//   ΔE = cos·dω·T(d)·(L_obstacle − L'(ω)), L' the field's radiance toward the point at the
//   obstacle's altitude: the fog in front of the obstacle is taken to glow as the open
//   field does along that direction (δ-M's formal solution then gives exactly this).
//   T uses δ-M's scaled depth, as the field does (light scattered into the forward spike
//   stays on its way).
//
// What it leaves out, and why: the field is that of a horizontally uniform layer, so the
// fog between buildings is lit as if nothing shaded it (the fog's glow in a street
// canyon is that of the open layer) but for the sunlight the fog in a building's shadow
// does not scatter toward a shaded point (fog_shadowed_sunlight.h, first order); the
// forward spike's sunlight is in the direct beam, so a surface that the beam does not
// reach loses the aureole within a few degrees of the sun with it.
#pragma once

#include <array>
#include <vector>

#include "skylit/core/vec3.h"
#include "skylit/media/fog_sky_light.h"
#include "skylit/spectrum/spectrum.h"

namespace skylit {

class FogSurfaceLight {
 public:
  static constexpr int kNormalElevations = 25;  // −90° … 90°, 7.5° apart
  static constexpr int kIncidentElevations = 256;

  // `sky_light` must have the multiple-scattering field (diffuse_field() not null); it
  // is referred to, not copied.
  explicit FogSurfaceLight(const FogSkyLight& sky_light);

  // Whether a point at altitude z gets its sky light here (below the layer's top; under
  // a raised layer the field at its bottom stands for the light coming out of it).
  bool covers(double z_m) const { return z_m < sky_light_.layer().top_m(); }

  // The unobstructed irradiance (W m⁻² nm⁻¹) at `point` on the side `normal` faces.
  Spectrum irradiance(const Vec3& point, const Vec3& normal) const;

  // The radiance (W m⁻² sr⁻¹ nm⁻¹) arriving at altitude z from unit direction `from`.
  Spectrum incoming(double z_m, const Vec3& from) const;

  // The fog's transmittance for diffuse light over `distance` m from `point` along
  // `direction` (δ-M's scaled depth).
  Spectrum transmittance(const Vec3& point, const Vec3& direction, double distance) const;

  // The radiance arriving from a fixed set of directions, tabulated at every level of the
  // field: what the sky-light quadrature reads for each of its directions.
  class Directions {
   public:
    Directions(const FogSurfaceLight& light, const std::vector<Vec3>& directions);
    // L arriving at altitude z from direction i of the set.
    using At = FogDiffuseField::LevelWeight;
    At at(double z_m) const;
    Spectrum incoming(const At& at, size_t direction) const {
      const size_t n = count_;
      return table_[at.below * n + direction] * (1 - at.above) + table_[(at.below + 1) * n + direction] * at.above;
    }

   private:
    const FogSurfaceLight& light_;
    size_t count_;
    std::vector<Spectrum> table_;  // [level][direction]
  };

 private:
  using Terms = std::array<Spectrum, FogDiffuseField::kModes>;
  // The irradiance's Fourier terms E_m at a level toward normal elevation row j.
  const Spectrum* irradiance_terms(size_t level, int row) const {
    return &irradiance_[(level * kNormalElevations + static_cast<size_t>(row)) * FogDiffuseField::kModes];
  }
  Spectrum incoming_at_level(size_t level, const Vec3& from, const FogDiffuseField::AzimuthTerms& cosines) const;

  const FogSkyLight& sky_light_;
  const FogDiffuseField& field_;
  double depth_scale_;
  std::vector<Spectrum> irradiance_;  // [level][normal elevation][term]
};

}  // namespace skylit
