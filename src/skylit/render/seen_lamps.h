// Lamps the camera sees directly: point sources, so no ray meets them; each one not
// hidden by an object lands in the pixel it falls in, its irradiance at the camera
// (through the fog and the air) spread over that pixel's solid angle.
#pragma once

#include "skylit/render/camera.h"
#include "skylit/render/film.h"
#include "skylit/render/prepared_scene.h"

namespace skylit {

void add_seen_lamps(const PreparedScene& scene, const ImageCamera& camera, Film& film);

}  // namespace skylit
