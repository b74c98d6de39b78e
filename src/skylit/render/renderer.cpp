#include "skylit/render/renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "skylit/material/reflection.h"
#include "skylit/render/lamp_glow_image.h"
#include "skylit/spectrum/cie.h"

namespace skylit {

namespace {

constexpr int kTileSize = 32;
// Neighbouring pixel centres that differ by more than this fraction (in X, Y or Z) mark
// an edge, where the pixel gets its full grid of samples.
constexpr double kEdgeContrast = 0.05;

}  // namespace

Renderer::Renderer(const Scene& scene)
    : scene_(scene),
      to_sun_(direction_from_altitude_azimuth(scene.sun.altitude_deg, scene.sun.azimuth_deg)),
      atmosphere_(scene.atmosphere),
      sky_(atmosphere_, to_sun_, scene.camera.position.z) {
  for (const SceneObject& object : scene.objects) {
    tracer_.add_mesh(object.mesh);
    material_of_mesh_.push_back(object.material_index);
  }
  tracer_.commit();
  sky_light_ = std::make_unique<SkyLight>(
      sky_, tracer_, [this](const Ray& ray, const Hit& hit, uint64_t& rays) { return obstacle_radiance(ray, hit, rays); });
  if (!scene.clouds.empty() || scene.cloud_layer) {
    std::vector<Cloud> clouds(scene.clouds.begin(), scene.clouds.end());
    if (scene.cloud_layer) {
      const CloudLayer generated = CloudLayer::generate(*scene.cloud_layer);
      clouds.insert(clouds.end(), generated.clouds().begin(), generated.clouds().end());
    }
    double altitude = 0;
    for (const Cloud& c : clouds) altitude += c.shape().altitude;
    altitude /= static_cast<double>(std::max<size_t>(1, clouds.size()));
    clouds_ = std::make_unique<CloudLayer>(std::move(clouds));
    clouds_->prepare_sun(to_sun_);
    // Eq. 15: the sun at the clouds' altitude; the ambient light of multiple scattering
    // as the radiance of a Lambertian of albedo 0.25 under the sun and the sky there
    // (docs/clouds.md), so that clouds stay lit by the sky after sunset.
    cloud_light_.to_sun = to_sun_;
    cloud_light_.sun = sky_.direct_sun(altitude);
    cloud_light_.ambient = default_cloud_ambient(cloud_light_.sun, to_sun_) +
                           sky_.sky_irradiance({0, 0, 1}) * static_cast<float>(kDefaultCloudAmbientFraction / kPi);
    cloud_sky_share_ = measure_cloud_sky_share();
  }
  // The scene's meshes, for the fog's and the lamps' shadow volumes.
  std::vector<const TriangleMesh*> meshes;
  for (const SceneObject& object : scene.objects) meshes.push_back(&object.mesh);
  if (scene.fog) fog_ = std::make_unique<FogMedium>(*scene.fog, meshes, sky_, scene.camera.position);
  if (!scene.lights.empty()) {
    lamps_ = std::make_unique<SceneLamps>(scene.lights, tracer_, meshes, fog_ ? &fog_->layer() : nullptr);
  }
}

Spectrum Renderer::measure_cloud_sky_share() const {
  // The sky over a horizontal surface at the camera, with and without the clouds in
  // front of it, by a cosine-weighted midpoint rule (16 × 32 directions).
  Spectrum clear, cloudy;
  const Vec3 origin{scene_.camera.position.x, scene_.camera.position.y, 0.0};
  for (int i = 0; i < 16; ++i) {
    const double mu = std::sqrt((i + 0.5) / 16), sine = std::sqrt(1 - mu * mu);
    for (int j = 0; j < 32; ++j) {
      const double phi = 2 * kPi * (j + 0.5) / 32;
      const Vec3 dir{sine * std::cos(phi), sine * std::sin(phi), mu};
      const Spectrum sky = sky_.sky_radiance_near_ground(dir);
      const CloudScattering c = clouds_->scatter(origin, dir, 0.0, 1e7, cloud_light_);
      clear += sky;
      cloudy += sky * static_cast<float>(c.transmittance) + c.in_scattered;
    }
  }
  Spectrum share;
  for (int k = 0; k < kSpectralBins; ++k) share[k] = clear[k] > 0 ? std::min(2.0f, cloudy[k] / clear[k]) : 1.0f;
  return share;
}

Renderer::Between Renderer::between(const Ray& ray, double distance) const {
  const ScatteredLight no_air{Spectrum(0.0f), Spectrum(1.0f)};
  Between b{std::isfinite(distance) ? sky_.aerial_perspective(ray.direction, distance) : no_air,
            {Spectrum(1.0f), Spectrum(0.0f)},
            {Spectrum(0.0f), 1.0},
            no_air};
  if (fog_) b.fog = fog_->along(ray, distance);
  if (clouds_) {
    b.clouds = clouds_->scatter(ray.origin, ray.direction, 0.0, std::min(distance, 1e7), cloud_light_);
    if (!std::isfinite(distance) && std::isfinite(b.clouds.distance))
      b.air_to_clouds = sky_.aerial_perspective(ray.direction, b.clouds.distance);
  }
  return b;
}

Spectrum Renderer::seen_through(const Spectrum& radiance, const Between& between, bool sky) {
  // Clouds are farthest from the camera, the fog nearest; the air's long path is over
  // them all: clouds, then fog, then (for surfaces) the air.
  const float t_clouds = static_cast<float>(between.clouds.transmittance);
  Spectrum through_clouds = radiance * t_clouds + between.clouds.in_scattered;
  if (sky) {
    // The sky's radiance S holds the air along the whole ray: S = A + T·S_beyond, with
    // A and T the air's in-scatter and transmittance up to the clouds. The clouds
    // replace what lies beyond them and are seen through that air:
    // T·(cloud + t·S_beyond) + A = t·S + (1 − t)·A + T·cloud.
    const ScatteredLight& air = between.air_to_clouds;
    through_clouds = radiance * t_clouds + air.radiance * (1.0f - t_clouds) +
                     between.clouds.in_scattered * air.transmittance;
  }
  const Spectrum through_fog = through_clouds * between.fog.transmittance + between.fog.in_scattered;
  if (sky) return through_fog;
  return through_fog * between.air.transmittance + between.air.radiance;
}

SurfacePoint Renderer::surface_point(const Ray& ray, const Hit& hit) const {
  // Two-sided surfaces: use the side facing the ray's origin.
  Vec3 normal = hit.geometric_normal;
  if (dot(normal, ray.direction) > 0) normal = -normal;
  return {ray.origin + hit.t * ray.direction, normal, hit.t, material_of_mesh_[hit.mesh_id]};
}

Spectrum Renderer::sun_reaching(const SurfacePoint& point, uint64_t& rays) const {
  if (dot(point.normal, to_sun_) <= 0) return Spectrum(0.0f);
  const Spectrum sun = sky_.direct_sun(point.position.z);
  // Transmittance is largest in the red: if the last bin is dark, all are (the sun is
  // below this point's horizon).
  if (sun[kSpectralBins - 1] <= 0.0f) return sun;
  ++rays;
  if (tracer_.occluded(Ray{offset_from_surface(point.position, point.normal), to_sun_})) return Spectrum(0.0f);
  Spectrum reaching = fog_ ? sun * fog_->sun_transmittance(point.position) : sun;
  if (clouds_) reaching *= static_cast<float>(clouds_->sun_transmittance(point.position, to_sun_));  // cloud shadows
  return reaching;
}

Spectrum Renderer::obstacle_radiance(const Ray& ray, const Hit& hit, uint64_t& rays) const {
  const SurfacePoint point = surface_point(ray, hit);
  const Spectrum irradiance = sky_.sky_irradiance(point.normal) * sky_share(point.position.z) +
                              sun_reaching(point, rays) * static_cast<float>(dot(point.normal, to_sun_));
  const Spectrum albedo = diffuse_albedo(material_of(point), -dot(point.normal, ray.direction));
  return albedo * irradiance * static_cast<float>(1.0 / kPi);
}

CachedSkyLight Renderer::sky_light_at(const SurfacePoint& point, const Vec3& to_viewer, uint64_t& rays) const {
  const Material& material = material_of(point);
  return {sky_light_->diffuse_irradiance(point.position, point.normal, rays),
          sky_light_->specular_radiance(point.position, point.normal, to_viewer, material, rays)};
}

Spectrum Renderer::mirrored(const SurfacePoint& point, const Vec3& direction, uint64_t& rays) const {
  const Ray ray{offset_from_surface(point.position, point.normal), direction};
  ++rays;
  if (const std::optional<Hit> hit = tracer_.intersect(ray)) return obstacle_radiance(ray, *hit, rays);
  return sky_.sky_radiance_near_ground(direction) + sky_.sun_radiance(direction);
}

Spectrum Renderer::shade(const Ray& ray, const SurfacePoint& point, const CachedSkyLight& sky_light,
                         uint64_t& rays) const {
  const Material& material = material_of(point);
  const Vec3 to_viewer = -ray.direction;
  const Spectrum sun = sun_reaching(point, rays);
  // Sky light, dimmed by any fog above the point.
  const Spectrum share = sky_share(point.position.z);
  // Lambertian part: sky and sun irradiance.
  const Spectrum irradiance =
      sky_light.diffuse_irradiance * share + sun * static_cast<float>(dot(point.normal, to_sun_));
  Spectrum radiance = diffuse_albedo(material, dot(point.normal, to_viewer)) * irradiance * static_cast<float>(1.0 / kPi);
  // Glossy part: the sky's (cached) and the sun's highlight.
  radiance += sky_light.specular_radiance * share;
  if (has_specular(material))
    radiance += specular_reflection(material, point.normal, to_sun_, to_viewer) * sun;
  if (lamps_) radiance += lamps_->reflected(point, material, to_viewer, rays);
  // Mirror part (window glass): what lies in the mirror direction.
  if (const std::optional<Spectrum> mirror = mirror_reflectance(material, point.normal, to_viewer))
    radiance += *mirror * mirrored(point, mirror_direction(point.normal, to_viewer), rays);
  return radiance;
}

Spectrum Renderer::radiance(const Ray& ray, uint64_t& rays) const {
  ++rays;
  const std::optional<Hit> hit = tracer_.intersect(ray);
  const double distance = hit ? hit->t : std::numeric_limits<double>::infinity();
  // The lamps' glow exactly (render() takes it from a LampGlowImage instead).
  const Spectrum glow = lamps_ && fog_ ? lamps_->in_scattered(ray, distance) : Spectrum(0.0f);
  if (!hit)
    return glow + seen_through(sky_.sky_radiance(ray.direction) + sky_.sun_radiance(ray.direction),
                               between(ray, distance), true);
  const SurfacePoint point = surface_point(ray, *hit);
  return glow + seen_through(shade(ray, point, sky_light_at(point, -ray.direction, rays), rays), between(ray, distance), false);
}

XyzImage Renderer::render(const RenderOptions& options) const {
  const RenderSettings& settings = scene_.render;
  const int width = settings.width, height = settings.height, n = settings.samples_per_axis;
  const PinholeCamera camera(scene_.camera, width, height);
  XyzImage image(width, height);
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);

