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

}  // namespace skylit
