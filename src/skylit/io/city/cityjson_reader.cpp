#include "skylit/io/city/cityjson_reader.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

#include <nlohmann/json.hpp>

#include "skylit/core/error.h"
#include "skylit/core/file_names.h"
#include "skylit/core/text_file.h"
#include "skylit/io/city/geo_frame.h"
#include "skylit/io/scene/json_reader.h"

namespace skylit {

namespace {

using nlohmann::json;

// How deep a geometry's surfaces lie in its boundaries (and its semantic and material
// values one level less): a MultiSurface is a list of surfaces, a Solid a list of
// shells, a MultiSolid a list of solids.
int surface_depth(const std::string& type) {
  if (type == "MultiSurface" || type == "CompositeSurface") return 1;
  if (type == "Solid") return 2;
  if (type == "MultiSolid" || type == "CompositeSolid") return 3;
  return 0;  // points, lines, instances
}

// The decoded vertices a geometry's indices refer to.
struct VertexList {
  std::vector<Vec3> points;
};

// The document being read, for messages: every failure names the source and the path.
class Reader {
 public:
  Reader(std::string source, const CityJsonOptions& options) : source_(std::move(source)), options_(options) {}

  [[noreturn]] void fail(const std::string& path, const std::string& message) const {
    throw InputError(source_ + ": " + path + ": " + message);
  }

  const json& member(const json& object, const char* key, const std::string& path) const {
    const auto it = object.find(key);
    if (it == object.end()) fail(path, std::string("missing \"") + key + "\"");
    return *it;
  }

  // The document's "transform": scale and translate, or none.
  void read_transform(const json& document) {
    const auto it = document.find("transform");
    if (it == document.end()) return;
    const json& t = *it;
    if (!t.is_object()) fail("transform", "expected an object with scale and translate");
    for (int axis = 0; axis < 3; ++axis) {
      scale_[axis] = number_at(member(t, "scale", "transform"), axis, "transform.scale");
      translate_[axis] = number_at(member(t, "translate", "transform"), axis, "transform.translate");
    }
    if (scale_[0] == 0 || scale_[1] == 0 || scale_[2] == 0) fail("transform.scale", "a scale must not be 0");
    quantised_ = true;
  }

  bool quantised() const { return quantised_; }
  Reader for_source(std::string source) const {
    Reader copy = *this;
    copy.source_ = std::move(source);
    return copy;
  }

  double number_at(const json& array, int i, const std::string& path) const {
    if (!array.is_array() || array.size() != 3)
      fail(path, "expected three numbers, found " + describe_json_value(array));
    const json& v = array[static_cast<size_t>(i)];
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      fail(path + "[" + std::to_string(i) + "]", "expected a finite number, found " + describe_json_value(v));
    return v.get<double>();
  }

  VertexList read_vertices(const json& vertices, const std::string& path, bool quantised) const {
    if (!vertices.is_array()) fail(path, "expected an array of [x, y, z]");
    VertexList list;
    list.points.reserve(vertices.size());
    for (size_t i = 0; i < vertices.size(); ++i) {
      const std::string at = path + "[" + std::to_string(i) + "]";
      const json& v = vertices[i];
      Vec3 p{number_at(v, 0, at), number_at(v, 1, at), number_at(v, 2, at)};
      if (quantised)
        p = {p.x * scale_[0] + translate_[0], p.y * scale_[1] + translate_[1], p.z * scale_[2] + translate_[2]};
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) fail(at, "the vertex is not finite");
      list.points.push_back(p);
    }
    return list;
  }

  std::string read_crs(const json& document) const {
    const auto metadata = document.find("metadata");
    if (metadata == document.end() || !metadata->is_object()) return "";
    const auto crs = metadata->find("referenceSystem");
    if (crs == metadata->end()) return "";
    if (!crs->is_string()) fail("metadata.referenceSystem", "expected a string, found " + describe_json_value(*crs));
    return normalized_crs_name(crs->get<std::string>());
  }