  // The sky light at a sparse grid of pixel centres first.
  std::atomic<uint64_t> cache_rays{0};
  std::unique_ptr<SurfaceCache> cache;
  arena.execute([&] {
    cache = std::make_unique<SurfaceCache>(
        width, height,
        [&](int px, int py) -> std::optional<SurfacePoint> {
          const Ray ray = camera.ray_through(px + 0.5, py + 0.5);
          const std::optional<Hit> hit = tracer_.intersect(ray);
          cache_rays.fetch_add(1, std::memory_order_relaxed);
          if (!hit) return std::nullopt;
          return surface_point(ray, *hit);
        },
        [&](const SurfacePoint& p) {
          uint64_t rays = 0;
          const CachedSkyLight light = sky_light_at(p, normalize(scene_.camera.position - p.position), rays);
          cache_rays.fetch_add(rays, std::memory_order_relaxed);
          return light;
        });
  });
  rays_traced_.fetch_add(cache_rays.load(), std::memory_order_relaxed);

  const int tiles_x = (width + kTileSize - 1) / kTileSize;
  const int tiles_y = (height + kTileSize - 1) / kTileSize;
  const int tile_count = tiles_x * tiles_y;
  std::mutex progress_mutex;
  int tiles_done = 0;

  // What lies between camera and surface (air, fog) is found once per pixel and shared
  // by the pixel's samples that lie within 1 % of the same distance (the directions
  // differ by under a pixel); a sample on another surface at another depth gets its own.
  struct PixelBetween {
    bool valid = false;
    double distance = 0;
    Between between;
  };
  auto between_for = [&](const Ray& ray, double distance, PixelBetween& pixel) -> const Between& {
    const bool same = pixel.valid && (std::isinf(distance) ? std::isinf(pixel.distance)
                                                           : std::abs(distance - pixel.distance) <= 0.01 * pixel.distance);
    if (!same) pixel = {true, distance, between(ray, distance)};
    return pixel.between;
  };
  // The lamps' glow in fog, from pixel centres (lamp_glow_image.h); made after the
  // first pass, from the centres' view hits, and used by the second.
  std::unique_ptr<LampGlowImage> glow;
  auto sample = [&](double x, double y, uint64_t& rays, PixelBetween& pixel_between, Xyz& glow_sum, ViewHit& met) {
    const Ray ray = camera.ray_through(x, y);
    ++rays;
    const std::optional<Hit> hit = tracer_.intersect(ray);
    met = hit ? ViewHit{hit->mesh_id, hit->t} : ViewHit{};
    if (glow) {
      const Xyz g = glow->at(x, y, ray, met);
      glow_sum = {glow_sum.x + g.x, glow_sum.y + g.y, glow_sum.z + g.z};
    }
    if (!hit)
      return seen_through(sky_.sky_radiance(ray.direction) + sky_.sun_radiance(ray.direction),
                          between_for(ray, std::numeric_limits<double>::infinity(), pixel_between), true);
    const SurfacePoint point = surface_point(ray, *hit);
    std::optional<CachedSkyLight> sky_light = cache->interpolate(x, y, point);
    if (!sky_light) sky_light = sky_light_at(point, -ray.direction, rays);
    return seen_through(shade(ray, point, *sky_light, rays), between_for(ray, point.distance, pixel_between), false);
  };

