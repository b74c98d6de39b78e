// The `objects` part of a scene file: primitives (box, plane) and mesh files, each
// with one material.
#include <string>

#include "skylit/geometry/primitives.h"
#include "skylit/geometry/transform.h"
#include "skylit/io/model/mesh_io.h"
#include "skylit/io/scene/scene_parts.h"

namespace skylit {

namespace {

uint32_t find_material(const JsonReader& j, const std::vector<NamedMaterial>& materials) {
  const std::string name = j.string();
  std::string known;
  for (size_t i = 0; i < materials.size(); ++i) {
    if (materials[i].name == name) return static_cast<uint32_t>(i);
    known += (known.empty() ? "" : ", ") + materials[i].name;
  }
  j.fail("unknown material '" + name + "'; known materials: " + (known.empty() ? "(none)" : known));
}

Vec3 read_positive_size(const JsonReader& j) {
  const Vec3 size = j.vec3();
  if (size.x <= 0 || size.y <= 0 || size.z <= 0) j.fail_expected("three sizes greater than 0");
  return size;
}

TriangleMesh read_box(const JsonReader& j) {
  j.allow_only({"type", "name", "material", "min", "max", "center", "size", "rotation_z_deg"});
  const bool corners = j.has("min") || j.has("max");
  const bool centred = j.has("center") || j.has("size");
  if (corners == centred) j.fail("a box needs either min and max, or center and size");
  if (corners) {
    if (j.has("rotation_z_deg")) j.required("rotation_z_deg").fail("rotation needs center and size");
    const Vec3 lo = j.required("min").vec3(), hi = j.required("max").vec3();
    if (!(hi.x > lo.x && hi.y > lo.y && hi.z > lo.z)) j.required("max").fail("max must exceed min on every axis");
    return make_box(lo, hi);
  }
  const double rotation = j.optional("rotation_z_deg") ? j.required("rotation_z_deg").number_in(-360, 360) : 0.0;
  return make_box_centered(j.required("center").vec3(), read_positive_size(j.required("size")), rotation);
}

TriangleMesh read_plane(const JsonReader& j) {
  j.allow_only({"type", "name", "material", "center", "size_m"});
  const Vec3 center = j.optional("center") ? j.required("center").vec3() : Vec3{0, 0, 0};
  const double size = j.optional("size_m") ? j.required("size_m").number_in(1e-3, 1e6) : 10000.0;
  return make_ground_plane(center, size);
}

Transform read_transform(const JsonReader& j) {
  j.allow_only({"translate", "rotate_deg", "scale"});
  Transform t = Transform::identity();
  if (auto s = j.optional("scale")) {
    const Vec3 factors = s->is_number() ? Vec3{s->number(), s->number(), s->number()} : s->vec3();
    if (factors.x == 0 || factors.y == 0 || factors.z == 0) s->fail("scale factors must not be 0");
    t = Transform::scale(factors);
  }
  if (auto r = j.optional("rotate_deg")) t = Transform::rotation_xyz_deg(r->vec3()) * t;
  if (auto p = j.optional("translate")) t = Transform::translation(p->vec3()) * t;
  return t;
}

TriangleMesh read_mesh(const JsonReader& j, const std::filesystem::path& base_dir) {
  j.allow_only({"type", "name", "material", "file", "up_axis", "transform"});
  const std::filesystem::path file = base_dir / j.required("file").string();
  const std::string extension = file.extension().string();
  // glTF 2.0 is +Y up by its specification; OBJ has no convention, and ours is +Z.
  const bool gltf = extension == ".gltf" || extension == ".glb" || extension == ".GLTF" || extension == ".GLB";
  UpAxis up = gltf ? UpAxis::y : UpAxis::z;
  if (auto u = j.optional("up_axis")) up = u->one_of({"y", "z"}) == "y" ? UpAxis::y : UpAxis::z;
  TriangleMesh mesh = load_mesh_file(file, up);
  if (auto t = j.optional("transform")) mesh = transformed(mesh, read_transform(*t));
  return mesh;
}

}  // namespace

std::vector<SceneObject> read_objects(const JsonReader& j, const std::vector<NamedMaterial>& materials,
                                      const std::filesystem::path& base_dir) {
  std::vector<SceneObject> out;
  for (const JsonReader& o : j.elements()) {
    const std::string type = o.required("type").one_of({"box", "plane", "mesh"});
    SceneObject object;
    object.name = o.optional("name") ? o.required("name").string() : o.path();
    object.material_index = find_material(o.required("material"), materials);
    if (type == "box")
      object.mesh = read_box(o);
    else if (type == "plane")
      object.mesh = read_plane(o);
    else
      object.mesh = read_mesh(o, base_dir);
    out.push_back(std::move(object));
  }
  return out;
}

}  // namespace skylit
