// Multiple scattering in the fog layer (issue 13): the diffuse radiance inside a flat,
// horizontally uniform layer lit by the sun and the sky at its top and resting on a
// Lambertian ground, from one-dimensional radiative transfer solved per spectral bin.
//
// Method (docs/fog.md, "Multiple scattering"):
// - The layer's phase function and albedo do not change with altitude, so in the
//   coordinate "optical depth from the top" any density profile is a homogeneous slab.
// - δ-M scaling (Wiscombe 1977, J. Atmos. Sci. 34:1408): the phase function's Legendre
//   moments χ_l are cut at 2N, a fraction f = χ_2N of the scattering going into a forward
//   spike that is treated as not scattered at all. The slab's optical depth becomes
//   (1 − ωf)τ, its albedo ω(1 − f)/(1 − ωf), its phase function the smooth rest.
// - Discrete ordinates: N Gauss–Legendre cosines per hemisphere (double Gauss), and the
//   field's Fourier terms m = 0 … 2N−1 in azimuth about the sunbeam (DISORT's splitting:
//   the addition theorem separates the δ-M phase function into terms that do not couple).
//   Between levels, each stream is integrated along its characteristic with a source
//   linear in depth (positive weights for any layer thickness); with the sky's term at the
//   top and the ground's reflection at the bottom (term 0 only: the ground is Lambertian)
//   this is one banded linear system per term and distinct extinction (grey fog: one per
//   term).
// - The field toward any direction is then the formal solution along it (the "source
//   function integration"), and the light a unit of scattering sends toward a direction
//   is f·L(u) + (1 − f)·∫p'L: what replaces Eq. 11's single-scattered source.
// - The sun's direct beam with the forward spike's light is the beam attenuated by the
//   scaled depth (1 − ωf)τ: the beams of Eq. 21 carry it with the true phase function.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <vector>

#include "skylit/media/fog_layer.h"
#include "skylit/spectrum/spectrum.h"

namespace skylit {

// What lights the layer.
struct FogLayerLighting {
  // The sky's radiance entering the top toward a downward direction whose cosine with the
  // nadir is mu (0 < mu ≤ 1) and whose azimuth of travel is phi (radians) from the
  // sunbeam's (0: travelling the way the sunlight does, i.e. seen looking toward the sun).
  std::function<Spectrum(double mu, double phi)> sky;
  Spectrum sun_irradiance;   // normal to the beam at the top (W m⁻² nm⁻¹)
  double sun_cosine = 0;     // μ0; ≤ 0: no sun
  double ground_albedo = 0;  // Lambertian, grey, at the layer's bottom
};

// Legendre moments χ_0 … χ_count−1 of a phase function normalised over the sphere
// (χ_0 = 1, χ_1 = mean cosine), by quadrature on panels crowding toward the forward
// direction, where droplets' diffraction peaks are a fraction of a degree wide.
std::vector<double> phase_legendre_moments(const std::function<double(double)>& phase, int count);

// sum += weight · Σ_m azimuth_weights[m]·terms[m] over `count` terms, bin by bin: the
// inner loop of every look-up of Fourier terms toward one azimuth, which the renderer
// runs for each view ray (one pass, no temporary spectra).
inline void add_azimuth_weighted(Spectrum& sum, const Spectrum* terms, int count, const float* azimuth_weights,
                                 float weight) {
  for (int m = 0; m < count; ++m) {
    const float c = azimuth_weights[m] * weight;
    for (int b = 0; b < kSpectralBins; ++b) sum[b] += c * terms[m][b];
  }
}

// Gauss–Legendre nodes and weights on [0, 1] (weights sum to 1).
void gauss_legendre_unit(int n, std::vector<double>& x, std::vector<double>& w);

class FogDiffuseField {
 public:
  static constexpr int kStreams = 8;                   // per hemisphere (N)
  static constexpr int kDirectionsPerHemisphere = 32;  // of the output table
  static constexpr int kModes = 2 * kStreams;          // Fourier terms in azimuth
  // cos(m·φ) for m = 0 … kModes−1: what the terms are weighed by at a relative azimuth φ.
  using AzimuthTerms = std::array<float, kModes>;
  static AzimuthTerms azimuth_terms(double relative_azimuth);

  FogDiffuseField(const FogLayer& layer, const FogLayerLighting& lighting);

  // f of δ-M and the factor (1 − ωf) on the fog's optical depth toward the sun that
  // keeps the forward spike's light in the direct beam.
  double forward_fraction() const { return f_; }
  double sun_depth_scale() const { return 1.0 - omega_ * f_; }
  double single_scattering_albedo() const { return omega_; }
  // The phase function's mean cosine g (χ_1).
  double mean_cosine() const { return f_ + (1 - f_) * chi_scaled_[1]; }
  // δ-M's smooth phase function p'(cos Θ) (sr⁻¹, normalised over the sphere): what a
  // unit of scattering sends outside the forward spike is (1 − f)·p'.
  double smooth_phase(double cos_angle) const;