  // The document's (or a CityJSONSeq feature's) "appearance": its materials and
  // textures appended to the model, its texture coordinates kept for the surfaces,
  // which index them from material_base_ and texture_base_.
  void read_appearance(const json& document, CityModel& model) {
    const auto appearance = document.find("appearance");
    if (!options_.appearance.read || appearance == document.end()) return;
    material_base_ = model.materials.size();
    texture_base_ = model.textures.size();
    texture_vertices_.clear();
    if (!appearance->is_object()) fail("appearance", "expected an object with materials and textures");
    if (const auto materials = appearance->find("materials"); materials != appearance->end()) {
      if (!materials->is_array()) fail("appearance.materials", "expected an array");
      for (size_t i = 0; i < materials->size(); ++i)
        model.materials.push_back(read_material((*materials)[i], "appearance.materials[" + std::to_string(i) + "]", i));
    }
    if (const auto textures = appearance->find("textures"); textures != appearance->end()) {
      if (!textures->is_array()) fail("appearance.textures", "expected an array");
      for (size_t i = 0; i < textures->size(); ++i) {
        const std::string at = "appearance.textures[" + std::to_string(i) + "]";
        const json& t = (*textures)[i];
        if (!t.is_object()) fail(at, "expected a texture object");
        const json& image = member(t, "image", at);
        if (!image.is_string() || image.get_ref<const std::string&>().empty())
          fail(at + ".image", "expected the image's file name");
        CityTexture texture{image.get<std::string>(), ""};
        if (const auto wrap = t.find("wrapMode"); wrap != t.end() && wrap->is_string()) texture.wrap_mode = *wrap;
        model.textures.push_back(std::move(texture));
      }
    }
    if (const auto uvs = appearance->find("vertices-texture"); uvs != appearance->end()) {
      if (!uvs->is_array()) fail("appearance.vertices-texture", "expected an array of [u, v]");
      texture_vertices_.reserve(uvs->size());
      for (size_t i = 0; i < uvs->size(); ++i) {
        const std::string at = "appearance.vertices-texture[" + std::to_string(i) + "]";
        const json& uv = (*uvs)[i];
        if (!uv.is_array() || uv.size() != 2 || !finite_number(uv[0]) || !finite_number(uv[1]))
          fail(at, "expected [u, v], two finite numbers, found " + describe_json_value(uv));
        texture_vertices_.push_back({uv[0].get<float>(), uv[1].get<float>()});
      }
    }
  }

  static bool finite_number(const json& v) { return v.is_number() && std::isfinite(v.get<double>()); }

  CityMaterial read_material(const json& m, const std::string& path, size_t index) const {
    if (!m.is_object()) fail(path, "expected a material object");
    CityMaterial material;
    const auto name = m.find("name");
    material.name =
        name != m.end() && name->is_string() ? name->get<std::string>() : "material " + std::to_string(index);
    const auto colour = [&](const char* key, std::array<double, 3>& out) {
      const auto it = m.find(key);
      if (it == m.end()) return;
      if (!it->is_array() || it->size() != 3) fail(path + "." + key, "expected [r, g, b] from 0 to 1");
      for (size_t c = 0; c < 3; ++c) out[c] = unit_number((*it)[c], path + "." + key + "[" + std::to_string(c) + "]");
    };
    colour("diffuseColor", material.diffuse);
    colour("emissiveColor", material.emissive);
    colour("specularColor", material.specular);
    if (const auto it = m.find("shininess"); it != m.end()) material.shininess = unit_number(*it, path + ".shininess");
    if (const auto it = m.find("transparency"); it != m.end())
      material.transparency = unit_number(*it, path + ".transparency");
    if (const auto it = m.find("isSmooth"); it != m.end() && it->is_boolean()) material.smooth = it->get<bool>();
    return material;
  }

  double unit_number(const json& v, const std::string& path) const {
    if (!finite_number(v) || v.get<double>() < 0 || v.get<double>() > 1)
      fail(path, "expected a number from 0 to 1, found " + describe_json_value(v));
    return v.get<double>();
  }