  // A pixel's value from a regular grid × grid of samples inside it, averaged with equal
  // weights (grid 1: its centre); `met` gets what the last sample met.
  auto pixel_value = [&](int x, int y, int grid, uint64_t& rays, ViewHit& met) {
    Spectrum sum;
    Xyz glow_sum;
    PixelBetween pixel_between;
    for (int sy = 0; sy < grid; ++sy)
      for (int sx = 0; sx < grid; ++sx)
        sum += sample(x + (sx + 0.5) / grid, y + (sy + 0.5) / grid, rays, pixel_between, glow_sum, met);
    const double mean = 1.0 / (grid * grid);
    const Xyz pixel = xyz_from_spectrum(sum * static_cast<float>(mean));
    return Xyz{pixel.x + glow_sum.x * mean, pixel.y + glow_sum.y * mean, pixel.z + glow_sum.z * mean};
  };

  // Two passes over the tiles (adaptive antialiasing): first one sample at every pixel's
  // centre; then the full n × n grid only where an edge runs, that is where a pixel's
  // centre and one of its four neighbours' met different objects or differ in any of
  // X, Y, Z by more than kEdgeContrast. Elsewhere the image is smooth at the pixel's scale and its
  // centre stands for the grid's mean.
  std::vector<ViewHit> centre_hit(static_cast<size_t>(width) * height);
  XyzImage refined;
  const int passes = n > 1 ? 2 : 1;
  auto is_edge = [&](int x, int y) {
    const Xyz a = image.at(x, y);
    const uint32_t mesh = centre_hit[static_cast<size_t>(y) * width + x].mesh;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + dx, ny = y + dy;
        if ((dx == 0) == (dy == 0) || nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
        if (centre_hit[static_cast<size_t>(ny) * width + nx].mesh != mesh) return true;
        const Xyz b = image.at(nx, ny);
        for (auto [p, q] : {std::pair{a.x, b.x}, std::pair{a.y, b.y}, std::pair{a.z, b.z}})
          if (std::abs(p - q) > kEdgeContrast * std::max(std::abs(p), std::abs(q))) return true;
      }
    return false;
  };
  // The glow image from the first pass's centre hits; its exact centre values go into
  // the first pass's pixels (whose one sample is the centre), before the second pass
  // compares neighbours and refines edges, whose samples interpolate it.
  auto add_centre_glow = [&] {
    arena.execute([&] {
      glow = std::make_unique<LampGlowImage>(camera, width, height, centre_hit, *lamps_);
      tbb::parallel_for(0, height, [&](int y) {
        for (int x = 0; x < width; ++x) {
          const Xyz p = image.at(x, y), g = glow->centre_glow(x, y);
          image.set(x, y, {p.x + g.x, p.y + g.y, p.z + g.z});
        }
      });
    });
  };
  auto render_tile = [&](int tile, int pass) {
    const int x0 = (tile % tiles_x) * kTileSize, y0 = (tile / tiles_x) * kTileSize;
    const int x1 = std::min(x0 + kTileSize, width), y1 = std::min(y0 + kTileSize, height);
    uint64_t rays = 0;
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) {
        ViewHit met;
        if (pass == 0) {
          image.set(x, y, pixel_value(x, y, passes == 1 ? n : 1, rays, met));
          centre_hit[static_cast<size_t>(y) * width + x] = met;
        } else if (is_edge(x, y)) {
          refined.set(x, y, pixel_value(x, y, n, rays, met));
        }
      }
    }
    rays_traced_.fetch_add(rays, std::memory_order_relaxed);
    if (options.on_progress) {
      std::lock_guard lock(progress_mutex);
      options.on_progress(++tiles_done, passes * tile_count);
    }
  };

  for (int pass = 0; pass < passes; ++pass) {
    if (pass == 1 && lamps_ && fog_) add_centre_glow();
    if (pass == 1) refined = image;  // the second pass reads the first's image and writes here
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<int>(0, tile_count, 1), [&](const tbb::blocked_range<int>& range) {
        for (int tile = range.begin(); tile != range.end(); ++tile) render_tile(tile, pass);
      });
    });
  }
  if (passes == 1 && lamps_ && fog_) add_centre_glow();
  if (passes == 2) image = std::move(refined);
  if (lamps_) add_seen_lamps(image, camera);
  return image;
}

