// The `objects` part of a scene file: primitives (box, plane) with one material each,
// and mesh files with the materials they give their triangles (replaced by the
// scene's `material_overrides`), the object's `material` where they give none.
#include <fnmatch.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>

#include "skylit/geometry/primitives.h"
#include "skylit/geometry/transform.h"
#include "skylit/geometry/vertex_normals.h"
#include "skylit/io/model/mesh_io.h"
#include "skylit/io/scene/scene_parts.h"
#include "skylit/material/model_material.h"
#include "skylit/material/presets.h"

namespace skylit {

namespace {

// A mesh's transform may turn millimetres into metres or a model into a city; a million
// either way is past any such use.
constexpr double kMaxScaleFactor = 1e6;
// Mesh vertices, once placed, within ±1e15 m: wider than kSceneExtentM for points, since a
// model in survey coordinates or read in the wrong unit is accepted with a warning
// (scene_report.cpp), but far inside what single precision and squared lengths hold.
constexpr double kMaxMeshCoordinateM = 1e15;

std::optional<uint32_t> material_named(const std::string& name, const std::vector<NamedMaterial>& materials) {
  for (size_t i = 0; i < materials.size(); ++i)
    if (materials[i].name == name) return static_cast<uint32_t>(i);
  return std::nullopt;
}

// An object's material: one the scene's `materials` names, else a preset by its own name
// (added to `materials` once, so that a scene of presets alone needs no `materials`).
uint32_t find_material(const JsonReader& j, std::vector<NamedMaterial>& materials) {
  const std::string name = j.string();
  if (auto index = material_named(name, materials)) return *index;
  if (find_material_preset(name)) {
    materials.push_back({name, read_material(j)});
    return static_cast<uint32_t>(materials.size() - 1);
  }
  std::string known;
  for (const NamedMaterial& m : materials) known += (known.empty() ? "" : ", ") + m.name;
  j.fail("unknown material '" + name + "': neither in the scene's materials (" + (known.empty() ? "none" : known) +
         ") nor a preset (" + material_preset_names() + ")");
}

// Characters of a glob pattern that must match literally.
size_t literal_length(const std::string& pattern) {
  return static_cast<size_t>(std::count_if(pattern.begin(), pattern.end(),
                                           [](char c) { return c != '*' && c != '?' && c != '[' && c != ']'; }));
}

// JSON objects have no order, so among the patterns that match, the most specific
// (most literal characters) wins: "*Glass*" before "*"; ties go to the first in
// alphabetical order.
const MaterialOverride* best_override(const std::string& name, const std::vector<MaterialOverride>& overrides) {
  const MaterialOverride* best = nullptr;
  for (const MaterialOverride& o : overrides)
    if (fnmatch(o.pattern.c_str(), name.c_str(), 0) == 0 &&
        (!best || literal_length(o.pattern) > literal_length(best->pattern)))
      best = &o;
  return best;
}

Vec3 read_positive_size(const JsonReader& j) {
  const Vec3 size = j.vec3();
  for (const double s : {size.x, size.y, size.z})
    if (!(s > 0 && s <= 2 * kSceneExtentM)) j.fail_expected("three sizes greater than 0 and at most 2e7 m");
  return size;
}

TriangleMesh read_box(const JsonReader& j) {
  j.allow_only({"type", "name", "material", "min", "max", "center", "size", "rotation_z_deg"});
  const bool corners = j.has("min") || j.has("max");
  const bool centred = j.has("center") || j.has("size");
  if (corners == centred) j.fail("a box needs either min and max, or center and size");
  if (corners) {
    if (j.has("rotation_z_deg")) j.required("rotation_z_deg").fail("rotation needs center and size");
    const Vec3 lo = j.required("min").point_m(), hi = j.required("max").point_m();
    if (!(hi.x > lo.x && hi.y > lo.y && hi.z > lo.z)) j.required("max").fail("max must exceed min on every axis");
    return make_box(lo, hi);
  }
  const double rotation = j.optional("rotation_z_deg") ? j.required("rotation_z_deg").number_in(-360, 360) : 0.0;
  return make_box_centered(j.required("center").point_m(), read_positive_size(j.required("size")), rotation);
}

TriangleMesh read_plane(const JsonReader& j) {
  j.allow_only({"type", "name", "material", "center", "size_m"});
  const Vec3 center = j.optional("center") ? j.required("center").point_m() : Vec3{0, 0, 0};
  const double size = j.optional("size_m") ? j.required("size_m").number_in(1e-3, 1e6) : 10000.0;
  return make_ground_plane(center, size);
}

Transform read_transform(const JsonReader& j) {
  j.allow_only({"translate", "rotate_deg", "scale"});
  Transform t = Transform::identity();
  if (auto s = j.optional("scale")) {
    const Vec3 factors = s->is_number() ? Vec3{s->number(), s->number(), s->number()} : s->vec3();
    for (const double f : {factors.x, factors.y, factors.z})
      if (f == 0 || std::abs(f) > kMaxScaleFactor) s->fail("scale factors must not be 0 nor beyond ±1e6");
    t = Transform::scale(factors);
  }
  if (auto r = j.optional("rotate_deg")) t = Transform::rotation_xyz_deg(r->vec3()) * t;
  if (auto p = j.optional("translate")) t = Transform::translation(p->point_m()) * t;
  return t;
}

// Metres per file unit.
double metres_per_unit(const std::string& unit) {
  if (unit == "cm") return 0.01;
  if (unit == "mm") return 0.001;
  if (unit == "ft") return 0.3048;  // the international foot
  if (unit == "in") return 0.0254;
  return 1.0;
}

// `center`: the model's box centred on the origin in x and y (survey coordinates
// brought to the site); `place_on_ground`: its lowest point kOnGroundM above z = 0, so
// that faces lying on the ground do not fight a ground plane for the same hits (an
// outside trial's paving and flat models rendered as speckle). Returns the shift.
constexpr double kOnGroundM = 1e-3;  // below any drawing's precision

Vec3 place(const JsonReader& j, TriangleMesh& mesh) {
  const bool center = j.optional("center") && j.required("center").boolean();
  const bool ground = j.optional("place_on_ground") && j.required("place_on_ground").boolean();
  const BoundingBox box = mesh.bounds();
  Vec3 shift{0, 0, 0};
  if (box.empty()) return shift;
  if (center) shift = {-box.center().x, -box.center().y, 0};
  if (ground) shift.z = kOnGroundM - box.lo.z;
  if (center || ground)
    for (Vec3& v : mesh.vertices) v += shift;
  return shift;
}

LoadedModel read_mesh(const JsonReader& j, const std::filesystem::path& base_dir, ModelSource& source) {
  j.allow_only({"type", "name", "material", "file", "up_axis", "units", "transform", "center", "place_on_ground",
                "normals", "crease_angle_deg"});
  const std::filesystem::path file = base_dir / j.required("file").string();
  const std::string extension = file.extension().string();
  // glTF 2.0 is +Y up by its specification; OBJ has no convention, and ours is +Z.
  const bool gltf = extension == ".gltf" || extension == ".glb" || extension == ".GLTF" || extension == ".GLB";
  UpAxis up = gltf ? UpAxis::y : UpAxis::z;
  if (auto u = j.optional("up_axis")) up = u->one_of({"y", "z"}) == "y" ? UpAxis::y : UpAxis::z;
  LoadedModel model = load_model_file(file, up);
  source.file = file.string();
  source.up_axis = up == UpAxis::y ? 'y' : 'z';
  source.missing_libraries = model.missing_libraries;
  source.missing_images = model.missing_images;
  source.skipped_primitives = model.skipped_primitives;
  source.read_warnings = model.read_warnings;
  if (auto u = j.optional("units")) source.units = u->one_of({"m", "cm", "mm", "ft", "in"});
  if (const double f = metres_per_unit(source.units); f != 1.0)
    model.mesh = transformed(model.mesh, Transform::scale({f, f, f}));
  const auto t = j.optional("transform");
  if (t) {
    const Transform transform = read_transform(*t);
    model.mesh = transformed(model.mesh, transform);
    if (transform.determinant() < 0) reverse_corner_order(model.corner_uvs);  // as transformed() turned the triangles
    transform_corner_normals(model.corner_normals, transform);
    if (!model.corner_normals.empty()) sanitize_file_normals(model.mesh, model.corner_normals);  // a flattening scale
  }
  source.offset_m = place(j, model.mesh);
  // The file's vertices are finite; placed, they must also lie in the scene's extent.
  for (std::size_t i = 0; i < model.mesh.vertices.size(); ++i) {
    const Vec3& v = model.mesh.vertices[i];
    if (!(std::abs(v.x) <= kMaxMeshCoordinateM && std::abs(v.y) <= kMaxMeshCoordinateM &&
          std::abs(v.z) <= kMaxMeshCoordinateM))
      (t ? *t : j.required("file"))
          .fail("vertex " + std::to_string(i) + " of the mesh lies beyond ±1e15 m of the site once placed");
  }
  return model;
}

// Each triangle's scene material: its file material's override, or the file material
// itself (added to `materials` once, as "<object>/<name>"), or the object's material.
void assign_model_materials(const JsonReader& j, const LoadedModel& model, std::vector<NamedMaterial>& materials,
                            const std::vector<MaterialOverride>& overrides, std::vector<bool>& override_used,
                            SceneObject& object) {
  ModelSource& source = *object.source;
  const bool has_fallback = j.has("material");
  const uint32_t fallback = has_fallback ? find_material(j.required("material"), materials) : 0;
  object.material_index = fallback;
  std::map<int32_t, uint32_t> scene_material;
  object.triangle_materials.reserve(model.triangle_material.size());
  for (int32_t m : model.triangle_material) {
    if (m == LoadedModel::kNoMaterial) {
      if (!has_fallback) j.fail("the file gives some triangles no material: give the object a \"material\" for them");
      object.triangle_materials.push_back(fallback);
      continue;
    }
    auto [it, added] = scene_material.try_emplace(m, 0);
    if (added) {
      const ModelMaterial& file_material = model.materials[m];
      if (const MaterialOverride* o = best_override(file_material.name, overrides)) {
        it->second = o->material;
        override_used[static_cast<size_t>(o - overrides.data())] = true;
        source.materials.push_back({file_material.name, materials[o->material].name, true});
      } else {
        it->second = static_cast<uint32_t>(materials.size());
        materials.push_back({object.name + "/" + file_material.name, material_from_model(file_material),
                             appearance_from_model(file_material)});
        source.materials.push_back(
            {file_material.name, materials.back().name + " (" + describe(file_material) + ")", false});
      }
    }
    object.triangle_materials.push_back(it->second);
  }
  // One material for all (a file without materials, say): no list needed.
  const auto& list = object.triangle_materials;
  if (!list.empty() && std::all_of(list.begin(), list.end(), [&](uint32_t m) { return m == list[0]; })) {
    object.material_index = list[0];
    object.triangle_materials.clear();
  }
}

}  // namespace

std::vector<MaterialOverride> read_material_overrides(const JsonReader& j, std::vector<NamedMaterial>& materials) {
  std::vector<MaterialOverride> out;
  for (const auto& [pattern, value] : j.members()) {
    if (pattern.empty()) value.fail("a pattern must not be empty");
    if (value.is_string())
      if (auto index = material_named(value.string(), materials)) {
        out.push_back({pattern, *index});
        continue;
      }
    materials.push_back({"override " + pattern, read_material(value)});
    out.push_back({pattern, static_cast<uint32_t>(materials.size() - 1)});
  }
  return out;
}

std::vector<SceneObject> read_objects(const JsonReader& j, std::vector<NamedMaterial>& materials,
                                      const std::vector<MaterialOverride>& overrides,
                                      const std::filesystem::path& base_dir, std::vector<std::string>& unused_overrides,
                                      std::optional<SiteLocation>& site) {
  std::vector<SceneObject> out;
  std::vector<bool> override_used(overrides.size(), false);
  for (const JsonReader& o : j.elements()) {
    const std::string type = o.required("type").one_of({"box", "plane", "mesh", "city"});
    if (type == "city") {
      out.push_back(read_city(o, base_dir, materials, site));
      continue;
    }
    SceneObject object;
    object.name = o.optional("name") ? o.required("name").string() : o.path();
    if (type == "mesh") {
      object.source.emplace();
      LoadedModel model = read_mesh(o, base_dir, *object.source);
      assign_model_materials(o, model, materials, overrides, override_used, object);
      object.mesh = std::move(model.mesh);
      object.corner_uvs = std::move(model.corner_uvs);
      // The file's own normals, or with "normals": "crease" (or none in the file) smooth
      // normals from the crease angle in the placed mesh's frame; a mesh that is flat
      // everywhere (to 0.1°) keeps its geometric normals and needs no memory for them.
      const std::string normals = o.optional("normals") ? o.required("normals").one_of({"file", "crease"}) : "file";
      const bool file_normals = normals == "file" && !model.corner_normals.empty();
      const double crease = o.optional("crease_angle_deg") ? o.required("crease_angle_deg").number_in(0, 180) : 30.0;
      if (file_normals)
        object.corner_normals = std::move(model.corner_normals);
      else if (crease > 0)
        object.corner_normals = crease_angle_normals(object.mesh, crease);
      if (!object.corner_normals.empty() && !any_smooth_corner(object.mesh, object.corner_normals, 0.1))
        object.corner_normals.clear();
    } else {
      object.material_index = find_material(o.required("material"), materials);
      object.mesh = type == "box" ? read_box(o) : read_plane(o);
    }
    out.push_back(std::move(object));
  }
  for (size_t i = 0; i < overrides.size(); ++i)
    if (!override_used[i]) unused_overrides.push_back(overrides[i].pattern);
  return out;
}

}  // namespace skylit