  void read_templates(const json& document) {
    const auto it = document.find("geometry-templates");
    if (it == document.end()) return;
    if (!it->is_object()) fail("geometry-templates", "expected an object with templates and vertices-templates");
    templates_ = &member(*it, "templates", "geometry-templates");
    if (!templates_->is_array()) fail("geometry-templates.templates", "expected an array of geometries");
    // Template vertices are real coordinates, never quantised.
    template_vertices_ = read_vertices(member(*it, "vertices-templates", "geometry-templates"),
                                       "geometry-templates.vertices-templates", false);
  }

  // Reads every object of a "CityObjects" member into `model`.
  void read_objects(const json& objects, const VertexList& vertices, const std::string& path, CityModel& model) const {
    if (!objects.is_object()) fail(path, "expected an object of city objects by id");
    for (const auto& [id, object] : objects.items()) {
      const std::string at = path + "[\"" + id + "\"]";
      if (!object.is_object()) fail(at, "expected a city object");
      const json& type = member(object, "type", at);
      if (!type.is_string()) fail(at + ".type", "expected a string, found " + describe_json_value(type));
      CityObject city_object{id, type.get<std::string>(), 0, {}};
      const auto geometry = object.find("geometry");
      if (geometry != object.end()) {
        if (!geometry->is_array()) fail(at + ".geometry", "expected an array of geometries");
        read_chosen_geometry(*geometry, vertices, at + ".geometry", city_object, model);
      }
      model.objects.push_back(std::move(city_object));
    }
  }

 private:
  int geometry_lod(const json& geometry, const std::string& path) const {
    if (!geometry.is_object()) fail(path, "expected a geometry object");
    const json& type = member(geometry, "type", path);
    if (!type.is_string()) fail(path + ".type", "expected a string");
    if (type.get<std::string>() == "GeometryInstance") {
      const json& index = member(geometry, "template", path);
      return geometry_lod(template_at(index, path + ".template"), "geometry-templates.templates");
    }
    const auto lod = geometry.find("lod");
    if (lod == geometry.end()) return 0;
    std::optional<int> value;
    if (lod->is_string()) value = parse_lod(lod->get<std::string>());
    if (lod->is_number()) value = parse_lod(std::to_string(lod->get<double>()));
    if (!value)
      fail(path + ".lod", "expected a level of detail (\"2.2\", \"1\", ...), found " + describe_json_value(*lod));
    return *value;
  }

  const json& template_at(const json& index, const std::string& path) const {
    if (!templates_) fail(path, "the file has no geometry-templates");
    if (!index.is_number_unsigned() || index.get<size_t>() >= templates_->size())
      fail(path,
           "no template " + describe_json_value(index) + " (the file has " + std::to_string(templates_->size()) + ")");
    return (*templates_)[index.get<size_t>()];
  }

  // The object's geometry of the chosen LoD (CityJsonOptions::lod).
  void read_chosen_geometry(const json& geometries, const VertexList& vertices, const std::string& path,
                            CityObject& object, CityModel& model) const {
    int best = -1;
    size_t chosen = 0;
    for (size_t g = 0; g < geometries.size(); ++g) {
      const std::string at = path + "[" + std::to_string(g) + "]";
      const int lod = geometry_lod(geometries[g], at);
      const std::string& type = geometries[g]["type"].get_ref<const std::string&>();
      if (surface_depth(type) == 0 && type != "GeometryInstance") continue;  // points and lines
      if (options_.lod && lod > *options_.lod) continue;
      if (lod > best) best = lod, chosen = g;
    }
    if (best < 0) return;
    object.lod = best;
    read_geometry(geometries[chosen], vertices, path + "[" + std::to_string(chosen) + "]", nullptr, object, model);
  }

  // `instance`: the matrix and reference point of a GeometryInstance whose template
  // this is.
  struct Instance {
    std::array<double, 16> matrix;
    Vec3 reference;
  };

