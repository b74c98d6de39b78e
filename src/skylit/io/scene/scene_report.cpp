#include "skylit/io/scene/scene_report.h"

#include <algorithm>
#include <cmath>

#include "skylit/core/formatted.h"
#include "skylit/core/text_file.h"
#include "skylit/geometry/ray_tracer.h"
#include "skylit/render/camera.h"

namespace skylit {
namespace {

// Thresholds of the warnings. Beyond 10 km from the origin Embree's single
// precision spaces points 1 mm apart or more. Half a metre off the ground is more than
// any modelling slip of a plinth. A building 2 km across is beyond any single
// building (the tallest is 828 m), and one under 0.2 m across is no building at all:
// both suggest a unit read wrong (mm or cm as m; km or feet-to-metre mix-ups).
constexpr double kFarFromOrigin_m = 10e3;
constexpr double kOffGround_m = 0.5;
constexpr double kLargestModel_m = 2e3;
constexpr double kSmallestModel_m = 0.2;

std::string quoted(const std::string& s) { return "'" + s + "'"; }

// How far a box's centre lies from the origin (the site) across the ground, m.
double centre_distance_m(const BoundingBox& box) {
  const Vec3 c = box.center();
  return std::hypot(c.x, c.y);
}

void check_model_placement(const SceneObject& object, std::vector<std::string>& warnings) {
  const BoundingBox box = object.mesh.bounds();
  if (box.empty()) return;
  const std::string who = "object " + quoted(object.name);
  const double distance = centre_distance_m(box);
  if (distance > kFarFromOrigin_m)
    warnings.push_back(who + formatted(" lies %.1f km from the origin: set \"center\": true (or translate it) so that "
                                       "single-precision ray tracing keeps its detail",
                                       distance / 1e3));
  if (box.lo.z > kOffGround_m)
    warnings.push_back(
        who + formatted(" floats %.2f m above the ground (its lowest point): \"place_on_ground\": true?", box.lo.z));
  if (box.lo.z < -kOffGround_m)
    warnings.push_back(
        who + formatted(" sinks %.2f m below the ground (its lowest point): \"place_on_ground\": true?", -box.lo.z));
  const Vec3 size = box.size();
  const double largest = std::max({size.x, size.y, size.z});
  if (largest > kLargestModel_m)
    warnings.push_back(
        who + formatted(" is %.0f m across: is the file in mm or cm? Set \"units\" (m, cm, mm, ft, in)", largest));
  if (largest < kSmallestModel_m)
    warnings.push_back(who + formatted(" is only %.3f m across: is the file in another unit? Set \"units\"", largest));
}

// A city model is placed by its coordinates around the site: far from it, the site is
// probably wrong (another city's, or a weather station's far away), and the earth's
// curvature puts the model kilometres below the horizon.
void check_city_placement(const SceneObject& object, std::vector<std::string>& warnings) {
  for (const std::string& w : object.city->terrain_warnings)
    warnings.push_back("object " + quoted(object.name) + ": " + w);
  if (object.city && object.city->axes_swapped && !object.city->axes_swapped_by_format)
    warnings.push_back("object " + quoted(object.name) +
                       ": the file's first two coordinates are read the other way "
                       "round than " +
                       object.city->crs +
                       " defines them (easting first for a northing-first CRS, or "
                       "the reverse): only so do they lie in its area of use; if the model is misplaced, give "
                       "\"crs\" as a PROJ string with the file's axis order");
  const BoundingBox box = object.mesh.bounds();
  if (box.empty()) return;
  const double distance = centre_distance_m(box);
  if (distance > kFarFromOrigin_m)
    warnings.push_back("object " + quoted(object.name) +
                       formatted(" lies %.1f km from the site: is the scene's site the model's?", distance / 1e3));
}

// Inside a closed mesh, every ray from the camera leaves through the back of a face.
// Fourteen directions (the cube's faces and corners) leave no way out unseen.
void check_camera_inside(const Scene& scene, const RayTracer& tracer, std::vector<std::string>& warnings) {
  std::vector<Vec3> directions;
  for (int axis = 0; axis < 3; ++axis)
    for (double s : {-1.0, 1.0}) directions.emplace_back(axis == 0 ? s : 0, axis == 1 ? s : 0, axis == 2 ? s : 0);
  for (double x : {-1.0, 1.0})
    for (double y : {-1.0, 1.0})
      for (double z : {-1.0, 1.0}) directions.push_back(normalize({x, y, z}));
  std::vector<int> back_hits(scene.objects.size(), 0);
  for (const Vec3& d : directions) {
    const auto hit = tracer.intersect({scene.camera.position, d});
    if (!hit || dot(hit->geometric_normal, d) <= 0) return;  // a way out, or a front face
    ++back_hits[hit->mesh_id];
  }
  const auto most = std::max_element(back_hits.begin(), back_hits.end());
  warnings.push_back("the camera is inside a closed mesh (object " +
                     quoted(scene.objects[static_cast<size_t>(most - back_hits.begin())].name) +
                     "): every ray from it meets the back of a face");
}

// A grid of camera rays that all meet one flat surface of one object.
void check_camera_view(const Scene& scene, const RayTracer& tracer, std::vector<std::string>& warnings) {
  constexpr int kColumns = 16, kRows = 9;
  const ImageCamera camera(scene.camera, kColumns, kRows);
  std::optional<Hit> first;
  for (int row = 0; row < kRows; ++row)
    for (int column = 0; column < kColumns; ++column) {
      const auto hit = tracer.intersect(camera.ray_through(column + 0.5, row + 0.5));
      if (!hit) return;
      if (!first) first = hit;
      // Within 1° of the first normal: one plane.
      if (hit->mesh_id != first->mesh_id || dot(hit->geometric_normal, first->geometric_normal) < 0.99985) return;
    }
  warnings.push_back("the camera sees nothing but one surface of object " + quoted(scene.objects[first->mesh_id].name) +
                     ": is it facing a wall from close by?");
}

// A length printed to the millimetre, without the "-0.000" of a shift of −0.2 mm.
double printed_mm(double metres) { return std::abs(metres) < 5e-4 ? 0.0 : metres; }

// The city model's file, CRS, site, city objects by type and surface classes with
// their materials.
std::string describe_city(const CitySource& c) {
  const char* axes = !c.axes_swapped ? ""
                     : c.axes_swapped_by_format
                         ? " (read easting first, as the format writes it)"
                         : " (its first two coordinates read the other way round: see the warning)";
  std::string out = c.file + ", CRS " + c.crs + axes + "\n";
  out += formatted("  site %.7f° ", std::abs(c.latitude_deg)) + (c.latitude_deg < 0 ? "S" : "N") +
         formatted(", %.7f° ", std::abs(c.longitude_deg)) + (c.longitude_deg < 0 ? "W" : "E") +
         (c.site_from_model ? " (the model's centre: no site given)" : " (the scene's site)") +
         formatted("; ground level %.2f m (z = 0)", c.ground_height_m) +
         (c.curvature_applied ? "; earth curvature and refraction applied" : "") + "\n";
  out += "  city objects:";
  for (const auto& [type, count] : c.objects_by_type)
    out.append(" ").append(std::to_string(count)).append(" ").append(type).append(",");
  out.back() = '\n';
  if (c.objects_outside_region > 0) out += "  " + std::to_string(c.objects_outside_region) + " outside the region\n";
  if (c.degenerate_surfaces > 0)
    out += "  " + std::to_string(c.degenerate_surfaces) + " surfaces of zero area skipped\n";
  if (c.appearance_triangles > 0)
    out += "  " + std::to_string(c.appearance_triangles) + " triangles take the file's appearance (theme " +
           quoted(c.appearance_theme) + "); the others their class's material\n";
  if (!c.terrain.empty()) out += "  terrain: " + c.terrain + "\n";
  out += "  surfaces (by class):\n";
  for (const auto& k : c.classes)
    out += "    " + k.name + ": " + std::to_string(k.triangles) + " triangles → " + k.material + "\n";
  return out;
}

}  // namespace

std::string describe_objects(const Scene& scene) {
  std::string out;
  for (const SceneObject& object : scene.objects) {
    const BoundingBox box = object.mesh.bounds();
    out += "object " + quoted(object.name) + ": ";
    if (object.source) {
      const ModelSource& s = *object.source;
      out += s.file + ", up axis " + s.up_axis + ", units " + s.units;
      if (s.offset_m.x != 0 || s.offset_m.y != 0 || s.offset_m.z != 0)
        out += formatted(", shifted by (%.3f, %.3f, %.3f) m", printed_mm(s.offset_m.x), printed_mm(s.offset_m.y),
                         printed_mm(s.offset_m.z));
      out += "\n";
      if (s.skipped_primitives > 0)
        out += "  " + std::to_string(s.skipped_primitives) + " primitive(s) of points or lines not drawn\n";
    } else if (object.city) {
      out += describe_city(*object.city);
    } else {
      out += "primitive\n";
    }
    const size_t triangles = object.mesh.triangles.size();
    out += "  " + std::to_string(triangles) + (triangles == 1 ? " triangle" : " triangles");
    if (!box.empty()) {
      const Vec3 size = box.size();
      out += formatted("; extent %.2f × %.2f", size.x, size.y) + formatted(" × %.2f m", size.z);
      out += formatted(" (x %.2f to %.2f,", box.lo.x, box.hi.x) + formatted(" y %.2f to %.2f,", box.lo.y, box.hi.y) +
             formatted(" z %.2f to %.2f)", box.lo.z, box.hi.z);
    }
    out += "\n";
    if (object.source && !object.source->materials.empty()) {
      out += "  materials in the file:\n";
      for (const auto& m : object.source->materials)
        out += "    " + quoted(m.file_name) + " → " + m.became + (m.overridden ? " (override)" : "") + "\n";
    }
    if (!object.city && (object.triangle_materials.empty() || !object.source || object.source->materials.empty()))
      out += "  material: " + scene.materials[object.material_index].name + "\n";
  }
  return out;
}

std::string describe_lights(const Scene& scene) {
  if (scene.lights.empty()) return {};
  std::string out = "lights: " + std::to_string(scene.lights.size()) + "\n";
  // Lights of one row or file come together: a group is a run of one source.
  for (size_t first = 0; first < scene.lights.size();) {
    const SceneLight& light = scene.lights[first];
    size_t end = first + 1;
    double z_lo = light.luminaire.position().z, z_hi = z_lo;
    const auto same_group = [&](const SceneLight& next) {
      return next.source == light.source && next.luminaire.tilt_multiplier() == light.luminaire.tilt_multiplier();
    };
    for (; end < scene.lights.size() && same_group(scene.lights[end]); ++end) {
      z_lo = std::min(z_lo, scene.lights[end].luminaire.position().z);
      z_hi = std::max(z_hi, scene.lights[end].luminaire.position().z);
    }
    const IntensityDistribution& d = light.luminaire.distribution();
    const double lumens = d.luminous_flux() * light.luminaire.tilt_multiplier();
    out += "  " + quoted(light.name);
    if (end - first > 1) out += " and " + std::to_string(end - first - 1) + " more";
    out += ": " + (light.source.empty() ? std::string("photometry") : light.source) + "\n";
    out += formatted("    %.0f lm each, peak %.0f cd; at z %.2f", lumens, d.peak_candela(), z_lo) +
           (z_hi > z_lo ? formatted(" to %.2f m\n", z_hi) : std::string(" m\n"));
    first = end;
  }
  return out;
}

std::vector<std::string> scene_warnings(const Scene& scene, bool check_camera) {
  std::vector<std::string> warnings;
  for (const SceneObject& object : scene.objects) {
    if (object.city && !object.city->missing_texture_images.empty()) {
      const auto& missing = object.city->missing_texture_images;
      warnings.push_back("object " + quoted(object.name) + ": " + std::to_string(missing.size()) +
                         " texture image(s) of the city model not found beside its file (the first: " +
                         quoted(missing.front()) + "); their surfaces take their material or class's instead");
    }
    if (object.city) check_city_placement(object, warnings);
    if (!object.source) continue;  // boxes and planes are where the user put them
    check_model_placement(object, warnings);
    for (const std::string& library : object.source->missing_libraries)
      warnings.push_back("object " + quoted(object.name) + ": material library " + quote_name(library) +
                         " not found beside its file; its faces take the object's material");
    for (const std::string& image : object.source->missing_images)
      warnings.push_back("object " + quoted(object.name) + ": texture image " + quote_name(image) +
                         " not found beside its file; its materials are used without it");
    for (const std::string& line : object.source->read_warnings)
      warnings.push_back("object " + quoted(object.name) + ": " + line);
    if (scene.material_override_count > 0)
      for (const auto& m : object.source->materials)
        if (!m.overridden)
          warnings.push_back("object " + quoted(object.name) + ": material " + quoted(m.file_name) +
                             " matched no override; used as the file describes it");
  }
  // A station's hourly weather stands for its region's: beyond some 50 km, clouds, fog
  // and haze commonly differ (a coast, a mountain range), and beyond a few hundred the
  // file is probably the wrong one.
  constexpr double kFarStationKm = 50;
  if (scene.weather && scene.weather->station_distance_km > kFarStationKm)
    warnings.push_back(
        formatted("weather: the file's station lies %.0f km from the site; its weather is taken as "
                  "the site's (a nearer station's file would be truer)",
                  scene.weather->station_distance_km));
  // No sky leaves the ground without daylight while the sun is up (an overcast winter
  // noon still gives thousands of lux): a record of none then is a gap the file filled
  // with zeros (PVGIS files have many), rendered as it says.
  if (scene.weather && scene.weather->sun_altitude_deg > 1 && scene.weather->file_global_horizontal_lux &&
      *scene.weather->file_global_horizontal_lux <= 0)
    warnings.push_back(
        formatted("weather: the record gives no daylight (0 lx global horizontal) with the sun "
                  "%.1f° up, which no sky allows: probably a gap in the file filled with zeros; "
                  "rendered as the file says, dark",
                  scene.weather->sun_altitude_deg));
  for (const std::string& pattern : scene.unused_material_overrides)
    warnings.push_back("material_overrides: pattern " + quoted(pattern) + " matched no material of any file");
  if (check_camera && !scene.objects.empty()) {
    RayTracer tracer;
    for (const SceneObject& object : scene.objects) tracer.add_mesh(object.mesh);
    tracer.commit();
    check_camera_inside(scene, tracer, warnings);
    check_camera_view(scene, tracer, warnings);
  }
  return warnings;
}

}  // namespace skylit
