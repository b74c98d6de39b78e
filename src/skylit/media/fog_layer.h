// A fog layer: the density of Eq. 2, ρ(z) = ρ0·exp(−z/h0), between a bottom and a top
// altitude and nothing outside; the extinction of Eq. 9, τ = ρ·τ0·(λ/λ0)^−b; and in
// closed form the optical depths of Eq. 10 (between two points) and of Eq. 19 (from a
// point toward the sun), the latter made finite by the layer's top. The derivations and
// units: docs/fog.md.
//
// Optical depths factor into a wavelength-free *column* N = ∫ρ ds (metres, since ρ is a
// pure number) times the extinction at unit density σ(λ) = τ0·(λ/λ0)^−b (m⁻¹): the
// geometry is done once, then each spectral bin is one multiplication.
#pragma once

#include <array>

#include "skylit/core/vec3.h"
#include "skylit/media/fog_phase.h"
#include "skylit/media/fog_settings.h"
#include "skylit/spectrum/spectrum.h"

namespace skylit {

// Columns at or above this are opaque at any extinction; they stand for "infinite"
// (the sun at or below the horizon) so that no Inf or NaN ever leaves this code.
inline constexpr double kOpaqueColumnM = 1e250;

// ρ0 from a visibility (m) at 550 nm and back, for the settings' τ0, λ0 and b
// (Koschmieder: σ(550 nm)·ρ0 = 3.912/V).
double fog_density_from_visibility(double visibility_m, const FogSettings& settings);
double fog_visibility_from_density(double density, const FogSettings& settings);

// The part [lo, hi] of a ray's parameter range that lies in the layer; empty when
// hi ≤ lo.
struct RaySpan {
  double lo = 0, hi = 0;
  bool empty() const { return !(hi > lo); }
};

class FogLayer {
 public:
  // Checks the settings (InputError naming the field) and resolves the visibility.
  explicit FogLayer(const FogSettings& settings);

  double density_at_ground() const { return rho0_; }          // ρ0 (given or from the visibility)
  double inverse_scale_height_per_m() const { return eta_; }  // 1/h0; 0 when homogeneous
  double bottom_m() const { return z_bottom_; }
  double top_m() const { return z_top_; }
  double single_scattering_albedo() const { return albedo_; }
  bool multiple_scattering() const { return multiple_scattering_; }

  // ρ(z) of Eq. 2 inside [bottom, top], 0 outside.
  double density(double z_m) const;
  // σ(λ) = τ0·(λ/λ0)^−b (m⁻¹): Eq. 9 without ρ.
  double unit_density_extinction_per_m(double wavelength_nm) const;
  // σ at the centre of each bin of kGrid, as the atmosphere does for its aerosols.
  const std::array<double, kSpectralBins>& unit_density_extinction_bins() const { return sigma_bins_; }

  // The part of s in [s1, s2] where z_p + z_v·s lies in [bottom, top].
  RaySpan clip(double z_p, double z_v, double s1, double s2) const;
  // N = ∫ρ ds along z(s) = z_p + z_v·s for s in [s1, s2] (z_v the ray's vertical
  // direction cosine; s in metres), clipped to the layer: Eq. 10 without σ.
  double column(double z_p, double z_v, double s1, double s2) const;
  // The same between two points.
  double column_between(const Vec3& a, const Vec3& b) const;
  // N' = ∫ρ from altitude z toward the sun, whose direction has vertical component
  // z_L: Eq. 19 for a bounded layer. kOpaqueColumnM when z_L ≤ 0 (the sun at or below
  // the horizon is hidden by the ground or an unbounded layer).
  double sun_column(double z_m, double z_sun) const;

  // ∫ρ over a straight piece of the layer that starts at altitude z (inside), has the
  // given length and rises by dz = z_v·length over it.
  double piece_column(double z_start_m, double rise_m, double length_m) const;

  // Whether σ is the same in every bin (b = 0, the default): then e^(−σ·N) is one number.
  bool is_grey() const { return grey_; }
  // e^(−σ(λ)·N) in each bin: the fog's transmittance along a column N.
  Spectrum transmittance(double column_m) const;

  // F(θ) for cos θ = V·L (sr⁻¹).
  double phase(double cos_theta) const;

 private:
  double log_piece_column(double z_start_m, double rise_m, double log_length) const;

  double rho0_, log_rho0_, eta_, z_bottom_, z_top_, albedo_;
  double sigma0_, lambda0_, b_;
  std::array<double, kSpectralBins> sigma_bins_{};
  bool grey_ = true;
  FogPhase phase_kind_;
  double asymmetry_;
  bool multiple_scattering_;
  DropletPhaseParameters droplet_{};
};

}  // namespace skylit