  void read_geometry(const json& geometry, const VertexList& vertices, const std::string& path,
                     const Instance* instance, CityObject& object, CityModel& model) const {
    const std::string& type = geometry["type"].get_ref<const std::string&>();
    if (type == "GeometryInstance") {
      if (instance) fail(path, "a template must not itself be an instance");
      read_instance(geometry, vertices, path, object, model);
      return;
    }
    const int depth = surface_depth(type);
    if (depth == 0) return;  // a template of points or lines
    const json& boundaries = member(geometry, "boundaries", path);
    Context context{&vertices,
                    instance,
                    semantic_types(geometry, path),
                    &object,
                    model.materials.size() - material_base_,
                    model.textures.size() - texture_base_};
    const auto semantics = geometry.find("semantics");
    SurfaceValues values;
    if (semantics != geometry.end() && semantics->is_object() && semantics->contains("values"))
      values.semantic = &(*semantics)["values"];
    values.material = theme_values(geometry, "material", path, model.material_theme, model);
    values.texture = theme_values(geometry, "texture", path, model.texture_theme, model);
    if (values.texture && values.texture->is_number()) fail(path + ".texture", "a texture theme needs values");
    walk(boundaries, depth, values, path + ".boundaries", context);
  }

  void read_instance(const json& geometry, const VertexList& vertices, const std::string& path, CityObject& object,
                     CityModel& model) const {
    const json& template_geometry = template_at(member(geometry, "template", path), path + ".template");
    const json& boundaries = member(geometry, "boundaries", path);
    if (!boundaries.is_array() || boundaries.size() != 1)
      fail(path + ".boundaries", "expected one vertex index, the instance's reference point");
    Instance instance{};
    instance.reference = vertex_at(boundaries[0], vertices, path + ".boundaries[0]");
    const json& matrix = member(geometry, "transformationMatrix", path);
    if (!matrix.is_array() || matrix.size() != 16) fail(path + ".transformationMatrix", "expected 16 numbers");
    for (size_t i = 0; i < 16; ++i) {
      if (!matrix[i].is_number() || !std::isfinite(matrix[i].get<double>()))
        fail(path + ".transformationMatrix[" + std::to_string(i) + "]", "expected a finite number");
      instance.matrix[i] = matrix[i].get<double>();
    }
    if (!template_geometry.is_object() || !template_geometry.contains("type") || !template_geometry["type"].is_string())
      fail("geometry-templates.templates", "expected geometries with a type");
    read_geometry(template_geometry, template_vertices_, "geometry-templates.templates", &instance, object, model);
  }

  std::vector<std::string> semantic_types(const json& geometry, const std::string& path) const {
    std::vector<std::string> types;
    const auto semantics = geometry.find("semantics");
    if (semantics == geometry.end()) return types;
    const std::string at = path + ".semantics";
    if (!semantics->is_object()) fail(at, "expected an object with surfaces and values");
    const json& surfaces = member(*semantics, "surfaces", at);
    if (!surfaces.is_array()) fail(at + ".surfaces", "expected an array");
    for (size_t i = 0; i < surfaces.size(); ++i) {
      const std::string s = at + ".surfaces[" + std::to_string(i) + "]";
      if (!surfaces[i].is_object()) fail(s, "expected a semantic surface object");
      const json& type = member(surfaces[i], "type", s);
      if (!type.is_string()) fail(s + ".type", "expected a string");
      types.push_back(type.get<std::string>());
    }
    return types;
  }

  // The values of the chosen theme of a geometry's "material" or "texture" member
  // ({"values": [...]} or {"value": i}), or null. `chosen`: the theme taken so far for
  // this kind (the scene's, else the first the file gives), set on the first meeting.
  const json* theme_values(const json& geometry, const char* kind, const std::string& path, std::string& chosen,
                           CityModel& model) const {
    const auto themes = geometry.find(kind);
    if (!options_.appearance.read || themes == geometry.end()) return nullptr;
    const std::string at = path + "." + kind;
    if (!themes->is_object()) fail(at, "expected an object of themes");
    for (const auto& [name, value] : themes->items())
      if (std::find(model.appearance_themes.begin(), model.appearance_themes.end(), name) ==
          model.appearance_themes.end())
        model.appearance_themes.push_back(name);
    if (themes->empty()) return nullptr;
    const std::string& wanted = !options_.appearance.theme.empty() ? options_.appearance.theme
                                : !chosen.empty()                  ? chosen
                                                                   : themes->begin().key();
    const auto theme = themes->find(wanted);
    if (theme == themes->end()) return nullptr;
    chosen = wanted;
    if (!theme->is_object()) fail(at + "." + wanted, "expected a theme with value or values");
    if (theme->contains("values")) return &(*theme)["values"];
    if (theme->contains("value")) return &(*theme)["value"];
    fail(at + "." + wanted, "a theme needs value or values");
  }

