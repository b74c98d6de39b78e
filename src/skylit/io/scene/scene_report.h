// What a loaded scene holds, said for people (`skylit info`, `render --verbose`), and
// warnings about what is probably a mistake although the scene is valid: a model far
// from the origin, floating or sunk, in the wrong unit, a camera inside a building or
// facing one wall, an override that matched nothing.
#pragma once

#include <string>
#include <vector>

#include "skylit/scene/scene.h"

namespace skylit {

// Per object: its file, up axis, units and shift, triangle count, extent in metres,
// and each file material with what it became. Several lines, each ending in '\n'.
std::string describe_objects(const Scene& scene);

// The lights by where their photometry came from: per file or shape, how many lights
// use it, the luminous flux each sends out (tilt included; against the lamps' rated
// lumens, the luminaire's efficiency), its peak intensity and the heights it stands at.
// Empty without lights.
std::string describe_lights(const Scene& scene);

// One line each (no newline). The camera checks trace rays, which needs the scene's
// ray-tracing structure built (about as long as a render's set-up), so they are only
// made when `check_camera` is true.
std::vector<std::string> scene_warnings(const Scene& scene, bool check_camera);

}  // namespace skylit
