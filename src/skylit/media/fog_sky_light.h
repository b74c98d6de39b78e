// Sky light in fog (the paper's §5.2, Eqs. 13–14). The sky (and, below the horizon, the
// far ground) lights every droplet of the fog from all directions; the paper assumes a
// uniform phase function and no obstacles for it, and so do we.
//
//   J(z) = ∫_{4π} L(ω)·e^(−t'(z, ω)) dω   (Eq. 13; W m⁻² nm⁻¹)
//
// is the light arriving at altitude z inside the layer, each direction ω attenuated by the
// fog between z and the layer's face along ω (the top for directions above the horizon,
// the bottom below it; level directions see an infinite column and contribute nothing).
// It is tabulated once over the layer's altitudes. The radiance scattered toward the
// viewer along a view ray is then
//
//   I = ∫ τ(s)·(ω0/4π)·J(z(s))·e^(−t(s)) ds   (Eq. 11 with F = 1/4π),
//
// integrated by the trapezoidal rule with the adaptive pitch of Eq. 14. Quadrature,
// table and pitch constants, and why: docs/fog.md, "Sky light in fog".
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <vector>

#include "skylit/atmosphere/atmosphere.h"
#include "skylit/core/vec3.h"
#include "skylit/media/fog_diffuse_field.h"
#include "skylit/media/fog_layer.h"
#include "skylit/spectrum/spectrum.h"

namespace skylit {

class FogSkyLight {
 public:
  // Zenith bands per hemisphere (their edges at |w| = (k/16)², finer near the horizon),
  // Gauss–Legendre nodes per band, and azimuths over the half circle on one side of the
  // sun's vertical plane (the sky is symmetric about it; each counts twice).
  static constexpr int kBandsPerHemisphere = 16;
  static constexpr int kNodesPerBand = 3;
  static constexpr int kHalfAzimuths = 16;

  // Eq. 14's constants (docs/fog.md): the pitch is ds0/(τ·J·e^(−t)) with ds0 = kPitchScale
  // times the largest J of the table, so that τ·ds ≥ kPitchScale where the integrand is
  // at its largest; at most kGeometricPitch scale heights (or layer thicknesses) of
  // altitude change and a tenth of an attenuation length per step (0.3 erred by 4 % on
  // steep rays in a fog of visibility 100 m); at least kMinPitchM.
  static constexpr double kPitchScale = 0.05;
  static constexpr double kGeometricPitch = 0.07;
  static constexpr double kAttenuationPitch = 0.1;
  static constexpr double kMinPitchM = 1e-3;
  // Termination: the rest of the ray can add at most this fraction of what is summed.
  static constexpr double kTailTolerance = 1e-3;
  static constexpr int kMaxSteps = 100000;

  // Copies what it needs of `fog`; reads `sky` only here. With the layer's
  // multiple_scattering on, it also solves the layer's diffuse field (FogDiffuseField),
  // which then replaces the isotropic J(z)/4π as the light scattered along view rays.
  FogSkyLight(const FogLayer& fog, const SkyModel& sky, int altitudes = 64);

  // J(z) (W m⁻² nm⁻¹). Below the layer's bottom: the value at the bottom; above its top:
  // the unattenuated ∫L dω (there is no fog there to scatter it anyway).
  Spectrum at(double z_m) const;
  // ∫ L dω over the whole sphere without fog, from the same quadrature.
  const Spectrum& unattenuated() const { return unattenuated_; }
  // The table's altitudes (m), increasing from the bottom to the top.
  const std::vector<double>& altitudes() const { return z_; }