  struct Context {
    const VertexList* vertices;
    const Instance* instance;
    std::vector<std::string> semantic_types;
    CityObject* object;
    size_t materials, textures;  // the model's appearance materials and textures
  };

  // The semantic, material and texture values alongside a level of the boundaries; any
  // may be null (no value).
  struct SurfaceValues {
    const json* semantic = nullptr;
    const json* material = nullptr;
    const json* texture = nullptr;
  };

  // Descends `depth` levels of boundaries to the surfaces, with their values alongside.
  void walk(const json& boundaries, int depth, const SurfaceValues& values, const std::string& path,
            const Context& context) const {
    if (!boundaries.is_array()) fail(path, "expected an array");
    for (size_t i = 0; i < boundaries.size(); ++i) {
      const std::string at = path + "[" + std::to_string(i) + "]";
      SurfaceValues inner;
      inner.semantic = child(values.semantic, i, at, "semantics.values");
      inner.material = values.material && values.material->is_number()
                           ? values.material
                           : child(values.material, i, at, "material values");
      inner.texture = child(values.texture, i, at, "texture values");
      if (depth > 1)
        walk(boundaries[i], depth - 1, inner, at, context);
      else
        read_surface(boundaries[i], inner, at, context);
    }
  }

  const json* child(const json* values, size_t i, const std::string& path, const char* what) const {
    if (!values || values->is_null()) return nullptr;
    if (!values->is_array()) fail(path, std::string("the ") + what + " do not match the boundaries");
    if (i >= values->size()) fail(path, std::string("the ") + what + " have no entry for this surface");
    return &(*values)[i];
  }

  void read_surface(const json& surface, const SurfaceValues& values, const std::string& path,
                    const Context& context) const {
    if (!surface.is_array() || surface.empty()) fail(path, "expected a surface: an array of rings");
    CitySurface out;
    const json* semantic = values.semantic;
    if (semantic && !semantic->is_null()) {
      if (!semantic->is_number_unsigned() || semantic->get<size_t>() >= context.semantic_types.size())
        fail(path, "semantic value " + describe_json_value(*semantic) + " is not one of the geometry's " +
                       std::to_string(context.semantic_types.size()) + " semantic surfaces");
      out.semantic = context.semantic_types[semantic->get<size_t>()];
    }
    const json* material = values.material;
    if (material && !material->is_null()) {
      const size_t count = context.materials;
      if (!material->is_number_unsigned() || material->get<size_t>() >= count)
        fail(path, "material " + describe_json_value(*material) + " is not one of the file's " + std::to_string(count) +
                       " appearance materials");
      out.material = static_cast<int>(material_base_ + material->get<size_t>());
    }
    for (size_t r = 0; r < surface.size(); ++r) {
      const std::string at = path + "[" + std::to_string(r) + "]";
      const json& ring = surface[r];
      if (!ring.is_array()) fail(at, "expected a ring: an array of vertex indices");
      if (ring.empty()) fail(at, "a ring without points");
      std::vector<Vec3> points;
      points.reserve(ring.size());
      for (size_t k = 0; k < ring.size(); ++k) {
        Vec3 p = vertex_at(ring[k], *context.vertices, at + "[" + std::to_string(k) + "]");
        if (context.instance) p = instanced(p, *context.instance);
        points.push_back(p);
      }
      out.rings.push_back(std::move(points));
    }
    if (values.texture && !values.texture->is_null()) read_texture_values(*values.texture, path, context, out);
    drop_holes_of_fewer_than_three_points(out);
    context.object->surfaces.push_back(std::move(out));
  }

