#include "skylit/render/scene_lamps.h"

#include <cmath>

#include "skylit/material/reflection.h"

namespace skylit {

SceneLamps::SceneLamps(const std::vector<SceneLight>& lights, const RayTracer& tracer,
                       const std::vector<const TriangleMesh*>& meshes, const FogLayer* fog)
    : tracer_(tracer), fog_(fog) {
  for (const SceneLight& light : lights) {
    Lamp lamp{&light, std::make_unique<IntensityMap>(light.luminaire), nullptr, nullptr};
    if (fog) {
      lamp.volumes = std::make_unique<ShadowVolumes>(ShadowVolumes::for_point_light(
          meshes, light.luminaire.position(), light.luminaire.aim(), light.luminaire.distribution().max_gamma_deg()));
      lamp.glow = std::make_unique<LampInScatter>(*fog, light.luminaire, light.spectrum_per_candela, lamp.map.get());
    }
    lamps_.push_back(std::move(lamp));
  }
}

Spectrum SceneLamps::irradiance_from(size_t index, const Vec3& point) const {
  const Luminaire& luminaire = lamps_[index].light->luminaire;
  const Vec3 from_lamp = point - luminaire.position();
  const double d2 = dot(from_lamp, from_lamp);
  if (!(d2 > 0)) return Spectrum(0.0f);
  const double candela = luminaire.intensity(from_lamp);
  if (!(candela > 0)) return Spectrum(0.0f);
  Spectrum e = lamps_[index].light->spectrum_per_candela * static_cast<float>(candela / d2);
  if (fog_) e *= fog_->transmittance(fog_->column_between(luminaire.position(), point));
  return e;  // for the few lamps seen directly: no need to spare the exponentials
}

Spectrum SceneLamps::reflected(const SurfacePoint& point, const Material& material, const Vec3& to_viewer,
                               uint64_t& rays) const {
  // The Lambertian part sums the lamps' irradiance first (scalars times each lamp's
  // spectrum) and multiplies by the albedo once; the occlusion ray, the costly part,
  // is traced only for lamps that send light to the point at all.
  Spectrum irradiance, glossy;
  const bool has_glossy = has_specular(material);
  const Vec3 origin = offset_from_surface(point.position, point.normal);
  for (size_t i = 0; i < lamps_.size(); ++i) {
    const Luminaire& luminaire = lamps_[i].light->luminaire;
    const Vec3 to_lamp = luminaire.position() - point.position;
    const double d2 = dot(to_lamp, to_lamp);
    if (!(d2 > 0)) continue;
    const double distance = std::sqrt(d2);
    const Vec3 l = to_lamp / distance;
    const double cos_in = dot(point.normal, l);
    if (!(cos_in > 0)) continue;
    const double candela = lamps_[i].map->candela(-to_lamp);
    if (!(candela > 0)) continue;
    ++rays;
    if (tracer_.occluded(Ray{origin, l, 0.0, length(luminaire.position() - origin) * (1 - 1e-6)})) continue;
    double scale = candela / d2;
    Spectrum e = lamps_[i].light->spectrum_per_candela;
    if (fog_) {
      const double column = fog_->column_between(luminaire.position(), point.position);
      if (fog_->is_grey()) scale *= std::exp(-fog_->unit_density_extinction_bins()[0] * column);
      else e *= fog_->transmittance(column);
    }
    e *= static_cast<float>(scale);
    irradiance += e * static_cast<float>(cos_in);
    if (has_glossy) glossy += specular_reflection(material, point.normal, l, to_viewer) * e;
  }
  return diffuse_albedo(material, dot(point.normal, to_viewer)) * irradiance * static_cast<float>(1.0 / kPi) + glossy;
}

Spectrum SceneLamps::in_scattered(const Ray& ray, double distance) const {
  Spectrum sum;
  if (!fog_) return sum;
  const RaySpan span = fog_->clip(ray.origin.z, ray.direction.z, 0.0, distance);
  if (span.empty()) return sum;
  thread_local std::vector<Interval> lit, emitting;  // reused: no allocation per ray
  for (const Lamp& lamp : lamps_) {
    // Shadows only where the lamp shines at all (a headlight's cone is narrow).
    lamp.glow->emitting_intervals(ray, span.lo, span.hi, emitting);
    if (emitting.empty()) continue;
    lamp.volumes->sunlit_intervals(ray, emitting.front().begin, emitting.back().end, lit);
    if (!lit.empty()) sum += lamp.glow->along(ray, lit);
  }
  return sum;
}

}  // namespace skylit
