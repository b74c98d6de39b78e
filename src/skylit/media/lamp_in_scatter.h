// The light of a lamp (a point source with an intensity distribution) scattered once by
// the fog toward a viewer: the glow around street lamps and the beams of headlights in
// fog (§7, Fig. 9), integrated without sampling noise.
//
// Along a viewing ray o + s·d, the radiance the fog adds toward o is (single scattering)
//
//   L(λ) = ∫ ω ρ(z) σ(λ) · I_e(λ, p − P)/r² · T(λ; P → p) · T(λ; o → p) · F(θ) ds
//
// over the parts of the ray the lamp lights (shadow volumes from the lamp, exact), with
// P the lamp, r = |p − P|, θ the scattering angle between the light's path P → p and
// the way back to the viewer −d, T the fog's transmittances (Eq. 10 in closed form),
// F its phase function and I_e the lamp's spectral radiant intensity. With h the
// distance of the ray from the lamp and s₀ the foot of the perpendicular, s − s₀ =
// −h cot θ and ds/r² = dθ/h: in the scattering angle the inverse-square singularity
// vanishes and L = (1/h)∫ ω ρ σ I_e T T F dθ over θ ∈ (0, π) (the substitution of
// Nishita et al. 1987 for point sources in a scattering medium; for a homogeneous
// medium and an isotropic lamp it leads to the closed form of Sun et al. 2005, "A
// practical analytic single scattering model for real time rendering", which the
// tests use). The integral in θ is done by Gauss–Legendre panels that start small at
// the ray's first lit angle and grow geometrically (the fog's phase function has a
// forward peak a degree wide, seen where the ray passes close to the lamp), cut also
// where the ray enters and leaves the lamp's emission cone; where the ray runs on for
// more than an optical depth beyond the lamp, panels also shrink geometrically toward
// θ = π, where the far tail fades within an angle of about σh. Measured: within 2e-5
// of the closed form (lamps ahead of and behind the viewer) and 3e-4 of adaptive
// quadrature (docs/lights.md).
#pragma once

#include <memory>
#include <vector>

#include "skylit/geometry/intervals.h"
#include "skylit/geometry/ray_tracer.h"
#include "skylit/lights/intensity_map.h"
#include "skylit/lights/luminaire.h"
#include "skylit/media/fog_layer.h"
#include "skylit/spectrum/spectrum.h"

namespace skylit {

// A lamp's luminous opening is not a point: rays passing closer than this to the lamp
// are treated as passing at this distance (the in-scatter of a point source grows as
// 1/h). Typical street-lamp and headlight openings are 0.1–0.5 m across.
inline constexpr double kLampSourceRadiusM = 0.05;

class LampInScatter {
 public:
  // The lamp and its spectrum per candela (lights/lamp_spectrum.h), in `layer`; the
  // intensity is looked up in `map` (built here if none is given), which must be the
  // lamp's and outlive this object.
  LampInScatter(const FogLayer& layer, const Luminaire& lamp, const Spectrum& spectrum_per_candela,
                const IntensityMap* map = nullptr);

  // W m⁻² sr⁻¹ nm⁻¹ scattered toward the ray's origin over the lit parts of the ray
  // (`lit`: parameter intervals along the unit direction, sorted, within the ray).
  Spectrum along(const Ray& ray, const std::vector<Interval>& lit) const;
  // The same when the parts inside the emission cone (emitting_intervals over a range
  // covering `lit`) are known already.
  Spectrum along(const Ray& ray, const std::vector<Interval>& lit, const std::vector<Interval>& emitting) const;

  // The parts of [s_min, s_max] where the lamp sends light (inside its emission cone,
  // γ ≤ max_gamma_deg of its distribution), into `out`.
  void emitting_intervals(const Ray& ray, double s_min, double s_max, std::vector<Interval>& out) const;

 private:
  // ∫ over θ in [theta_lo, theta_hi] for a ray at distance h from the lamp with foot s₀.
  struct RayInLayer {
    double lo, hi;         // the view ray's parameter range inside the layer
    double entry_density;  // ρ where it enters (at lo)
    double decay_per_m;    // η·z_v: ρ(s) = entry_density·e^(−decay_per_m·(s − lo))
  };
  // tail_scale: the extinction (m⁻¹) at the far end when the piece runs on beyond the
  // lamp for more than an optical depth (its far tail then gets graded panels), else 0.
  void integrate(const Ray& ray, const RayInLayer& in, double s0, double h, double theta_lo, double theta_hi,
                 double tail_scale, double& grey, Spectrum& spectral) const;
  double phase(double theta) const;

  const FogLayer& layer_;
  const Luminaire& lamp_;
  std::unique_ptr<IntensityMap> own_map_;
  const IntensityMap* map_;
  Spectrum spectrum_;
  Spectrum sigma_;  // the fog's extinction at unit density in each bin
  bool grey_;       // σ the same in every bin: one exponential per node
  double cos_max_gamma_;
  double max_panel_;                // rad: the widest Gauss–Legendre panel
  double sigma_max_;                // the largest extinction at unit density over the bins
  bool lamp_inside_;                // the lamp is in the layer: its paths to the view ray stay in it
  double lamp_density_;             // ρ at the lamp
  std::vector<float> phase_table_;  // F(θ) on a uniform θ grid
};

}  // namespace skylit
