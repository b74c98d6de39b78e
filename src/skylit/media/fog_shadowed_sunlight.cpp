#include "skylit/media/fog_shadowed_sunlight.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "skylit/geometry/intervals.h"

namespace skylit {

namespace {
constexpr double kFarM = 50e3;  // a level ray inside the layer: far enough to be opaque
// Largest change per step of the sun's scaled depth and of the altitude (as a share of
// the density's vertical scale), up to kMaxSteps a part: the sunlight is taken at each
// step's middle; the fog's column along the step, and so the dimming toward the point,
// is exact.
constexpr double kSunDepthPitch = 0.25, kAltitudePitch = 0.25;
constexpr int kMaxSteps = 32;
}  // namespace

FogShadowedSunlight::FogShadowedSunlight(const FogLayer& layer, const FogDiffuseField& field,
                                         const SunShadowVolumes& shadows, const RayTracer& tracer, const Vec3& to_sun,
                                         const Spectrum& sun_above_fog, std::vector<SkyElement> directions)
    : layer_(layer),
      field_(field),
      shadows_(shadows),
      tracer_(tracer),
      to_sun_(normalize(to_sun)),
      sun_above_fog_(sun_above_fog),
      directions_(std::move(directions)),
      sun_lights_fog_(to_sun_.z > 0 && !sun_above_fog_.is_black()) {
  const auto& sigma = layer_.unit_density_extinction_bins();
  sigma_max_ = *std::max_element(sigma.begin(), sigma.end());
  const double eta = std::abs(layer_.inverse_scale_height_per_m());
  const double thickness = layer_.top_m() - layer_.bottom_m();
  vertical_scale_ = eta > 0 ? std::min(thickness, 1.0 / eta) : thickness;
  densest_ = std::max(layer_.density(layer_.bottom_m()), layer_.density(layer_.top_m()));
}

bool FogShadowedSunlight::shaded(const Vec3& point, const Vec3& normal) const {
  if (!sun_lights_fog_) return false;  // no beam anywhere: nothing of it to miss
  return dot(normal, to_sun_) <= 0 || tracer_.occluded(Ray{offset_from_surface(point, normal), to_sun_});
}

Spectrum FogShadowedSunlight::missing_radiance(const Vec3& point, const Vec3& direction, double distance) const {
  Spectrum out(0.0f);
  if (!sun_lights_fog_) return out;
  const RaySpan inside = layer_.clip(point.z, direction.z, 0.0, std::min(distance, kFarM));
  if (inside.empty()) return out;
  thread_local std::vector<Interval> parts;
  shadows_.sunlit_intervals(Ray{point, direction}, inside.lo, inside.hi, parts);
  complement_of_union(inside.lo, inside.hi, 0.0, parts);  // now the parts in shadow
  if (parts.empty()) return out;

  // The light travels along −direction, the sunbeam along −to_sun.
  const double phase = (1.0 - field_.forward_fraction()) * field_.smooth_phase(dot(direction, to_sun_));
  const double scale = field_.sun_depth_scale(), albedo = layer_.single_scattering_albedo();
  if (!(phase > 0) || !(albedo > 0)) return out;
  const auto& sigma = layer_.unit_density_extinction_bins();
  const int bins = layer_.is_grey() ? 1 : kSpectralBins;  // grey: one bin stands for all

  std::array<double, kSpectralBins> sum{};
  for (const Interval& part : parts) {
    const double rise = std::abs(direction.z) * (part.end - part.begin);
    const double steps_needed = std::max(rise / (kAltitudePitch * vertical_scale_),
                                         scale * sigma_max_ * densest_ * rise / (kSunDepthPitch * to_sun_.z));
    const int steps = !(steps_needed < kMaxSteps) ? kMaxSteps : std::max(1, static_cast<int>(std::ceil(steps_needed)));
    const double ds = (part.end - part.begin) / steps;
    double column_before = layer_.column(point.z, direction.z, 0.0, part.begin);
    for (int i = 0; i < steps; ++i) {
      const double s0 = part.begin + i * ds, s1 = s0 + ds;
      const double z = point.z + direction.z * 0.5 * (s0 + s1);
      const double step_column = layer_.column(point.z, direction.z, s0, s1);
      const double sun_column = layer_.sun_column(z, to_sun_.z);
      for (int k = 0; k < bins; ++k) {
        const double sg = scale * sigma[static_cast<size_t>(k)];
        // ∫ σρ e^(−τ'(s)) ds over the step, exactly: e^(−τ'(s0))·(1 − e^(−Δτ'))/scale.
        sum[static_cast<size_t>(k)] += std::exp(-sg * (column_before + sun_column)) * -std::expm1(-sg * step_column);
      }
      column_before += step_column;
    }
  }
  for (int k = 0; k < kSpectralBins; ++k)
    out[k] =
        static_cast<float>(albedo * phase / scale * sum[static_cast<size_t>(bins == 1 ? 0 : k)] * sun_above_fog_[k]);
  return out;
}

Spectrum FogShadowedSunlight::missing_irradiance(const Vec3& point, const Vec3& normal) const {
  Spectrum out(0.0f);
  if (!sun_lights_fog_) return out;
  const Vec3 origin = offset_from_surface(point, normal);
  thread_local std::vector<Ray> rays;
  thread_local std::vector<std::optional<Hit>> hits;
  thread_local std::vector<double> weights;  // cos·dω
  rays.clear();
  weights.clear();
  for (const SkyElement& e : directions_) {
    const double c = dot(normal, e.direction);
    if (c <= 0) continue;
    rays.push_back(Ray{origin, e.direction});
    weights.push_back(c * e.solid_angle);
  }
  tracer_.intersect(rays, hits);
  for (size_t i = 0; i < rays.size(); ++i) {
    const double distance = hits[i] ? hits[i]->t : std::numeric_limits<double>::infinity();
    out += missing_radiance(origin, rays[i].direction, distance) * static_cast<float>(weights[i]);
  }
  return out;
}

}  // namespace skylit
