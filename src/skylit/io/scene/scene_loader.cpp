#include "skylit/io/scene/scene_loader.h"

#include <cmath>

#include "skylit/core/error.h"
#include "skylit/core/text_file.h"
#include "skylit/io/scene/scene_overrides.h"
#include "skylit/io/scene/scene_parts.h"
#include "skylit/scene/camera_framing.h"

namespace skylit {

namespace {

Camera read_camera(const JsonReader& j) {
  j.allow_only({"position", "look_at", "up", "vertical_fov_deg", "focal_length_mm", "sensor_height_mm", "frame",
                "from_azimuth_deg", "elevation_deg", "projection", "horizontal_fov_deg", "lens_shift"});
  Camera camera;
  // A camera framed from a direction has its position found later, as has every
  // framed camera its look_at; stand-ins meanwhile.
  const bool framed_by_direction = j.has("frame") && (j.has("from_azimuth_deg") || j.has("elevation_deg"));
  camera.position = framed_by_direction && !j.has("position") ? Vec3{0, 0, 0} : j.required("position").point_m();
  camera.look_at = j.has("frame") ? camera.position + Vec3{0, 1, 0} : j.required("look_at").point_m();
  if (auto up = j.optional("up")) {
    camera.up = up->vec3();
    if (!(length(camera.up) > 0) || !std::isfinite(length(camera.up)))
      up->fail("up must be a non-zero vector of moderate length");
  }
  const Vec3 forward = camera.look_at - camera.position;
  if (length(forward) == 0) j.required("look_at").fail("look_at must differ from position");
  if (length(cross(forward, camera.up)) <= 1e-9 * length(forward) * length(camera.up))
    j.optional("up") ? j.required("up").fail("up must not be parallel to the viewing direction")
                     : j.fail("the view is vertical: give an 'up' vector that is not parallel to it");

  const auto fov = j.optional("vertical_fov_deg");
  const auto focal = j.optional("focal_length_mm");
  if (fov && focal) j.fail("give either vertical_fov_deg or focal_length_mm, not both");
  if (auto sensor = j.optional("sensor_height_mm"); sensor && !focal)
    sensor->fail("sensor_height_mm needs focal_length_mm");
  read_camera_projection(j, camera);
  if (camera.projection != Projection::perspective) {
    if (focal) focal->fail("focal_length_mm is for the perspective projection; give vertical_fov_deg");
  } else if (fov) {
    camera.vertical_fov_deg = fov->number_in(0.01, 179);
  } else if (focal) {
    // A full-frame sensor (24 mm high) unless told otherwise.
    const double focal_mm = focal->number_in(0.1, 1e5);
    const double sensor_mm = j.optional("sensor_height_mm") ? j.required("sensor_height_mm").number_in(0.1, 1e3) : 24.0;
    camera.vertical_fov_deg = degrees(2.0 * std::atan(sensor_mm / (2.0 * focal_mm)));
  }
  return camera;
}

// `camera.frame`: the named objects shown whole, from a direction (from_azimuth_deg,
// elevation_deg) or from `position`, looking at their centre (scene/camera_framing.h).
void frame_camera(const JsonReader& j, Scene& scene) {
  const auto frame = j.optional("frame");
  const bool by_direction = j.has("from_azimuth_deg") || j.has("elevation_deg");
  if (!frame) {
    if (by_direction) j.fail("from_azimuth_deg and elevation_deg need \"frame\": the objects to show");
    return;
  }
  if (j.has("look_at")) j.required("look_at").fail("give either look_at or frame, not both");
  if (j.has("up")) j.required("up").fail("a framed camera chooses its own up");
  BoundingBox box;
  const auto names = frame->elements();
  if (names.empty()) frame->fail_expected("an array of object names");
  for (const JsonReader& n : names) {
    const std::string name = n.string();
    bool found = false;
    std::string known;
    for (const SceneObject& object : scene.objects) {
      known += (known.empty() ? "" : ", ") + object.name;
      if (object.name == name) box.add(object.mesh.bounds()), found = true;
    }
    if (!found) n.fail("no object is named '" + name + "'; objects: " + known);
  }
  if (box.empty()) frame->fail("the framed objects have no triangles");
  const double aspect = static_cast<double>(scene.render.width) / scene.render.height;
  const double fov = scene.camera.vertical_fov_deg;
  if (by_direction) {
    if (j.has("position")) j.required("position").fail("give either position or from_azimuth_deg, not both");
    const double azimuth = j.required("from_azimuth_deg").number_in(-360, 360);
    const double elevation = j.required("elevation_deg").number_in(-90, 90);
    scene.camera = frame_from_direction(box, azimuth, elevation, fov, aspect);
  } else {
    const bool fov_given = j.has("vertical_fov_deg") || j.has("focal_length_mm");
    scene.camera = frame_from_position(box, scene.camera.position, fov, aspect, !fov_given);
    if (length(scene.camera.look_at - scene.camera.position) == 0)
      j.required("position").fail("the camera stands at the centre of the framed objects");
  }
}

RenderSettings read_render(const JsonReader& j) {
  j.allow_only({"width", "height", "exposure_ev", "samples_per_axis", "integrator", "samples_per_pixel", "seed",
                "cloud_light", "false_colour", "exr_layers", "display", "obstacle_light"});
  RenderSettings render;
  if (auto w = j.optional("width")) render.width = w->integer_in(1, 16384);
  if (auto h = j.optional("height")) render.height = h->integer_in(1, 16384);
  if (static_cast<long long>(render.width) * render.height > kMaxRenderPixels)
    j.fail("width × height is " + std::to_string(static_cast<long long>(render.width) * render.height) +
           " pixels, over the limit of 33,177,600 (7680 × 4320): a frame needs about 300 bytes per pixel");
  if (auto ev = j.optional("exposure_ev")) {
    // "auto" is the default, accepted explicitly so that --set can restore it.
    if (!(ev->is_string() && ev->string() == "auto")) render.exposure_ev = ev->number_in(-30, 40);
  }
  if (auto s = j.optional("samples_per_axis")) render.samples_per_axis = s->integer_in(1, 16);
  if (auto i = j.optional("integrator"))
    render.integrator = i->one_of({"bands", "path"}) == "path" ? Integrator::path : Integrator::bands;
  if (auto c = j.optional("cloud_light"))
    render.cloud_light =
        c->one_of({"two_stream", "paper"}) == "paper" ? CloudLightModel::paper : CloudLightModel::two_stream;
  if (auto s = j.optional("samples_per_pixel")) render.samples_per_pixel = s->integer_in(1, 1 << 20);
  if (auto s = j.optional("seed")) render.seed = static_cast<uint64_t>(s->integer_in(0, 1 << 30));
  if (auto f = j.optional("false_colour")) render.false_colour = read_false_colour(*f);
  if (auto l = j.optional("exr_layers")) render.exr_layers = l->boolean();
  if (auto d = j.optional("display")) render.human_display = d->one_of({"photographic", "human"}) == "human";
  if (auto o = j.optional("obstacle_light")) render.obstacles_own_sky = o->one_of({"open_sky", "own_sky"}) == "own_sky";
  return render;
}

}  // namespace

Scene scene_from_json(const nlohmann::json& document, const std::string& source,
                      const std::filesystem::path& base_dir) {
  const JsonReader root(document, source);
  if (!root.is_object()) root.fail_expected("an object with camera, sun (or site and time), objects");
  root.allow_only({"camera",
                   "sun",
                   "site",
                   "time",
                   "weather",
                   "sky",
                   "atmosphere",
                   "fog",
                   "clouds",
                   "materials",
                   "material_overrides",
                   "objects",
                   "lights",
                   "lamp_rows",
                   "cars",
                   "road_lighting",
                   "moon",
                   "night_sky",
                   "render",
                   "probes"});
  Scene scene;
  scene.camera = read_camera(root.required("camera"));
  const auto weather = root.optional("weather");
  bool sun_needs_site = false;
  if (weather) {
    // The site may be given: the file's station is often tens of kilometres from it.
    for (const char* key : {"sun", "time"})
      if (root.has(key)) root.required(key).fail("give either a weather file's hour or the " + std::string(key));
    if (auto a = root.optional("atmosphere")) scene.atmosphere = read_atmosphere(*a);
  } else {
    sun_needs_site = read_sun_and_atmosphere(root, scene);
  }
  if (auto sky = root.optional("sky")) scene.atmosphere.cie_sky = read_sky(*sky, weather.has_value());
  if (auto fog = root.optional("fog")) scene.fog = read_fog(*fog);
  if (auto clouds = root.optional("clouds")) read_clouds(*clouds, scene);
  // A city model is placed around the scene's site, or else its own centre becomes the
  // site; never the weather station's, which may lie far away.
  std::optional<SiteLocation> site = read_scene_site(root);
  // Optional: meshes may bring their own materials, and objects may name presets.
  if (auto materials = root.optional("materials")) scene.materials = read_materials(*materials);
  std::vector<MaterialOverride> overrides;
  if (auto o = root.optional("material_overrides")) overrides = read_material_overrides(*o, scene.materials);
  scene.material_override_count = overrides.size();
  scene.objects = read_objects(root.required("objects"), scene.materials, overrides, base_dir,
                               scene.unused_material_overrides, site);
  // After the scene's own sky, fog and clouds, which the weather leaves as they are; the
  // sun for the site, or the station's where nothing gave one.
  if (weather) read_weather(*weather, base_dir, scene, site);
  if (sun_needs_site) place_sun(root, site, scene);
  read_moon_and_night_sky(root, scene);
  if (auto lights = root.optional("lights")) scene.lights = read_lights(*lights, base_dir);
  if (auto rows = root.optional("lamp_rows")) read_lamp_rows(*rows, base_dir, scene.lights);
  if (auto cars = root.optional("cars")) read_cars(*cars, base_dir, scene.lights);
  if (auto road = root.optional("road_lighting")) scene.road_lighting = read_road_lighting(*road);
  if (auto render = root.optional("render")) scene.render = read_render(*render);
  frame_camera(root.required("camera"), scene);
  if (auto probes = root.optional("probes")) scene.probes = read_probes(*probes);
  return scene;
}

Scene load_scene(const std::filesystem::path& scene_file, const std::vector<std::string>& overrides) {
  nlohmann::json document = parse_json_text(read_text_file(scene_file, "scene file"), scene_file.string());
  for (const std::string& assignment : overrides) apply_override(document, assignment);
  return scene_from_json(document, scene_file.string(), scene_file.parent_path());
}

}  // namespace skylit