  // A ring of one or two points encloses nothing. Real files hold such rings, and
  // refusing the file lost a whole district for one (CityGML's reader met them first;
  // docs/citygml.md): a hole of them is dropped with its texture coordinates, and an
  // exterior of them is kept, its surface then counted among those of zero area
  // (city_placement.h). Its indices and texture values were checked all the same.
  static void drop_holes_of_fewer_than_three_points(CitySurface& surface) {
    for (size_t r = surface.rings.size(); r-- > 1;) {
      if (surface.rings[r].size() >= 3) continue;
      surface.rings.erase(surface.rings.begin() + static_cast<std::ptrdiff_t>(r));
      if (!surface.texture_coordinates.empty())
        surface.texture_coordinates.erase(surface.texture_coordinates.begin() + static_cast<std::ptrdiff_t>(r));
    }
  }

  // A surface's texture values: per ring [texture, uv index per point], or [null]; a
  // surface without a texture, holes or not, is [[null]] (CityJSON 2.0, §Texture).
  void read_texture_values(const json& rings, const std::string& path, const Context& context,
                           CitySurface& surface) const {
    if (rings.is_array() && rings.size() == 1 && rings[0].is_array() && rings[0].size() == 1 && rings[0][0].is_null())
      return;
    if (!rings.is_array() || rings.size() != surface.rings.size())
      fail(path, "the texture values give " + (rings.is_array() ? std::to_string(rings.size()) : std::string("no")) +
                     " rings for a surface of " + std::to_string(surface.rings.size()));
    for (size_t r = 0; r < rings.size(); ++r) {
      const std::string at = path + "[" + std::to_string(r) + "]";
      const json& values = rings[r];
      if (!values.is_array() || values.empty()) fail(at, "expected texture values [texture, uv, uv, ...] or [null]");
      std::vector<std::array<float, 2>> uvs(surface.rings[r].size(), {0.0F, 0.0F});
      if (!values[0].is_null()) {
        const size_t count = context.textures;
        if (!values[0].is_number_unsigned() || values[0].get<size_t>() >= count)
          fail(at, "texture " + describe_json_value(values[0]) + " is not one of the file's " + std::to_string(count) +
                       " textures");
        if (values.size() != uvs.size() + 1)
          fail(at, "the texture values give " + std::to_string(values.size() - 1) + " coordinates for a ring of " +
                       std::to_string(uvs.size()) + " points");
        if (surface.texture == CitySurface::kNone)
          surface.texture = static_cast<int>(texture_base_ + values[0].get<size_t>());
        for (size_t k = 0; k < uvs.size(); ++k) {
          const json& index = values[k + 1];
          if (!index.is_number_unsigned() || index.get<uint64_t>() >= texture_vertices_.size())
            fail(at + "[" + std::to_string(k + 1) + "]", "texture vertex " + describe_json_value(index) +
                                                             " is out of range (the file has " +
                                                             std::to_string(texture_vertices_.size()) + ")");
          uvs[k] = texture_vertices_[index.get<size_t>()];
        }
      }
      surface.texture_coordinates.push_back(std::move(uvs));
    }
    if (surface.texture == CitySurface::kNone) surface.texture_coordinates.clear();
  }

  Vec3 vertex_at(const json& index, const VertexList& vertices, const std::string& path) const {
    if (!index.is_number_unsigned() || index.get<uint64_t>() >= vertices.points.size())
      fail(path, "vertex index " + describe_json_value(index) + " is out of range (the file has " +
                     std::to_string(vertices.points.size()) + " vertices)");
    return vertices.points[index.get<size_t>()];
  }

  static Vec3 instanced(const Vec3& p, const Instance& instance) {
    const auto& m = instance.matrix;  // row-major 4 × 4
    return Vec3{m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3], m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7],
                m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]} +
           instance.reference;
  }

  std::string source_;
  CityJsonOptions options_;
  std::array<double, 3> scale_{1, 1, 1}, translate_{0, 0, 0};
  bool quantised_ = false;
  std::vector<std::array<float, 2>> texture_vertices_;
  // Where the current appearance's materials and textures begin in the model.
  size_t material_base_ = 0, texture_base_ = 0;
  const json* templates_ = nullptr;
  VertexList template_vertices_;
};