void Renderer::add_seen_lamps(XyzImage& image, const PinholeCamera& camera) const {
  const Vec3& eye = scene_.camera.position;
  for (size_t i = 0; i < lamps_->size(); ++i) {
    const Vec3& lamp = lamps_->position(i);
    const std::optional<std::pair<double, double>> at = camera.project(lamp);
    if (!at) continue;
    const int x = static_cast<int>(std::floor(at->first)), y = static_cast<int>(std::floor(at->second));
    if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
    const Vec3 to_lamp = lamp - eye;
    const double distance = length(to_lamp);
    if (!(distance > 0)) continue;
    const Vec3 direction = to_lamp / distance;
    rays_traced_.fetch_add(1, std::memory_order_relaxed);
    if (tracer_.occluded(Ray{eye, direction, 0.0, distance * (1 - 1e-6)})) continue;
    const Spectrum irradiance = lamps_->irradiance_from(i, eye) * sky_.aerial_perspective(direction, distance).transmittance;
    const Xyz added = xyz_from_spectrum(irradiance * static_cast<float>(1.0 / camera.pixel_solid_angle(x + 0.5, y + 0.5)));
    const Xyz old = image.at(x, y);
    image.set(x, y, {old.x + added.x, old.y + added.y, old.z + added.z});
  }
}

}  // namespace skylit
