#include "skylit/render/bands_integrator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "skylit/core/angles.h"
#include "skylit/material/reflection.h"
#include "skylit/spectrum/cie.h"

namespace skylit {

namespace {

// BandsIntegrator::sky_light_bound_lx's part for the obstacles, ρ·E*, per wavelength bin:
// E₀ the most the open sky puts on any of 4,096 planes of all orientations (it changes
// slowly with the plane) and the sun's (or the moon's) normal irradiance above any
// building; ρ the largest diffuse albedo of the materials obstacles are seen with (at
// normal incidence, where a coating reflects least), at most the sky-light integrals' own
// 0.99 (SkyLight::diffuse_irradiance). Per bin, as vegetation reflects half the near
// infrared's light and little of the green's.
double obstacles_bound_lx(const SkyModel& sky, const std::vector<Material>& obstacle_materials) {
  Spectrum open;
  for (const SkyElement& e : fibonacci_sphere(4096)) {
    const Spectrum on_plane = sky.sky_irradiance(e.direction).spectrum();
    for (int k = 0; k < kSpectralBins; ++k) open[k] = std::max(open[k], on_plane[k]);
  }
  constexpr double kAboveAnyBuildingM = 10'000;
  open += sky.direct_sun(kAboveAnyBuildingM).spectrum();
  Spectrum albedo;
  for (const Material& m : obstacle_materials) {
    const Spectrum a = diffuse_albedo(m, 1.0).spectrum();
    for (int k = 0; k < kSpectralBins; ++k) albedo[k] = std::max(albedo[k], std::min(a[k], 0.99f));
  }
  Spectrum sent;
  for (int k = 0; k < kSpectralBins; ++k) sent[k] = albedo[k] * open[k] / (1 - albedo[k]);
  return illuminance(Irradiance(sent));
}

}  // namespace

BandsIntegrator::BandsIntegrator(const PreparedScene& scene)
    : scene_(scene),
      sky_(scene.sky()),
      to_sun_(scene.to_sun()),
      fog_light_(scene.fog() ? scene.fog()->surface_light() : nullptr),
      obstacle_materials_(obstacle_materials(scene.scene().materials)) {
  for (const NamedMaterial& m : scene.scene().materials) broad_lobe_.push_back(is_broad_lobe(m.material));
  // Obstacles of level i are lit by the integrals of level i; the surfaces seen look up level 0.
  const bool own_sky = scene.scene().render.obstacles_own_sky;
  const int levels = own_sky ? static_cast<int>(kObstacleLevelDirections.size()) : 0;
  std::vector<int> lookup_directions{SkyLight::kDefaultDirections};
  for (int level = 0; level < levels; ++level) {
    const int directions = kObstacleLevelDirections[static_cast<size_t>(level)];
    obstacle_sky_lights_.push_back(
        sky_light_looking_up(level + 1, directions, SkyLight::Cells::kCentres, SkyLight::Turning::kPerPoint));
    lookup_directions.push_back(directions);
  }
  lookup_directions.pop_back();
  obstacle_sky_ = std::make_unique<ObstacleSkyLight>(
      scene.scene(), scene.tracer(), lookup_directions,
      [this](int level, const Vec3& point, const Vec3& normal, uint64_t turn) {
        return obstacle_sky_lights_[static_cast<size_t>(level)]->diffuse_irradiance(point, normal, nullptr, turn);
      },
      [this](const Vec3& point, const Vec3& normal) {
        // No ray where the sun cannot shine (facing away, or below the point's horizon).
        return dot(normal, to_sun_) > 0 && sky_.direct_sun(point.z)[kSpectralBins - 1] > 0.0f &&
               !sun_blocked(point, normal);
      },
      [this](const Vec3& point, const Vec3& normal) {
        // Built below, before any patch is asked for.
        const Irradiance rough = reflected_sun_->from_rough(point, normal);
        return reflected_sun_->has_mirrors() ? rough + reflected_sun_->from_mirrors(point, normal) : rough;
      });
  // The image's own integrals take the open sky and what obstacles hide from the same
  // cell means (sky/sky_light.h); the obstacles' patches keep the sky model's table.
  sky_light_ = sky_light_with(SkyLight::kDefaultDirections);
  one_pixel_sky_light_ = sky_light_looking_up(0, kOnePixelDirections, SkyLight::Cells::kMeansAcrossTheAureole);
  if (scene.lamps() && scene.fog()) {  // what the image cache uses where the lamps' glow outshines the sky
    obstacles_bound_lx_ = obstacles_bound_lx(sky_, obstacle_materials_);
    // Past the obstacle levels, the integral lights its obstacles as the point.
    faint_sky_light_ = sky_light_looking_up(obstacle_sky_->levels(), kOnePixelDirections);
  }
  reflected_sun_ = std::make_unique<ReflectedSun>(scene.scene(), scene.tracer(), to_sun_,
                                                  [this](const Vec3& position, const Vec3& normal) {
                                                    return sun_reaching(SurfacePoint{position, normal, 0, 0});
                                                  });
}

std::vector<size_t> BandsIntegrator::obstacle_patch_counts() const {
  return obstacle_sky_ ? obstacle_sky_->patch_counts() : std::vector<size_t>{};
}

std::unique_ptr<SkyLight> BandsIntegrator::sky_light_with(int directions) const {
  return sky_light_looking_up(0, directions, SkyLight::Cells::kMeans);
}

std::unique_ptr<SkyLight> BandsIntegrator::sky_light_looking_up(int level, int directions, SkyLight::Cells cells,
                                                                SkyLight::Turning turning) const {
  const auto obstacle = [this, level](const Ray& ray, const Hit& hit, double element_width_rad) {
    return element_obstacle_light(ray, hit, level, element_width_rad);
  };
  // The points' own integrals (level 0) lose the sunlight the fog in the shadows around a
  // shaded point does not scatter; the obstacles' keep the open field's, a correction
  // of a correction (docs/fog.md).
  const FogShadowedSunlight* shadowed = level == 0 && scene_.fog() ? scene_.fog()->shadowed_sunlight() : nullptr;
  return std::make_unique<SkyLight>(sky_, scene_.tracer(), obstacle, fibonacci_sphere(directions), fog_light_, shadowed,
                                    cells, turning);
}

PrimaryHit BandsIntegrator::first_hit(const Ray& ray) const {
  const std::optional<Hit> hit = scene_.tracer().intersect(ray);
  if (!hit) return {};
  return {hit->mesh_id, scene_.surface_point(ray, *hit)};
}

ViewPath BandsIntegrator::view_path(const Ray& ray, double distance) const {
  ViewPath path;
  path.to_sky = !std::isfinite(distance);
  // The air's stretch from the camera to a distance along the ray: the direction's place
  // in the air's table found at the first (a sky ray that meets neither fog nor a cloud
  // asks for none).
  std::optional<AerialPerspectiveTable::Along> air;
  auto air_to = [&](double d) {
    if (!air) air.emplace(sky_.aerial_perspective_along(ray.direction));
    return air->at(d);
  };
  if (!path.to_sky) path.near = air_to(distance);
  if (!path.to_sky && scene_.shadowed_air()) path.near = scene_.shadowed_air()->in_shadows(path.near, ray, distance);
  if (const FogMedium* fog = scene_.fog()) {
    const MediumStretch to_distance = path.near;
    const FogMedium::Along along = fog->along(ray, distance);
    path.fog_beyond = along.beyond;
    path.fog_whole = along.near.transmittance * along.beyond;
    path.fog_forward_gain = along.forward_gain * path.near.transmittance;  // 0 for the sky
    path.fog_air_transmittance = path.near.transmittance;
    path.fog_open_radiance = along.open_radiance;
    if (along.seen_distance > along.entry_distance) {
      // The air cut where the ray enters the fog and where the fog hides the rest; each
      // later stretch is what the longer one from the camera adds beyond the shorter.
      const MediumStretch to_entry = along.entry_distance > 0 ? air_to(along.entry_distance) : MediumStretch{};
      // (Seen to the surface, as in thin fog: the stretch to it, already looked up.)
      const MediumStretch to_seen =
          !path.to_sky && along.seen_distance == distance ? to_distance : air_to(along.seen_distance);
      path.near = followed_by(to_entry, mixed(remainder_after(to_entry, to_seen), along.near));
      path.air_near = to_seen.in_scattered;
      if (!path.to_sky && along.seen_distance < distance) path.air_beyond = remainder_after(to_seen, to_distance);
    }
  }
  if (const CloudsInSky* clouds = scene_.clouds()) {
    const CloudsInSky::Along along = clouds->along(ray.origin, ray.direction, distance);
    path.clouds = along.stretch;
    if (path.to_sky && std::isfinite(along.entry_distance)) path.air_to_clouds = air_to(along.entry_distance);
  }
  return path;
}

Transmittance BandsIntegrator::clouds_share(const Vec3& point, const Vec3& facing) const {
  return scene_.clouds() ? scene_.clouds()->sky_share(point, facing) : Transmittance(1.0f);
}

Transmittance BandsIntegrator::sky_share(const Vec3& point, const Vec3& facing) const {
  const Transmittance clouds = clouds_share(point, facing);
  return scene_.fog() ? scene_.fog()->sky_light_share(point.z) * clouds : clouds;
}

Transmittance BandsIntegrator::diffuse_share(const SurfacePoint& point) const {
  return sky_light_->lights_in_fog(point.position.z) ? clouds_share(point.position, point.normal)
                                                     : sky_share(point.position, point.normal);
}

bool BandsIntegrator::sun_blocked(const Vec3& position, const Vec3& normal) const {
  return scene_.tracer().occluded(Ray{offset_from_surface(position, normal), to_sun_});
}

Irradiance BandsIntegrator::sun_reaching(const SurfacePoint& point, std::optional<float> sunlit_share) const {
  if (dot(point.normal, to_sun_) <= 0) return Irradiance(0.0f);
  const Irradiance sun = sky_.direct_sun(point.position.z);
  // Transmittance is largest in the red: if the last bin is dark, all are (the sun is
  // below this point's horizon).
  if (sun[kSpectralBins - 1] <= 0.0f) return sun;
  if (sunlit_share ? *sunlit_share <= 0 : sun_blocked(point.position, point.normal)) return Irradiance(0.0f);
  Irradiance reaching = scene_.fog() ? sun * scene_.fog()->sun_beam_transmittance(point.position) : sun;
  if (scene_.clouds())  // the clouds' shadows
    reaching *= static_cast<float>(scene_.clouds()->sun_transmittance(point.position));
  return sunlit_share ? reaching * *sunlit_share : reaching;
}

Radiance BandsIntegrator::lambertian_obstacle_radiance(const Ray& ray, const SurfacePoint& point,
                                                       const Material& material, const Irradiance& sky,
                                                       const Irradiance& sun) const {
  const Irradiance irradiance = sky * diffuse_share(point) + sun * static_cast<float>(dot(point.normal, to_sun_));
  // No emission here: an emitting surface is seen, but does not light others (a sky band
  // element's ray that meets a small lit window would stand for the whole element).
  return lambertian_radiance(diffuse_albedo(material, dot(point.normal, -ray.direction)), irradiance);
}

Irradiance BandsIntegrator::open_sky_irradiance(const SurfacePoint& point) const {
  return sky_light_->lights_in_fog(point.position.z) ? Irradiance(fog_light_->irradiance(point.position, point.normal))
                                                     : sky_.sky_irradiance(point.normal);
}

double BandsIntegrator::sky_light_bound_lx(const SurfacePoint& point) const {
  // Under cloud bases the clouds' share lifts the sky light (cloud_sky_share.h).
  const double clouds = std::max(1.0f, clouds_share(point.position, point.normal).max_value());
  return clouds * (illuminance(open_sky_irradiance(point)) + obstacles_bound_lx_);
}

Irradiance BandsIntegrator::obstacle_sky(const Ray& ray, const Hit& hit, const SurfacePoint& point, int level) const {
  if (const std::optional<ObstacleSkyLight::Patch> own = obstacle_sky_->at(level, ray, hit, resolved_m(ray.origin)))
    return own->sky;
  return open_sky_irradiance(point);
}

ObstacleLight BandsIntegrator::element_obstacle_light(const Ray& ray, const Hit& hit, int level,
                                                      double element_width_rad) const {
  const SurfacePoint point = scene_.untextured_point(ray, hit);
  const Material& body = obstacle_materials_[point.material];
  if (scene_.scene().render.obstacles_own_sky) {
    // Without a patch of its own (past the last level, or too small), the integral that
    // meets the obstacle lights it as itself (SkyLight::diffuse_irradiance).
    // The patch's sunlit share stands for the element's hit; near a shadow edge, the
    // share of the element's own footprint (obstacle_sky_light.h).
    if (const std::optional<ObstacleSkyLight::Patch> own =
            obstacle_sky_->at(level, ray, hit, resolved_m(ray.origin), element_width_rad)) {
      const Radiance reflected_sun =
          lambertian_radiance(diffuse_albedo(body, dot(point.normal, -ray.direction)), own->reflected_sun);
      return obstacle_radiance(ray, point, body, own->sky, level, own->sunlit) + reflected_sun;
    }
    return {obstacle_radiance(ray, point, body, Irradiance(0.0f), level),
            diffuse_albedo(body, dot(point.normal, -ray.direction))};
  }
  return obstacle_radiance(ray, point, body, open_sky_irradiance(point), level);
}

Radiance BandsIntegrator::obstacle_radiance(const Ray& ray, const SurfacePoint& point, const Material& body,
                                            const Irradiance& sky, int level, std::optional<float> sunlit_share) const {
  const Vec3 to_viewer = -ray.direction;
  const Irradiance sun = sun_reaching(point, sunlit_share);
  Radiance radiance = lambertian_obstacle_radiance(ray, point, body, sky, sun);
  // A broad lobe's sunlight toward the ray's origin: the integral whose ray this is
  // gathers it over its directions, as smooth in them as the lobe is wide.
  if (broad_lobe_[point.material])
    radiance += specular_reflection(scene_.material(point.material), point.normal, to_sun_, to_viewer).reflect(sun);
  const Reflectance fresnel = specular_fresnel(scene_.material(point.material), dot(point.normal, to_viewer));
  if (fresnel.is_black()) return radiance;
  const Ray mirrored{offset_from_surface(point.position, point.normal), mirror_direction(point.normal, to_viewer)};
  if (const std::optional<Hit> next = scene_.tracer().intersect(mirrored)) {
    const SurfacePoint seen = scene_.untextured_point(mirrored, *next);
    return radiance + fresnel * lambertian_obstacle_radiance(mirrored, seen, obstacle_materials_[seen.material],
                                                             obstacle_sky(mirrored, *next, seen, level),
                                                             sun_reaching(seen));
  }
  return radiance + fresnel * sky_seen_from(point.position, mirrored.direction);
}

Radiance BandsIntegrator::sky_seen_from(const Vec3& point, const Vec3& direction) const {
  if (sky_light_->lights_in_fog(point.z))
    return Radiance(fog_light_->incoming(point.z, direction)) * clouds_share(point, direction);
  return sky_.sky_radiance_near_ground(direction) * sky_share(point, direction);
}

CachedSkyLight BandsIntegrator::sky_light_at(const SkyLight& diffuse_from, const SkyLight& glossy_from,
                                             const SurfacePoint& point, const Vec3& viewer) const {
  const Material& material = material_of(point);
  const Vec3 to_viewer = normalize(viewer - point.position);
  double obstacle_distance_m = 0;
  const Irradiance diffuse = diffuse_from.diffuse_irradiance(point.position, point.normal, &obstacle_distance_m);
  CachedSkyLight out{diffuse, glossy_from.specular_radiance(point.position, point.normal, to_viewer, material),
                     reflected_sun_->from_rough(point.position, point.normal), obstacle_distance_m};
  if (const FogMedium* fog = scene_.fog(); fog && fog->hides_light_behind_surfaces())
    out.fog_hidden = fog->hidden_behind(Ray{viewer, -to_viewer}, length(point.position - viewer), point.plane(),
                                        surface_extent(point));
  return out;
}

double BandsIntegrator::surface_extent(const SurfacePoint& point) const {
  // Rings of 8 probes at radii doubling from 0.25 m, each looking back at the plane from
  // a height of a tenth of its radius; the surface reaches a ring where half its probes
  // find it there, facing the same way (a wall's foot on the ground still reaches as far
  // as the wall goes up and sideways: the ground hides the rest, as the field's own ground
  // does).
  const Vec3& n = point.plane();
  const auto [t1, t2] = perpendicular_pair(n);
  double reached = 0;
  for (double radius = 0.25; radius <= kLargestSurfaceExtentM; radius *= 2) {
    const double height = 0.1 * radius;
    int found = 0;
    for (int k = 0; k < 8; ++k) {
      const double angle = kPi * k / 4;
      const Ray probe{point.position + height * n + radius * (std::cos(angle) * t1 + std::sin(angle) * t2), -n, 0.0,
                      2 * height};
      const std::optional<Hit> hit = scene_.tracer().intersect(probe);
      if (hit && std::abs(hit->t - height) < 0.25 * height && std::abs(dot(hit->geometric_normal, n)) > 0.95) ++found;
    }
    if (found < 4) break;
    reached = radius;
  }
  return reached;
}

Irradiance BandsIntegrator::reflected_sun(const SurfacePoint& point, const CachedSkyLight& cached) const {
  if (!reflected_sun_->has_mirrors()) return cached.rough_reflected_sun;
  return cached.rough_reflected_sun + reflected_sun_->from_mirrors(point.position, point.normal);
}

Radiance BandsIntegrator::mirrored(const SurfacePoint& point, const Vec3& direction) const {
  const Ray ray{offset_from_surface(point.position, point.normal), direction};
  if (const std::optional<Hit> hit = scene_.tracer().intersect(ray)) {
    // Seen in the mirror by the camera: with its textures.
    const SurfacePoint seen = scene_.surface_point(ray, *hit);
    return obstacle_radiance(ray, seen, scene_.material_at(seen).get(), obstacle_sky(ray, *hit, seen, 0), 0);
  }
  // In a fog whose multiple scattering lights the point, the fog's light and the sun
  // through it (the paper's mode mirrors the clear sky).
  if (sky_light_->lights_in_fog(point.position.z))
    return sky_seen_from(point.position, direction) +
           sky_.sun_radiance(direction) * scene_.fog()->sun_transmittance(point.position);
  return sky_.sky_radiance_near_ground(direction) + sky_.sun_radiance(direction);
}

Irradiance BandsIntegrator::irradiance(const SurfacePoint& point, const CachedSkyLight& sky_light) const {
  Irradiance e = sky_light.diffuse_irradiance * diffuse_share(point) +
                 sun_reaching(point) * static_cast<float>(dot(point.normal, to_sun_)) + reflected_sun(point, sky_light);
  if (const SceneLamps* lamps = scene_.lamps()) e += lamps->irradiance_on(point);
  return e;
}

Radiance BandsIntegrator::shade(const Ray& ray, const SurfacePoint& point, const CachedSkyLight& sky_light,
                                LeavingParts* parts) const {
  const PointMaterial point_material = scene_.material_at(point);
  const Material& material = point_material.get();
  const Vec3 to_viewer = -ray.direction;
  const Irradiance sun = sun_reaching(point);
  // Sky light, dimmed by any fog above the point (unless the fog's own light is in it).
  const Transmittance share = diffuse_share(point);
  // Lambertian part: sky and sun irradiance, and the sun reflected by facades.
  const Irradiance irradiance = sky_light.diffuse_irradiance * share +
                                sun * static_cast<float>(dot(point.normal, to_sun_)) + reflected_sun(point, sky_light);
  Radiance radiance = lambertian_radiance(diffuse_albedo(material, dot(point.normal, to_viewer)), irradiance);
  // Glossy part: the sky's (cached) and the sun's highlight.
  radiance += sky_light.specular_radiance * share;
  // What it leaves about alike toward every direction (FogHiddenBehind): not the sun's
  // highlight nor what the mirror shows, which leave toward the camera alone.
  if (parts) {
    parts->alike_everywhere = point.emissive ? radiance + emitted_radiance(point.emission_cd_m2) : radiance;
    parts->sun_reaches = !sun.is_black();
  }
  if (has_point_light_lobe(material))
    radiance += point_light_reflection(material, point.normal, to_sun_, to_viewer).reflect(sun);
  if (const SceneLamps* lamps = scene_.lamps()) radiance += lamps->reflected(point, material, to_viewer);
  // Mirror part (window glass): what lies in the mirror direction.
  if (const std::optional<Reflectance> mirror = mirror_reflectance(material, point.normal, to_viewer))
    radiance += *mirror * mirrored(point, mirror_direction(point.normal, to_viewer));
  // Light the surface gives off itself (a lit window, a sign).
  if (point.emissive) radiance += emitted_radiance(point.emission_cd_m2);
  return radiance;
}

Radiance BandsIntegrator::lamp_glow(const Ray& ray, const PrimaryHit& hit, const SampleContext& context) const {
  if (!scene_.lamps() || !scene_.fog()) return Radiance(0.0f);
  if (context.caches.glow)
    return Radiance(context.caches.glow->at(context.image_x, context.image_y, ray, ViewHit{hit.mesh, hit.distance()}));
  return scene_.lamps()->in_scattered(ray, hit.distance());
}

Radiance BandsIntegrator::radiance(const Ray& ray, const PrimaryHit& hit, const SampleContext& context) const {
  const Radiance glow = lamp_glow(ray, hit, context);
  const double distance = hit.distance();
  auto path = [&]() -> ViewPath {
    if (context.pixel_path) return context.pixel_path->for_distance(distance, [&] { return view_path(ray, distance); });
    return view_path(ray, distance);
  };
  if (hit.is_sky())
    return glow + path().seen_from_camera(sky_.sky_radiance(ray.direction) + sky_.sun_radiance(ray.direction));
  std::optional<CachedSkyLight> sky_light;
  if (context.caches.sky_light) {
    sky_light = context.caches.sky_light->interpolate(context.image_x, context.image_y, hit.point);
    if (!sky_light && context.slivers) {
      if (const CachedSkyLight* shared = context.slivers->find(context.image_x, context.image_y, hit.point))
        sky_light = *shared;
    }
    if (!sky_light) {
      sky_light = sky_light_for_one_pixel(hit.point, ray.origin);
      if (context.slivers) context.slivers->add(context.image_x, context.image_y, hit.point, *sky_light);
    }
  } else {
    sky_light = sky_light_at(hit.point, ray.origin);
  }
  LeavingParts parts;
  const Radiance leaving = shade(ray, hit.point, *sky_light, &parts);
  if (sky_light->fog_hidden.gain.is_black()) return glow + path().seen_from_camera(leaving);
  // The fog just before a surface the sun does not reach lies in a shadow: the view has
  // lost the field's sun-side light there (the surface's own sun test, not the shadow
  // volumes along the view, which flicker where a face lies along the sunbeam).
  const bool fog_in_shadow = scene_.fog()->takes_sun_side_out_in_shadows() && !parts.sun_reaches;
  return glow + path().seen_from_camera(leaving, {sky_light->fog_hidden, parts.alike_everywhere, fog_in_shadow});
}

}  // namespace skylit
