// What a user sets about fog: the paper's exponential density (§3.2, Eq. 2) in a flat
// layer with a bottom and a top, its extinction (§5, Eq. 9) and its phase function.
// Units, defaults and the reasons for them: docs/fog.md.
#pragma once

#include <limits>
#include <optional>

namespace skylit {

enum class FogPhase {
  droplet_fit,        // Jendersie & d'Eon (2023): HG + Draine fitted to Mie for water droplets
  henyey_greenstein,  // Henyey & Greenstein (1941) with the asymmetry below
};

struct FogSettings {
  // ρ0 of Eq. 2: the relative particle density at altitude 0 (the ground), a pure
  // number. The fog's extinction at λ0 there is ρ0·τ0. The paper's Fig. 8a has 0.59.
  double density_at_ground = 0.59;
  // Instead of ρ0: the meteorological visibility (m) that density would give at 550 nm,
  // by Koschmieder, V = 3.912/σ(550 nm). When set, it replaces density_at_ground.
  std::optional<double> ground_visibility_m;
  // h0 of Eq. 2 (m): the density falls by e over h0 upward; negative h0 makes the fog
  // denser with height (the paper's Fig. 8b: ρ0 = 0.037, h0 = −15). ±∞ is a homogeneous
  // layer. Must not be 0.
  double scale_height_m = 10.0;
  // The layer (m above the ground): no fog below the bottom or above the top. The top
  // keeps the optical depth toward the sun finite, which h0 < 0 needs.
  double bottom_altitude_m = 0.0;
  double top_altitude_m = 60.0;
  // τ0 of Eq. 9: the extinction coefficient (m⁻¹) at λ0 where ρ = 1. With 0.02 m⁻¹ the
  // paper's ρ0 = 0.59 is a moderate fog (visibility 331 m at the ground).
  double unit_density_extinction_per_m = 0.02;
  double reference_wavelength_nm = 550.0;  // λ0 of Eq. 9
  // b of Eq. 9: extinction ∝ (λ/λ0)^−b. Fog droplets (5–50 µm) are far larger than the
  // wavelength, so their extinction hardly depends on it: b = 0 (white fog).
  double wavelength_exponent = 0.0;
  // Scattering / extinction. Water droplets absorb next to nothing in the visible.
  double single_scattering_albedo = 1.0;
  FogPhase phase = FogPhase::droplet_fit;
  double droplet_diameter_um = 15.0;  // for droplet_fit; the fit holds for 5–50 µm
  double asymmetry = 0.85;            // g, for henyey_greenstein
  // Light scattered more than once (docs/fog.md, "Multiple scattering"): a 1-D
  // discrete-ordinates solution for the layer with its Fourier terms in azimuth about
  // the sun, lighting the fog and the surfaces in it. false: the paper's single
  // scattering (§5: the sun's beams and the sky light of Eq. 13, isotropic), grey and too
  // dark in thick fog, kept as the paper's mode.
  bool multiple_scattering = true;
};

// Koschmieder's constant: −ln 0.02, the visual range at a 2 % contrast threshold.
inline constexpr double kKoschmiederConstant = 3.912;

}  // namespace skylit