  // The light a unit of scattering at altitude z sends in the direction of travel with
  // upward cosine `up` and azimuth `relative_azimuth` (radians) from the sunbeam's (per
  // steradian): ∫ p(Θ) L_diffuse dω, with the sun's single scattering left out (the beams
  // carry it). W m⁻² sr⁻¹ nm⁻¹ per unit scattering; the paper's isotropic J(z)/4π is its
  // single-scattering, isotropic counterpart.
  Spectrum scattered(double z_m, double up, double relative_azimuth) const;
  // Its Fourier terms S_m(z, up), unclamped: scattered = max(0, Σ_m cos(mφ)·S_m).
  void scattered_terms(double z_m, double up, std::array<Spectrum, kModes>& terms) const;
  // The diffuse radiance itself toward the same direction.
  Spectrum radiance(double z_m, double up, double relative_azimuth) const;
  // The same without the sun's single scattering (which the beams carry): the radiance D
  // whose forward spike `scattered` holds, f·D.
  Spectrum radiance_without_sun(double z_m, double up, double relative_azimuth) const;
  // The diffuse irradiance on a horizontal plane facing up (downward flux) at z.
  Spectrum downward_irradiance(double z_m) const;
  // The part of `scattered` brought by the diffuse light that travels within kSunSideDeg
  // of the sunbeam's direction, i.e. arrives from the sun's half of the sky: (1 − f)·∫p'L
  // over those directions (the spike's f·D excepted: it returns the light along the view
  // itself, which nothing blocks while the view goes on). A point in a building's shadow
  // has the building between it and the sun, and the building hides that light too
  // (docs/fog.md, "The field in the buildings' shadows"). Fourier terms as
  // scattered_terms; zero without the sun.
  void sun_side_terms(double z_m, double up, std::array<Spectrum, kModes>& terms) const;
  static constexpr double kSunSideDeg = 90.0;
  double sun_cosine() const { return sun_cosine_; }
  // A bound on the largest value `scattered` takes (Σ_m |S_m|), per bin.
  const std::array<double, kSpectralBins>& largest() const { return largest_; }

  // The tables' levels (by column from the top) and where altitude z falls between them:
  // the level at or above z and the weight of the next one down.
  struct LevelWeight {
    size_t below;
    float above;
  };
  LevelWeight level_at(double z_m) const;
  size_t level_count() const { return column_.size(); }
  // The diffuse radiance's Fourier terms R_m at one level toward the direction of travel
  // with upward cosine `up`, unclamped: radiance = max(0, Σ_m cos(mφ)·R_m).
  void radiance_terms_at_level(size_t level, double up, std::array<Spectrum, kModes>& terms) const;

 private:
  // The output direction at or below `up` and the weight of the next one.
  struct DirectionWeight {
    size_t below;
    float above;
  };
  DirectionWeight direction_at(double up) const;
  // A table's kModes terms at one level toward one of its directions.
  const Spectrum* terms_at(const std::vector<Spectrum>& table, size_t level, size_t direction) const {
    return &table[(level * direction_.size() + direction) * kModes];
  }
  // Adds `weight` times one level's terms, interpolated between two directions.
  void add_terms(const std::vector<Spectrum>& table, size_t level, DirectionWeight direction, float weight,
                 std::array<Spectrum, kModes>& terms) const;
  // The table's terms interpolated in altitude and direction.
  void lookup_terms(const std::vector<Spectrum>& table, double z_m, double up,
                    std::array<Spectrum, kModes>& terms) const;
  Spectrum lookup(const std::vector<Spectrum>& table, double z_m, double up, const AzimuthTerms& weights) const;

  FogLayer layer_;
  double omega_, f_;
  double sun_cosine_ = 0;                                     // μ0 when the sun lights the layer, else 0
  std::vector<double> column_;                                // column from the top (m) at each level, increasing
  std::vector<double> direction_;                             // output directions' upward cosines, increasing
  std::vector<Spectrum> scattered_, radiance_, without_sun_;  // [level][direction][term]
  std::vector<Spectrum> downward_;                            // [level]
  std::vector<Spectrum> sun_side_;                            // [level][direction][term]; empty without sun
  std::vector<double> chi_scaled_;                            // the Legendre moments of p'
  // Fills sun_side_ from the solved radiance_.
  void tabulate_sun_side(double sun_cosine);
  std::array<double, kSpectralBins> largest_{};
};

}  // namespace skylit
