#include "skylit/media/fog_behind_surface.h"

#include <algorithm>
#include <cmath>

#include "skylit/core/angles.h"

namespace skylit {
namespace {

constexpr double kElevationStepDeg = 180.0 / (FogBehindSurfaces::kElevations - 1);
constexpr double kAzimuthStep = kPi / (FogBehindSurfaces::kAzimuths - 1);
// Beyond this optical depth to the viewer nothing the fog does in front of a surface shows
// (FogMedium's kSeenDepth is 10).
constexpr double kHiddenDepth = 30.0;

// The bin whose centre is nearest 550 nm.
int bin_near_550_nm() {
  int best = 0;
  for (int b = 1; b < kSpectralBins; ++b)
    if (std::abs(kGrid.center_nm(b) - 550.0) < std::abs(kGrid.center_nm(best) - 550.0)) best = b;
  return best;
}

}  // namespace

Transmittance hidden_light_transmittance(const Transmittance& fog_to_viewer) {
  const auto least = static_cast<float>(std::exp(-kHiddenHeldDepth));
  Spectrum t = fog_to_viewer.spectrum();
  for (int b = 0; b < kSpectralBins; ++b) t[b] = std::max(t[b], least);
  return Transmittance(t);
}

FogBehindSurfaces::FogBehindSurfaces(const FogLayer& layer, const FogDiffuseField& field, const Vec3& sunbeam)
    : layer_(layer),
      field_(field),
      albedo_(field.single_scattering_albedo()),
      transport_scale_(1 - field.single_scattering_albedo() * field.mean_cosine()),
      sunbeam_(sunbeam),
      reference_bin_(bin_near_550_nm()) {
  const Vec3 horizontal{sunbeam.x, sunbeam.y, 0.0};
  sun_horizontal_ = length(horizontal) > 1e-9 ? normalize(horizontal) : Vec3{1, 0, 0};
  // Rings by Gauss–Legendre in the angle from the view (p' has a lobe tens of degrees
  // wide about it), even steps around.
  std::vector<double> x, w;
  gauss_legendre_unit(kRings, x, w);
  const double spike_free = 1.0 - field.forward_fraction();
  for (int r = 0; r < kRings; ++r) {
    const double angle = kPi * x[static_cast<size_t>(r)];
    Ring& ring = rings_[static_cast<size_t>(r)];
    ring.cos_angle = std::cos(angle);
    ring.sin_angle = std::sin(angle);
    // (A truncated series may dip below 0 far from its peak.)
    ring.weight = spike_free * std::max(0.0, field.smooth_phase(ring.cos_angle)) * kPi * w[static_cast<size_t>(r)] *
                  ring.sin_angle * 2 * kPi / kAround;
  }
  for (int a = 0; a < kAround; ++a) {
    const double psi = 2 * kPi * (a + 0.5) / kAround;
    around_cos_[static_cast<size_t>(a)] = std::cos(psi);
    around_sin_[static_cast<size_t>(a)] = std::sin(psi);
  }
  // The field's radiance at each level by elevation and azimuth from the sunbeam's.
  const size_t levels = field.level_count();
  radiance_.assign(levels * kElevations * kAzimuths, Spectrum(0.0f));
  std::array<Spectrum, FogDiffuseField::kModes> terms;
  std::array<FogDiffuseField::AzimuthTerms, kAzimuths> azimuths;
  for (int j = 0; j < kAzimuths; ++j)
    azimuths[static_cast<size_t>(j)] = FogDiffuseField::azimuth_terms(j * kAzimuthStep);
  for (size_t k = 0; k < levels; ++k)
    for (int i = 0; i < kElevations; ++i) {
      field.radiance_terms_at_level(k, std::sin(radians(-90.0 + i * kElevationStepDeg)), terms);
      for (int j = 0; j < kAzimuths; ++j) {
        Spectrum v(0.0f);
        add_azimuth_weighted(v, terms.data(), FogDiffuseField::kModes, azimuths[static_cast<size_t>(j)].data(), 1.0f);
        for (int b = 0; b < kSpectralBins; ++b) v[b] = std::max(v[b], 0.0f);
        radiance_[(k * kElevations + static_cast<size_t>(i)) * kAzimuths + static_cast<size_t>(j)] = v;
      }
    }
}

Spectrum FogBehindSurfaces::field_radiance(FogDiffuseField::LevelWeight level, const Vec3& direction) const {
  const double fe = std::clamp((degrees(std::asin(std::clamp(direction.z, -1.0, 1.0))) + 90.0) / kElevationStepDeg, 0.0,
                               kElevations - 1.0);
  const Vec3 horizontal{direction.x, direction.y, 0.0};
  const double along = dot(horizontal, sun_horizontal_), side = length(horizontal - along * sun_horizontal_);
  const double fa = std::clamp(std::atan2(side, along) / kAzimuthStep, 0.0, kAzimuths - 1.0);
  const int i = std::min(static_cast<int>(fe), kElevations - 2), j = std::min(static_cast<int>(fa), kAzimuths - 2);
  const float te = static_cast<float>(fe - i), ta = static_cast<float>(fa - j);
  Spectrum v(0.0f);
  for (int l = 0; l < 2; ++l) {
    const float lw = l == 0 ? 1 - level.above : level.above;
    if (lw == 0.0f) continue;
    const size_t at = ((level.below + static_cast<size_t>(l)) * kElevations + static_cast<size_t>(i)) * kAzimuths +
                      static_cast<size_t>(j);
    v += radiance_[at] * (lw * (1 - te) * (1 - ta));
    v += radiance_[at + 1] * (lw * (1 - te) * ta);
    v += radiance_[at + kAzimuths] * (lw * te * (1 - ta));
    v += radiance_[at + kAzimuths + 1] * (lw * te * ta);
  }
  return v;
}

FogHiddenBehind FogBehindSurfaces::at(const Vec3& point, const Vec3& normal, const Vec3& toward_viewer,
                                      double column_to_viewer_m, double length_in_fog_m, double extent_m) const {
  const double un = dot(toward_viewer, normal);
  const double density = layer_.density(point.z);
  const auto& sigma = layer_.unit_density_extinction_bins();
  const double sigma_ref = sigma[static_cast<size_t>(reference_bin_)];
  const double depth_ref = sigma_ref * column_to_viewer_m;
  if (!(un > 1e-6) || !(density > 0) || !(length_in_fog_m > 0) || !(extent_m > 0) || !(depth_ref < kHiddenDepth))
    return {};
  const Vec3 u_along_plane = toward_viewer - un * normal;
  // The fog taken at the surface's density up to where its optical depth reaches the
  // viewer's.
  const double extinction = sigma_ref * density;
  const double stretch = std::min(length_in_fog_m, column_to_viewer_m / density);
  // A frame about the view.
  const auto [e1, e2] = perpendicular_pair(toward_viewer);
  const FogDiffuseField::LevelWeight level = field_.level_at(point.z);
  double gain = 0;
  Spectrum field(0.0f), field_in_shadow(0.0f);
  for (const Ring& ring : rings_)
    for (size_t i = 0; i < kAround; ++i) {
      const Vec3 omega = ring.cos_angle * toward_viewer + ring.sin_angle * (around_cos_[i] * e1 + around_sin_[i] * e2);
      const double on = dot(omega, normal);
      if (on <= 1e-6) continue;  // light that does not come through the plane
      // ∫_0^S e^(σs)·e^(−σ_tr·s·(u·n)/(ω·n)) ds = (e^(kS) − 1)/k, k = σ − σ_tr·(u·n)/(ω·n)
      // (T(viewer, surface) is the caller's).
      const double a = un / on;
      const double k = extinction * (1 - transport_scale_ * a);
      // As far as the plane point stays on the surface.
      const double sideways = length(u_along_plane - a * (omega - on * normal));
      const double reach = sideways * stretch > extent_m ? extent_m / sideways : stretch;
      const double along = std::abs(k * reach) < 1e-9 ? reach : std::expm1(k * reach) / k;
      const double weight = ring.weight * along;
      gain += weight;
      const Spectrum light = field_radiance(level, omega) * static_cast<float>(weight);
      field += light;
      // In a shadow the field's light from the sun's side is out of the view already.
      if (dot(omega, sunbeam_) <= 0) field_in_shadow += light;
    }
  // Per bin: ωσ·ρ, and T(viewer, surface)'s part beyond kHiddenHeldDepth (the caller
  // multiplies by hidden_light_transmittance).
  Spectrum factor;
  for (int b = 0; b < kSpectralBins; ++b) {
    const double sigma_b = sigma[static_cast<size_t>(b)];
    const double beyond_held = std::exp(std::min(0.0, kHiddenHeldDepth - sigma_b * column_to_viewer_m));
    factor[b] = static_cast<float>(albedo_ * sigma_b * density * beyond_held);
  }
  return {Transmittance(factor * static_cast<float>(gain)), Radiance(factor * field),
          Radiance(factor * field_in_shadow)};
}

}  // namespace skylit
