#include "skylit/media/fog_surface_light.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

namespace skylit {

namespace {

constexpr int kModes = FogDiffuseField::kModes;

double normal_elevation(int row) {
  return kPi * (static_cast<double>(row) / (FogSurfaceLight::kNormalElevations - 1) - 0.5);
}

// K_m = ∫ max(0, a·cos ψ + b)·cos(mψ) dψ over the circle (a ≥ 0), for m = 0 … kModes−1.
std::array<double, kModes> clamped_cosine_terms(double a, double b) {
  std::array<double, kModes> k{};
  if (b >= a) {  // the whole circle is lit
    k[0] = 2 * kPi * b;
    k[1] = kPi * a;
    return k;
  }
  if (b <= -a) return k;
  const double psi = std::acos(-b / a);  // lit for |ψ| < psi
  const double s = std::sin(psi);
  k[0] = 2 * (a * s + b * psi);
  k[1] = a * (psi + s * std::cos(psi)) + 2 * b * s;
  for (int m = 2; m < kModes; ++m)
    k[static_cast<size_t>(m)] =
        a * (std::sin((m - 1) * psi) / (m - 1) + std::sin((m + 1) * psi) / (m + 1)) + 2 * b * std::sin(m * psi) / m;
  return k;
}

}  // namespace

FogSurfaceLight::FogSurfaceLight(const FogSkyLight& sky_light)
    : sky_light_(sky_light), field_(*sky_light.diffuse_field()), depth_scale_(sky_light.sun_depth_scale()) {
  // The kernel at each normal elevation and incident elevation, with the quadrature's
  // weight dμ = cos e·de folded in. The incident light arrives from elevation e and so
  // travels with upward cosine −sin e.
  std::vector<std::array<double, kModes>> kernel(static_cast<size_t>(kNormalElevations * kIncidentElevations));
  std::vector<double> travel_up(kIncidentElevations);
  const double de = kPi / kIncidentElevations;
  for (int i = 0; i < kIncidentElevations; ++i) {
    const double e = -0.5 * kPi + (i + 0.5) * de;
    travel_up[static_cast<size_t>(i)] = -std::sin(e);
    for (int j = 0; j < kNormalElevations; ++j) {
      const double en = normal_elevation(j);
      std::array<double, kModes> k = clamped_cosine_terms(std::cos(en) * std::cos(e), std::sin(en) * std::sin(e));
      for (double& v : k) v *= std::cos(e) * de;
      kernel[static_cast<size_t>(j * kIncidentElevations + i)] = k;
    }
  }
  const size_t levels = field_.level_count();
  irradiance_.assign(levels * kNormalElevations * kModes, Spectrum(0.0f));
  tbb::parallel_for(size_t{0}, levels, [&](size_t level) {
    std::vector<Terms> incident(kIncidentElevations);
    for (int i = 0; i < kIncidentElevations; ++i)
      field_.radiance_terms_at_level(level, travel_up[static_cast<size_t>(i)], incident[static_cast<size_t>(i)]);
    for (int j = 0; j < kNormalElevations; ++j) {
      Spectrum* out = &irradiance_[(level * kNormalElevations + static_cast<size_t>(j)) * kModes];
      for (int i = 0; i < kIncidentElevations; ++i) {
        const std::array<double, kModes>& k = kernel[static_cast<size_t>(j * kIncidentElevations + i)];
        const Terms& r = incident[static_cast<size_t>(i)];
        for (int m = 0; m < kModes; ++m)
          out[m] += r[static_cast<size_t>(m)] * static_cast<float>(k[static_cast<size_t>(m)]);
      }
    }
  });
}

Spectrum FogSurfaceLight::irradiance(const Vec3& point, const Vec3& normal) const {
  const double elevation = std::asin(std::clamp(normal.z, -1.0, 1.0));
  const double row = std::clamp((elevation / kPi + 0.5) * (kNormalElevations - 1), 0.0, kNormalElevations - 1.0);
  const int j = std::min(static_cast<int>(row), kNormalElevations - 2);
  const float fj = static_cast<float>(row - j);
  const FogDiffuseField::LevelWeight level = field_.level_at(point.z);
  const FogDiffuseField::AzimuthTerms cosines = FogDiffuseField::azimuth_terms(sky_light_.relative_azimuth(normal));
  Spectrum e(0.0f);
  const std::array<std::pair<const Spectrum*, float>, 4> corners{
      {{irradiance_terms(level.below, j), (1 - fj) * (1 - level.above)},
       {irradiance_terms(level.below, j + 1), fj * (1 - level.above)},
       {irradiance_terms(level.below + 1, j), (1 - fj) * level.above},
       {irradiance_terms(level.below + 1, j + 1), fj * level.above}}};
  for (const auto& [terms, weight] : corners) add_azimuth_weighted(e, terms, kModes, cosines.data(), weight);
  for (int b = 0; b < kSpectralBins; ++b) e[b] = std::max(e[b], 0.0f);
  return e;
}

Spectrum FogSurfaceLight::incoming_at_level(size_t level, const Vec3& from,
                                            const FogDiffuseField::AzimuthTerms& cosines) const {
  Terms terms;
  field_.radiance_terms_at_level(level, -from.z, terms);
  Spectrum l(0.0f);
  add_azimuth_weighted(l, terms.data(), kModes, cosines.data(), 1.0f);
  for (int b = 0; b < kSpectralBins; ++b) l[b] = std::max(l[b], 0.0f);  // a truncated series may dip below 0
  return l;
}

Spectrum FogSurfaceLight::incoming(double z, const Vec3& from) const {
  // Arriving from `from` is travelling toward −from: the field's radiance that way.
  return field_.radiance(z, -from.z, sky_light_.relative_azimuth(from));
}

Spectrum FogSurfaceLight::transmittance(const Vec3& point, const Vec3& direction, double distance) const {
  const FogLayer& layer = sky_light_.layer();
  return layer.transmittance(depth_scale_ * layer.column(point.z, direction.z, 0.0, distance));
}

FogSurfaceLight::Directions::Directions(const FogSurfaceLight& light, const std::vector<Vec3>& directions)
    : light_(light), count_(directions.size()) {
  const size_t levels = light.field_.level_count();
  table_.assign(levels * count_, Spectrum(0.0f));
  tbb::parallel_for(size_t{0}, count_, [&](size_t i) {
    const FogDiffuseField::AzimuthTerms cosines =
        FogDiffuseField::azimuth_terms(light.sky_light_.relative_azimuth(directions[i]));
    for (size_t level = 0; level < levels; ++level)
      table_[level * count_ + i] = light.incoming_at_level(level, directions[i], cosines);
  });
}

FogSurfaceLight::Directions::At FogSurfaceLight::Directions::at(double z) const { return light_.field_.level_at(z); }

}  // namespace skylit