  // Radiance (W m⁻² sr⁻¹ nm⁻¹) scattered toward `viewpoint` by the fog's sky light along
  // the ray viewpoint + s·dir (dir a unit vector) for s in [s_begin, s_end] (m), with the
  // fog's extinction from the viewpoint: ∫ τ (ω0/4π) J e^(−t) ds, trapezoidal, Eq. 14's
  // pitch. s_end may be +∞. `steps`, when given, receives the number of trapezoids.
  Spectrum in_scattered(const Vec3& viewpoint, const Vec3& dir, double s_begin, double s_end) const {
    return in_scattered(viewpoint, dir, s_begin, s_end, nullptr);
  }
  Spectrum in_scattered(const Vec3& viewpoint, const Vec3& dir, double s_begin, double s_end, int* steps) const;
  // The same integral split into the source's azimuthal terms (FogDiffuseField), which
  // along a ray depend on its altitude and elevation only: in_scattered toward any azimuth
  // φ is then max(0, Σ_m cos(mφ)·term_m). Writes and returns the number of terms (1 in
  // the paper's mode, whose source has no azimuth; at most kMaxTerms). With multiple
  // scattering and the sun up, `sun_side` (when not null, kMaxTerms entries) receives the
  // same for the part of the source that arrives from the sun's half of the sky
  // (FogDiffuseField::sun_side_terms), which a point in a building's shadow does not
  // receive; has_sun_side() says whether there is one.
  int in_scattered_terms(const Vec3& viewpoint, const Vec3& dir, double s_begin, double s_end, Spectrum* terms,
                         Spectrum* sun_side = nullptr) const;
  static constexpr int kMaxTerms = FogDiffuseField::kModes;
  // That sun-side part's in-scattered light along a ray, weighed for its azimuth (≥ 0).
  Spectrum sun_side_in_scattered(const Vec3& viewpoint, const Vec3& dir, double s_begin, double s_end) const;
  bool has_sun_side() const { return diffuse_.has_value() && diffuse_->sun_cosine() > 0; }
  // The azimuth (radians) of a direction from the sun's, about the vertical.
  double relative_azimuth(const Vec3& dir) const;

  const FogLayer& layer() const { return fog_; }
  // The light a unit of scattering at altitude z sends in the direction of travel of
  // upward cosine `up` and azimuth `relative_azimuth` from the sunbeam's
  // (W m⁻² sr⁻¹ nm⁻¹), the sun's single scattering left out: J(z)/4π in the paper's mode,
  // the multiple-scattering field's otherwise.
  Spectrum source(double z_m, double up, double relative_azimuth) const;
  // The factor on the fog's optical depth toward the sun for the beams (1 in the paper's
  // mode; FogDiffuseField::sun_depth_scale otherwise).
  double sun_depth_scale() const { return diffuse_ ? diffuse_->sun_depth_scale() : 1.0; }
  const FogDiffuseField* diffuse_field() const { return diffuse_ ? &*diffuse_ : nullptr; }

 private:
  using TermSource = std::function<void(double z_m, double up, Spectrum* terms)>;
  // The integral of a field's table (scattered_terms or sun_side_terms) weighed for the
  // ray's azimuth, ≥ 0 (with multiple scattering only).
  using FieldTerms = void (FogDiffuseField::*)(double, double, std::array<Spectrum, FogDiffuseField::kModes>&) const;
  Spectrum weighed_for_azimuth(const Vec3& viewpoint, const Vec3& dir, double s_begin, double s_end,
                               FieldTerms field_terms, int* steps) const;
  // ∫ τ (ω0) source_t e^(−t) ds for each of `terms` source terms, Eq. 14's pitch; the
  // first `paced` of them pace the steps and end the integration.
  void integrate(const Vec3& viewpoint, const Vec3& dir, double s_begin, double s_end, int terms, int paced,
                 const TermSource& source_terms, Spectrum* out, int* steps) const;
  static constexpr int kMaxIntegrated = 2 * kMaxTerms;

  FogLayer fog_;
  Vec3 sun_horizontal_{1, 0, 0}, sun_horizontal_side_{0, 1, 0};  // the sun's azimuth and 90° from it
  std::vector<double> z_;                                        // table altitudes
  std::vector<Spectrum> j_;                                      // J at them
  std::optional<FogDiffuseField> diffuse_;                       // with multiple scattering
  std::array<double, kSpectralBins> j_max_{};                    // the largest source (per sr), per bin
  double j_max_mean_ = 0.0;                                      // its bin mean: Eq. 14's scalar scale
  Spectrum unattenuated_;
};

}  // namespace skylit
