// A scene made ready to render: its meshes in the ray tracer, the atmosphere's tables
// for its sun and camera, its fog, clouds and lamps. Built once per scene (the costly
// part of setting up a frame), then only read, by any number of threads, by whichever
// integrator renders it.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "skylit/atmosphere/atmosphere.h"
#include "skylit/clouds/clouds_in_sky.h"
#include "skylit/geometry/ray_tracer.h"
#include "skylit/material/surface_appearance.h"
#include "skylit/render/fog_medium.h"
#include "skylit/render/scene_lamps.h"
#include "skylit/render/shadowed_air.h"
#include "skylit/render/surface_cutouts.h"
#include "skylit/render/surface_point.h"
#include "skylit/scene/scene.h"

namespace skylit {

// The material at a surface point: the scene's, or at a textured point a copy whose body
// has the texel's colour (surface_appearance.h, with_body_reflectance).
class PointMaterial {
 public:
  PointMaterial(const Material& material, const SurfacePoint& point);
  const Material& get() const { return textured_ ? *textured_ : material_; }

 private:
  const Material& material_;
  std::optional<Material> textured_;
};

class PreparedScene {
 public:
  // Keeps a reference to `scene`, which must outlive it.
  explicit PreparedScene(const Scene& scene);
  PreparedScene(Scene&&) = delete;

  const Scene& scene() const { return scene_; }
  // The angle a camera pixel spans, radians (as the textures' filter takes it).
  double pixel_angle_rad() const { return pixel_angle_rad_; }
  const RayTracer& tracer() const { return tracer_; }
  // Where the sun's light comes from: the scene's sun as seen (SkyModel::to_sun).
  const Vec3& to_sun() const { return sky_.to_sun(); }
  const SkyModel& sky() const { return sky_; }
  const FogMedium* fog() const { return fog_.get(); }          // null without fog
  const CloudsInSky* clouds() const { return clouds_.get(); }  // null without clouds
  const SceneLamps* lamps() const { return lamps_.get(); }     // null without lights
  // The clear air's sunlight taken out in the scene's shadows; null in fog (whose own
  // shadows cut its beams), without a sun, and in scenes of more than
  // kMaxShadowedAirTriangles triangles.
  const ShadowedAir* shadowed_air() const { return shadowed_air_.get(); }
  // The shadow volumes take about 440 bytes and 1.6 µs to build per triangle: a
  // million-triangle city would add 440 MB and 1.6 s to its frame (2026-12-07) for a
  // correction of a few per cent on views through its shadows.
  static constexpr size_t kMaxShadowedAirTriangles = 250'000;

  // The surface point a ray meets, its normal facing the ray's origin (surfaces are
  // two-sided; one-sided ones are not met from behind), with the material of the
  // triangle it meets. On a smooth-shaded mesh the
  // normal is the interpolated shading normal and the point is lifted onto the curved
  // surface it describes, so that shadow rays do not cut the terminator into facets
  // (geometry/vertex_normals.h). Where the material has textures, they are read with a
  // filter as wide as a camera pixel seen at the hit's distance along the ray
  // (appearance_at); where it shines, so does the point; where it has a normal map, the
  // normal is the map's (normal_mapped).
  SurfacePoint surface_point(const Ray& ray, const Hit& hit) const {
    SurfacePoint point = untextured_point(ray, hit);
    if (const SurfaceAppearance* a = scene_.materials[point.material].appearance.get())
      appearance_at(*a, scene_.objects[hit.mesh_id], hit, ray, point);
    return point;
  }
  // The same without the textures' look-ups (no texture colour, emission or normal
  // map): for a ray that stands for a whole sky element (render/obstacle_materials.h).
  SurfacePoint untextured_point(const Ray& ray, const Hit& hit) const {
    const SceneObject& object = scene_.objects[hit.mesh_id];
    SurfacePoint point{ray.origin + hit.t * ray.direction, hit.geometric_normal, hit.t,
                       object.material_of(hit.triangle)};
    const bool front = dot(point.normal, ray.direction) <= 0;
    if (!front) point.normal = -point.normal;
    point.plane_normal = point.normal;
    if (!object.corner_normals.empty()) shade_smooth(object, hit, ray, front, point);
    return point;
  }
  const Material& material(uint32_t index) const { return scene_.materials[index].material; }
  PointMaterial material_at(const SurfacePoint& point) const { return {material(point.material), point}; }

 private:
  static void shade_smooth(const SceneObject& object, const Hit& hit, const Ray& ray, bool front, SurfacePoint& point);
  void appearance_at(const SurfaceAppearance& appearance, const SceneObject& object, const Hit& hit, const Ray& ray,
                     SurfacePoint& point) const;

  static void normal_mapped(const SurfaceAppearance& appearance, const SceneObject& object, const Hit& hit,
                            const Ray& ray, const std::array<double, 6>& footprint, SurfacePoint& point);

  const Scene& scene_;
  // The angle a camera pixel spans, radians: the image's vertical field over its rows
  // (exact at a perspective image's centre, and for fisheyes and panoramas on average).
  double pixel_angle_rad_;
  // Per object whose materials cut rays (surface_cutouts.h); before tracer_, which
  // points at them, so that they outlive it.
  std::vector<std::unique_ptr<SurfaceCutouts>> cutouts_;
  RayTracer tracer_;  // mesh ids are the indices of scene_.objects
  Atmosphere atmosphere_;
  SkyModel sky_;
  std::unique_ptr<FogMedium> fog_;
  std::unique_ptr<CloudsInSky> clouds_;
  std::unique_ptr<SceneLamps> lamps_;
  std::unique_ptr<ShadowedAir> shadowed_air_;
};

}  // namespace skylit
