#include "skylit/render/scene_lamps.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <vector>

#include "skylit/material/reflection.h"
#include "skylit/spectrum/cie.h"

namespace skylit {

SceneLamps::SceneLamps(const std::vector<SceneLight>& lights, const RayTracer& tracer,
                       const std::vector<const TriangleMesh*>& meshes, const FogLayer* fog, double reach_m)
    : tracer_(tracer), fog_(fog), reach_m_(reach_m) {
  if (fog) faces_ = shadow_caster_faces(meshes);
  for (const SceneLight& light : lights) {
    Lamp lamp{&light, std::make_unique<IntensityMap>(light.luminaire), nullptr, nullptr, nullptr, nullptr};
    if (fog) {
      lamp.volumes =
          std::make_unique<PointLightShadowVolumes>(faces_, light.luminaire.position(), light.luminaire.aim(),
                                                    light.luminaire.distribution().max_gamma_deg(), reach_m);
      lamp.all_built = std::make_unique<std::once_flag>();
      lamp.glow = std::make_unique<LampInScatter>(*fog, light.luminaire, light.spectrum_per_candela, lamp.map.get());
    }
    lamps_.push_back(std::move(lamp));
  }
}

Irradiance SceneLamps::irradiance_from(size_t index, const Vec3& point) const {
  const Luminaire& luminaire = lamps_[index].light->luminaire;
  const Vec3 from_lamp = point - luminaire.position();
  const double d2 = dot(from_lamp, from_lamp);
  if (!(d2 > 0)) return Irradiance(0.0f);
  const double candela = luminaire.intensity(from_lamp);
  if (!(candela > 0)) return Irradiance(0.0f);
  Irradiance e(lamps_[index].light->spectrum_per_candela * static_cast<float>(candela / d2));
  if (fog_) e *= Transmittance(fog_->transmittance(fog_->column_between(luminaire.position(), point)));
  return e;  // for the few lamps seen directly: no need to spare the exponentials
}

Irradiance SceneLamps::irradiance_on(const SurfacePoint& point) const {
  Irradiance sum;
  const Vec3 origin = offset_from_surface(point.position, point.normal);
  for (size_t i = 0; i < lamps_.size(); ++i) {
    const Vec3 to_lamp = position(i) - origin;
    const double d = length(to_lamp);
    if (!(d > 0)) continue;
    const double cos_in = dot(point.normal, to_lamp) / d;
    if (!(cos_in > 0) || tracer_.occluded(Ray{origin, to_lamp / d, 0.0, d * (1 - 1e-6)})) continue;
    sum += irradiance_from(i, point.position) * static_cast<float>(cos_in);
  }
  return sum;
}

Radiance SceneLamps::reflected(const SurfacePoint& point, const Material& material, const Vec3& to_viewer) const {
  // Each lamp that sends light to the point at all is a candidate, with the radiance
  // (cd/m², mean over bins; the spectra are one candela per candela) it would reflect
  // toward the viewer unshadowed: its Lambertian part and its glossy highlight, which a
  // sharp lobe can make far larger than the illuminance suggests. Occlusion rays, the
  // costly part, go to the brightest first; once the candidates left could add less
  // than kUntestedShare of the radiance found so far, they are counted as unshadowed:
  // wrong at worst by that share.
  struct Candidate {
    size_t lamp;
    Vec3 l;
    double cos_in, scale;  // scale: candela/d² × the fog's transmittance if grey
    double radiance;
  };
  const bool has_glossy = has_point_light_lobe(material);
  const Reflectance albedo = diffuse_albedo(material, dot(point.normal, to_viewer));
  const double mean_albedo = albedo.mean_value();
  thread_local std::vector<Candidate> candidates;
  candidates.clear();
  for (size_t i = 0; i < lamps_.size(); ++i) {
    const Vec3 to_lamp = position(i) - point.position;
    const double d2 = dot(to_lamp, to_lamp);
    if (!(d2 > 0)) continue;
    const Vec3 l = to_lamp / std::sqrt(d2);
    const double cos_in = dot(point.normal, l);
    if (!(cos_in > 0)) continue;
    const double candela = lamps_[i].map->candela(-to_lamp);
    if (!(candela > 0)) continue;
    double scale = candela / d2;
    if (fog_ && fog_->is_grey())
      scale *= std::exp(-fog_->unit_density_extinction_bins()[0] * fog_->column_between(position(i), point.position));
    const double glossy_weight = has_glossy ? point_light_weight(material, point.normal, l, to_viewer) : 0.0;
    candidates.push_back({i, l, cos_in, scale, scale * (mean_albedo * cos_in / kPi + glossy_weight)});
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& a, const Candidate& b) { return a.radiance > b.radiance; });
  double left = 0;
  for (const Candidate& c : candidates) left += c.radiance;

