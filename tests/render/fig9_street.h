// The Fig. 9 street (examples/fig9.json) with its meshes in a ray tracer and its fog,
// for tests of the lamps' glow.
#pragma once

#include <string>
#include <vector>

#include "skylit/geometry/ray_tracer.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/media/fog_layer.h"

namespace skylit {

struct Fig9Street {
  Scene scene = load_scene(std::string(SKYLIT_SOURCE_DIR) + "/examples/fig9.json");
  std::vector<const TriangleMesh*> meshes;
  RayTracer tracer;
  FogLayer layer{*scene.fog};

  Fig9Street() {
    for (const SceneObject& o : scene.objects) {
      meshes.push_back(&o.mesh);
      tracer.add_mesh(o.mesh);
    }
    tracer.commit();
  }
};

}  // namespace skylit