void expect_type(const Reader& reader, const json& document, const char* type, const std::string& path) {
  if (!document.is_object())
    reader.fail(path.empty() ? "(document)" : path, std::string("expected a ") + type + " object");
  const auto it = document.find("type");
  if (it == document.end() || *it != type)
    reader.fail(
        (path.empty() ? "" : path + ".") + "type",
        std::string("expected \"") + type + "\", found " + (it == document.end() ? "none" : describe_json_value(*it)));
}

CityModel read_document(const std::string& text, const std::string& source, const CityJsonOptions& options) {
  const json document = parse_json_text(text, source);
  Reader reader(source, options);
  expect_type(reader, document, "CityJSON", "");
  CityModel model;
  model.easting_first = true;
  reader.read_transform(document);
  model.crs = reader.read_crs(document);
  reader.read_appearance(document, model);
  reader.read_templates(document);
  const VertexList vertices =
      reader.read_vertices(reader.member(document, "vertices", "(document)"), "vertices", reader.quantised());
  reader.read_objects(reader.member(document, "CityObjects", "(document)"), vertices, "CityObjects", model);
  return model;
}

// CityJSONSeq: the first line a CityJSON object (transform, metadata), then one
// CityJSONFeature per line with its own vertices.
CityModel read_sequence(const std::string& text, const std::string& source, const CityJsonOptions& options) {
  CityModel model;
  model.easting_first = true;
  json header_document;  // kept: the header's templates are read from it
  std::optional<Reader> header;
  size_t line_number = 0;
  for (size_t start = 0; start < text.size();) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(start, end - start);
    start = end + 1;
    ++line_number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::string where = source + ":" + std::to_string(line_number);
    if (!header) {
      header_document = parse_json_text(line, where);
      header.emplace(where, options);
      expect_type(*header, header_document, "CityJSON", "");
      header->read_transform(header_document);
      model.crs = header->read_crs(header_document);
      header->read_appearance(header_document, model);
      header->read_templates(header_document);
      continue;
    }
    const json feature = parse_json_text(line, where);
    Reader reader = header->for_source(where);  // messages name this line
    expect_type(reader, feature, "CityJSONFeature", "");
    reader.read_appearance(feature, model);  // a feature's own, if it has one
    const VertexList vertices =
        reader.read_vertices(reader.member(feature, "vertices", "(feature)"), "vertices", reader.quantised());
    reader.read_objects(reader.member(feature, "CityObjects", "(feature)"), vertices, "CityObjects", model);
  }
  if (!header) throw InputError(source + ":1: empty CityJSONSeq: expected a CityJSON header line");
  return model;
}

}  // namespace

std::optional<int> parse_lod(const std::string& text) {
  // "2", "2.2", "2.0" (version 1.0's numbers as printed by std::to_string: "2.000000").
  int whole = 0, fraction = 0;
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  auto [p, error] = std::from_chars(begin, end, whole);
  if (error != std::errc() || whole < 0 || whole > 4) return std::nullopt;
  if (p != end) {
    if (*p != '.' || p + 1 == end) return std::nullopt;
    auto [q, e2] = std::from_chars(p + 1, p + 2, fraction);
    if (e2 != std::errc() || fraction > 3) return std::nullopt;
    for (const char* r = q; r != end; ++r)
      if (*r != '0') return std::nullopt;
  }
  return whole * 10 + fraction;
}

CityModel read_cityjson_text(const std::string& text, const std::string& source, const CityJsonOptions& options) {
  return lower_case_extension(source) == ".jsonl" ? read_sequence(text, source, options)
                                                  : read_document(text, source, options);
}

CityModel read_cityjson_file(const std::filesystem::path& file, const CityJsonOptions& options) {
  return read_cityjson_text(read_text_file(file, "city model", kMaxCityFileBytes), file.string(), options);
}

}  // namespace skylit
