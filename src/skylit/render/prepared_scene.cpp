#include "skylit/render/prepared_scene.h"

namespace skylit {

PreparedScene::PreparedScene(const Scene& scene)
    : scene_(scene),
      to_sun_(direction_from_altitude_azimuth(scene.sun.altitude_deg, scene.sun.azimuth_deg)),
      atmosphere_(scene.atmosphere),
      sky_(atmosphere_, to_sun_, scene.camera.position.z) {
  for (const SceneObject& object : scene.objects) tracer_.add_mesh(object.mesh);
  tracer_.commit();
  if (!scene.clouds.empty() || scene.cloud_layer) {
    const Vec3 below_camera{scene.camera.position.x, scene.camera.position.y, 0.0};
    clouds_ =
        std::make_unique<CloudsInSky>(scene.clouds, scene.cloud_layer, sky_, below_camera, scene.render.cloud_light);
  }
  // The scene's meshes, for the fog's and the lamps' shadow volumes.
  std::vector<const TriangleMesh*> meshes;
  for (const SceneObject& object : scene.objects) meshes.push_back(&object.mesh);
  if (scene.fog) fog_ = std::make_unique<FogMedium>(*scene.fog, meshes, sky_, scene.camera.position);
  if (!scene.lights.empty())
    lamps_ = std::make_unique<SceneLamps>(scene.lights, tracer_, meshes, fog_ ? &fog_->layer() : nullptr);
}

void PreparedScene::shade_smooth(const SceneObject& object, const Hit& hit, const Ray& ray, bool front,
                                 SurfacePoint& point) {
  const CornerNormals& normals = object.corner_normals[hit.triangle];
  const double b[3] = {1.0 - hit.u - hit.v, hit.u, hit.v};
  Vec3 shading{0, 0, 0};
  for (int i = 0; i < 3; ++i) shading += b[i] * Vec3{normals[i][0], normals[i][1], normals[i][2]};
  const double len = length(shading);
  if (!(len > 0)) return;
  shading = (front ? 1.0 : -1.0) * shading / len;
  // A shading normal turned away from the viewer would shade the visible side as its
  // back: keep the flat normal there (at silhouettes of coarse meshes).
  if (dot(shading, ray.direction) >= 0) return;
  point.normal = shading;
  if (!front) return;  // the lift is toward the outside the normals describe
  const auto& tri = object.mesh.triangles[hit.triangle];
  point.position =
      shading_point({object.mesh.vertices[tri[0]], object.mesh.vertices[tri[1]], object.mesh.vertices[tri[2]]}, normals,
                    hit.u, hit.v);
}

}  // namespace skylit
