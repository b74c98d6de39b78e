// The readers of each part of a scene file, used by scene_loader.cpp. Each takes the
// JSON value of its part and throws InputError naming the path of what is wrong.
#pragma once

#include <filesystem>
#include <vector>

#include "skylit/io/scene/json_reader.h"
#include "skylit/scene/scene.h"
#include "skylit/sun/solar_position.h"

namespace skylit {

// load_scene (scene_loader.h) from a parsed document; `base_dir` resolves mesh paths,
// `source` names the document in messages. Here rather than in scene_loader.h because
// its nlohmann::json parameter must not reach the installed headers.
Scene scene_from_json(const nlohmann::json& document, const std::string& source, const std::filesystem::path& base_dir);

// `sun`, or `site` and `time`, and `atmosphere`, from the scene's top level. Returns
// true when the sun waits for a site: a `time` without `site`, which a city model's
// centre may give (place_sun, once the objects are read).
bool read_sun_and_atmosphere(const JsonReader& root, Scene& scene);
// The sun at the scene's `time` seen from `site`; fails on `time` without a site.
void place_sun(const JsonReader& root, const std::optional<SiteLocation>& site, Scene& scene);
// The scene's `site`, if it gives one.
std::optional<SiteLocation> read_scene_site(const JsonReader& root);
// The moon (placed in the sky model's light when the sun is down) and the night sky;
// after the sun is placed (night_reader.cpp).
void read_moon_and_night_sky(const JsonReader& root, Scene& scene);
AtmosphereSettings read_atmosphere(const JsonReader& atmosphere);
FogSettings read_fog(const JsonReader& fog);
FalseColourSettings read_false_colour(const JsonReader& false_colour);
std::vector<Probe> read_probes(const JsonReader& probes);
// The camera's projection, its angles of view and lens shift (all but the perspective
// projection's vertical_fov_deg and focal length, which read_camera reads).
void read_camera_projection(const JsonReader& camera_block, Camera& camera);
void read_clouds(const JsonReader& clouds, Scene& scene);
// `weather`: an EPW file's hour sets the sun, air, sky, clouds, fog and ground, and the
// site where `site` (the scene's, or a city model's centre) gives none
// (io/weather/weather_conditions.h); the file is relative to base_dir.
void read_weather(const JsonReader& weather, const std::filesystem::path& base_dir, Scene& scene,
                  const std::optional<SiteLocation>& site);
// `sky`: "physical" (the model's own, empty) or a CIE standard general sky.
std::optional<CieSkySettings> read_sky(const JsonReader& sky, bool weather_gives_diffuse);
std::vector<NamedMaterial> read_materials(const JsonReader& materials);
// One material: a preset's name, {"preset": name, …} or an object with a type.
Material read_material(const JsonReader& material);

// `material_overrides`: glob patterns (fnmatch(3), case-sensitive) on the names of a
// model file's materials, each with the scene material that replaces them.
struct MaterialOverride {
  std::string pattern;
  uint32_t material;  // into Scene::materials
};
// Each value names a scene material or a preset, or defines one inline (added to
// `materials` as "override <pattern>").
std::vector<MaterialOverride> read_material_overrides(const JsonReader& overrides,
                                                      std::vector<NamedMaterial>& materials);
Spectrum read_reflectance(const JsonReader& reflectance);
std::vector<SceneLight> read_lights(const JsonReader& lights, const std::filesystem::path& base_dir);
// `lamp_rows` (lights/lamp_rows.h): the rows' luminaires appended to `lights`.
void read_lamp_rows(const JsonReader& rows, const std::filesystem::path& base_dir, std::vector<SceneLight>& lights);
// `cars`: each a pair of headlamps appended to `lights` (lights/headlamps.h).
void read_cars(const JsonReader& cars, const std::filesystem::path& base_dir, std::vector<SceneLight>& lights);
// `road_lighting` (scene/road_lighting_settings.h).
RoadLightingSettings read_road_lighting(const JsonReader& road);
// Materials of model files are added to `materials`; override patterns that matched
// no file material are listed in `unused_overrides`. `site`: the scene's; a city
// model sets it to its centre when the scene gives none.
std::vector<SceneObject> read_objects(const JsonReader& objects, std::vector<NamedMaterial>& materials,
                                      const std::vector<MaterialOverride>& overrides,
                                      const std::filesystem::path& base_dir, std::vector<std::string>& unused_overrides,
                                      std::optional<SiteLocation>& site);
// An object of type "city" (city_reader.cpp).
SceneObject read_city(const JsonReader& city, const std::filesystem::path& base_dir,
                      std::vector<NamedMaterial>& materials, std::optional<SiteLocation>& site);

}  // namespace skylit