  Irradiance irradiance;
  Radiance glossy;
  const Vec3 origin = offset_from_surface(point.position, point.normal);
  double found = 0;
  for (const Candidate& c : candidates) {
    const bool test = left >= kUntestedShare * found;
    left -= c.radiance;
    if (test) {
      const Vec3& lamp = position(c.lamp);
      if (tracer_.occluded(Ray{origin, c.l, 0.0, length(lamp - origin) * (1 - 1e-6)})) continue;
      found += c.radiance;
    }
    Irradiance e(lamps_[c.lamp].light->spectrum_per_candela * static_cast<float>(c.scale));
    if (fog_ && !fog_->is_grey())
      e *= Transmittance(fog_->transmittance(fog_->column_between(position(c.lamp), point.position)));
    irradiance += e * static_cast<float>(c.cos_in);
    if (has_glossy) glossy += point_light_reflection(material, point.normal, c.l, to_viewer).reflect(e);
  }
  return lambertian_radiance(albedo, irradiance) + glossy;
}

const PointLightShadowVolumes& SceneLamps::all_volumes(const Lamp& lamp) const {
  if (!std::isfinite(reach_m_)) return *lamp.volumes;
  std::call_once(*lamp.all_built, [&] {
    const Luminaire& luminaire = lamp.light->luminaire;
    lamp.all_volumes = std::make_unique<PointLightShadowVolumes>(faces_, luminaire.position(), luminaire.aim(),
                                                                 luminaire.distribution().max_gamma_deg(),
                                                                 std::numeric_limits<double>::infinity());
  });
  return *lamp.all_volumes;
}

Radiance SceneLamps::in_scattered(const Ray& ray, double distance) const {
  Radiance sum;
  if (!fog_) return sum;
  const RaySpan span = fog_->clip(ray.origin.z, ray.direction.z, 0.0, distance);
  if (span.empty()) return sum;
  // A lamp's glow beyond its reach, unshadowed: an upper bound on what it adds.
  struct Tail {
    size_t lamp;
    double bound_cd_m2;
  };
  thread_local std::vector<Interval> lit, emitting, beyond;  // reused: no allocation per ray
  thread_local std::vector<Spectrum> within;                 // each lamp's glow within its reach
  thread_local std::vector<Tail> tails;
  within.assign(lamps_.size(), Spectrum(0.0f));
  tails.clear();
  Spectrum within_sum(0.0f);
  for (size_t i = 0; i < lamps_.size(); ++i) {
    const Lamp& lamp = lamps_[i];
    // Shadows only where the lamp shines at all (a headlight's cone is narrow).
    lamp.glow->emitting_intervals(ray, span.lo, span.hi, emitting);
    if (emitting.empty()) continue;
    const double begin = emitting.front().begin, end = emitting.back().end;
    // The chord [near, far] of the ray within the reach.
    const Vec3 to_lamp = lamp.light->luminaire.position() - ray.origin;
    const double foot = dot(to_lamp, ray.direction);  // the ray's direction is unit
    const double off2 = std::max(0.0, dot(to_lamp, to_lamp) - foot * foot);
    const double half_chord = std::sqrt(std::max(0.0, reach_m_ * reach_m_ - off2));
    double near = std::max(begin, foot - half_chord), far = std::min(end, foot + half_chord);
    if (off2 >= reach_m_ * reach_m_ || !(near < far)) near = far = end;
    beyond.clear();
    if (begin < near) beyond.push_back({begin, near});
    if (far < end) beyond.push_back({far, end});
    if (near < far) {
      lamp.volumes->lit_intervals(ray, near, far, lit);
      if (!lit.empty()) within[i] = lamp.glow->along(ray, lit, emitting);
      within_sum += within[i];
    }
    if (beyond.empty()) continue;
    const double bound = luminance(lamp.glow->along(ray, beyond, emitting));
    if (bound > 0) tails.push_back({i, bound});
  }
  // Drop the smallest bounds while their sum stays under the share; the rest exactly.
  std::sort(tails.begin(), tails.end(), [](const Tail& a, const Tail& b) { return a.bound_cd_m2 < b.bound_cd_m2; });
  double budget = kDroppedGlowShare * luminance(within_sum);
  for (const Tail& tail : tails) {
    if (tail.bound_cd_m2 <= budget) {
      budget -= tail.bound_cd_m2;
      continue;
    }
    const Lamp& lamp = lamps_[tail.lamp];
    lamp.glow->emitting_intervals(ray, span.lo, span.hi, emitting);
    all_volumes(lamp).lit_intervals(ray, emitting.front().begin, emitting.back().end, lit);
    within[tail.lamp] = lit.empty() ? Spectrum(0.0f) : lamp.glow->along(ray, lit, emitting);
  }
  for (const Spectrum& glow : within) sum += Radiance(glow);
  return sum;
}

}  // namespace skylit
