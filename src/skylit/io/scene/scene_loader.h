// Reads a scene file (JSON, docs/scene-format.md) into a validated Scene. Relative
// paths inside it (mesh files) are relative to the scene file's folder.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "skylit/scene/scene.h"

namespace skylit {

// Reads, applies `overrides` (`path=value`, see scene_overrides.h), validates.
// Every problem a user can cause is an InputError naming the file and the place.
Scene load_scene(const std::filesystem::path& scene_file, const std::vector<std::string>& overrides = {});

}  // namespace skylit
