// Wavefront OBJ models: geometry from our one-pass reader (obj_parser.h), materials
// from the `mtllib` libraries beside the file through tinyobjloader's MTL reader.
// Polygons, concave ones too, are split into triangles by our ear clipping
// (geometry/polygon_triangulation.h). Each face takes its `usemtl` material
// (docs/model-materials.md gives the mapping), with its `map_Kd`, `map_Ke`, `map_d`
// (cut-outs) and normal-map (`norm`, `map_Bump` holding a normal map) textures, the
// faces' texture coordinates and their `vn` normals. Lines and points are ignored.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <tiny_obj_loader.h>

#include "skylit/core/error.h"
#include "skylit/core/formatted.h"
#include "skylit/core/text_file.h"
#include "skylit/geometry/polygon_triangulation.h"
#include "skylit/io/model/mesh_io.h"
#include "skylit/io/model/obj_parser.h"
#include "skylit/io/model/texture_file.h"

namespace skylit {
namespace {

// A file an OBJ or MTL names, beside it: as written, else with Windows' backslashes read
// as slashes ("map_Kd .\textures\brick.jpg", as Windows exporters write it), else by its
// bare file name beside the model (an absolute path of the exporting machine,
// "C:\Users\arch\Documents\brick.jpg", with the file handed over beside the model, as
// most importers find it); as written if none is there.
std::filesystem::path beside(const std::filesystem::path& dir, const std::string& name) {
  std::error_code ec;
  if (std::filesystem::exists(dir / name, ec)) return dir / name;
  std::string slashed = name;
  std::replace(slashed.begin(), slashed.end(), '\\', '/');
  if (std::filesystem::exists(dir / slashed, ec)) return dir / slashed;
  const size_t last = slashed.find_last_of('/');
  if (last != std::string::npos && last + 1 < slashed.size()) {
    std::filesystem::path bare = dir / slashed.substr(last + 1);
    if (std::filesystem::exists(bare, ec)) return bare;
  }
  return dir / name;
}

// A material library the file names, read beside it.
struct MtlLibrary {
  std::string name;  // as the `mtllib` line gives it
  std::string text;
};

// Every library the `mtllib` lines name, read beside the file. A name with spaces is
// tried whole first, then as several names. Libraries that cannot be read are listed in
// `missing`.
std::vector<MtlLibrary> read_material_libraries(const std::vector<std::string>& mtllib_lines,
                                                const std::filesystem::path& dir, std::vector<std::string>& missing) {
  std::vector<MtlLibrary> libraries;
  const auto read = [&](const std::string& file) {
    std::error_code ec;  // a folder, device or FIFO is not read (a FIFO would block)
    const std::filesystem::path path = beside(dir, file);
    if (!std::filesystem::is_regular_file(path, ec)) return false;
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::ostringstream buffer;
    buffer << in.rdbuf();
    // A byte order mark hid the first newmtl.
    libraries.push_back({file, std::string(without_byte_order_mark(buffer.str())) + '\n'});
    return true;
  };
  for (const std::string& names : mtllib_lines) {
    if (names.empty() || read(names)) continue;
    std::istringstream words(names);
    for (std::string word; words >> word;)
      if (!read(word)) missing.push_back(word);
  }
  return libraries;
}

// Per material, in the order tinyobjloader's LoadMtl lists them: the library that
// defines it and whether it gives `d`. LoadMtl reads `Tr` as 1 − d unless the material
// gives `d`, and does not say which of the two it read. Lines are split and recognised
// as LoadMtl splits and recognises them, the libraries read as one text.
struct MtlDefinition {
  std::string library;
  bool gives_d = false;
};

std::vector<MtlDefinition> mtl_definitions(const std::vector<MtlLibrary>& libraries) {
  const auto blank = [](char c) { return c == ' ' || c == '\t'; };
  std::vector<MtlDefinition> out;
  MtlDefinition current;  // before any newmtl, LoadMtl's unnamed default, listed only at the end
  bool named = false;
  for (const MtlLibrary& library : libraries) {
    for (std::string_view text = library.text; !text.empty();) {
      const size_t end = std::min(text.find_first_of("\r\n"), text.size());
      std::string_view line = text.substr(0, end);
      text.remove_prefix(std::min(text.substr(end, 2) == "\r\n" ? end + 2 : end + 1, text.size()));
      while (!line.empty() && blank(line.back())) line.remove_suffix(1);
      line = line.substr(0, line.find('\0'));  // LoadMtl reads the trimmed line as a C string
      while (!line.empty() && blank(line.front())) line.remove_prefix(1);
      if (line.size() > 6 && line.starts_with("newmtl") && blank(line[6])) {
        if (named) out.push_back(current);
        current = {library.name, false};
        named = line.size() > 7;  // LoadMtl lists a material without a name only last
      } else if (line.size() > 1 && line[0] == 'd' && blank(line[1])) {
        current.gives_d = true;
      }
    }
  }
  out.push_back(current);
  return out;
}

double largest(const tinyobj::real_t* rgb) { return std::max({rgb[0], rgb[1], rgb[2]}); }

bool transparent_illum(const tinyobj::material_t& m) {
  return m.illum == 4 || m.illum == 6 || m.illum == 7 || m.illum == 9;
}

// MeshLab writes `Tr` as an opacity, Tr 1 for opaque: read as tinyobjloader reads it,
// 1 − d, that is a pane that lets all light through and reflects nothing, which no
// model means. So a Tr of 0.99 or more with no `d`, no transparent illum and no map_d
// is taken as MeshLab's (docs/model-materials.md).
bool tr_is_meshlab_opacity(const tinyobj::material_t& m, const MtlDefinition& definition) {
  return !definition.gives_d && m.dissolve <= 0.01 && !transparent_illum(m) && m.alpha_texname.empty();
}

// MTL's parameters onto skylit's kinds (docs/model-materials.md). Colours are
// taken as linear reflectances, as exporters write them (Blender's base colour, say).
ModelMaterial model_material(const tinyobj::material_t& m) {
  ModelMaterial out;
  out.name = m.name;
  out.color_linear = {m.diffuse[0], m.diffuse[1], m.diffuse[2]};
  // Ni 1 (or nonsense) is what exporters write when they mean "not set".
  out.ior = m.ior >= 1.05 && m.ior <= 3.0 ? m.ior : 1.5;
  out.roughness =
      m.roughness > 0 ? beckmann_from_gltf_roughness(m.roughness) : beckmann_from_phong_exponent(m.shininess);
  // With a map_d, d and illum describe the cut-outs it makes (foliage cards, railings:
  // exporters write "d 0" beside the mask), not a pane of glass.
  const bool cut_out = !m.alpha_texname.empty();
  if (!cut_out && (m.dissolve < 0.99 || transparent_illum(m))) {  // d, or Tr = 1 − d
    out.kind = ModelMaterial::Kind::glass;
    out.roughness = 0;             // window glass is flat; Ns describes a highlight's size, not a pane
  } else if (m.metallic >= 0.5) {  // the PBR extension's Pm
    out.kind = ModelMaterial::Kind::metal;
  } else if (largest(m.specular) > 0.1 && largest(m.diffuse) < 0.01) {  // all specular: a metal coloured Ks
    out.kind = ModelMaterial::Kind::metal;
    out.color_linear = {m.specular[0], m.specular[1], m.specular[2]};
  } else if (largest(m.specular) > 0 && m.illum >= 2) {  // a highlight: a coat over the body
    out.kind = ModelMaterial::Kind::coated;
  } else {
    out.kind = ModelMaterial::Kind::diffuse;
  }
  // Ke is taken as cd/m² per channel, as glTF's emission (docs/model-materials.md).
  out.emission_cd_m2 = {m.emission[0], m.emission[1], m.emission[2]};
  return out;
}

// A texture an MTL names, read once per file name from the model's folder; null for
// none, and for a file that cannot be found (listed in `missing`).
class ObjTextures {
 public:
  ObjTextures(std::filesystem::path folder, std::vector<std::string>& missing)
      : folder_(std::move(folder)), missing_(missing) {}

  // `clamp`: the map's -clamp on (its edge texels outside [0, 1], not the image repeated).
  std::shared_ptr<const Texture> get(const std::string& name, TextureEncoding encoding = TextureEncoding::srgb,
                                     bool clamp = false) {
    if (name.empty()) return nullptr;
    auto [it, added] = cache_.try_emplace({name, encoding, clamp});
    if (!added) return it->second;
    if (clamp) {
      if (const std::shared_ptr<const Texture> repeated = get(name, encoding))
        it->second = std::make_shared<const Texture>(
            repeated->with_wrap(TextureWrap::clamp_to_edge, TextureWrap::clamp_to_edge));
      return it->second;
    }
    std::error_code ec;
    const std::filesystem::path file = beside(folder_, name);
    if (std::filesystem::is_regular_file(file, ec))
      it->second = read_texture_file(file, encoding);
    else if (std::find(missing_.begin(), missing_.end(), name) == missing_.end())
      missing_.push_back(name);
    return it->second;
  }

 private:
  std::filesystem::path folder_;
  std::vector<std::string>& missing_;
  std::map<std::tuple<std::string, TextureEncoding, bool>, std::shared_ptr<const Texture>> cache_;
};

// A map's -s and -o (scale and origin offset of its texture coordinates, u' = s·u + o, as
// Blender writes a material's mapping), taken from map_Kd for every map of the material.
struct UvScaleOffset {
  float su = 1, sv = 1, ou = 0, ov = 0;
};

UvScaleOffset uv_scale_offset(const tinyobj::texture_option_t& option) {
  auto finite_or = [](double x, float fallback) { return std::isfinite(x) ? static_cast<float>(x) : fallback; };
  return {finite_or(option.scale[0], 1), finite_or(option.scale[1], 1), finite_or(option.origin_offset[0], 0),
          finite_or(option.origin_offset[1], 0)};
}

// Whether a texture holds a tangent-space normal map rather than a height (bump) map:
// MTL's map_Bump names either, and exporters (Blender's among them) write normal maps
// there. A normal map's texels point mostly out of the surface, so its mean is bluish
// (z = 2b − 1 near 1, x and y near 0); a height map's is grey.
bool looks_like_normal_map(const Texture& t) {
  const Rgba m = t.mean();
  return m[2] > 0.75f && std::abs(m[0] - 0.5f) < 0.2f && std::abs(m[1] - 0.5f) < 0.2f;
}

// The texture and the material's cut-outs from map_d: its alpha where the image has
// any (a map_Kd with alpha, say), else its grey value (a black-and-white mask).
void set_alpha_map(const std::string& name, ObjTextures& textures, ModelMaterial& material) {
  std::shared_ptr<const Texture> mask = textures.get(name, TextureEncoding::linear);
  if (!mask) return;
  material.alpha_cutoff = 0.5;
  material.alpha_texture = mask;
  material.alpha_channel = mask->mean()[3] < 1.0f ? 3 : 0;
}

}  // namespace

LoadedModel load_obj_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  ObjGeometry obj = parse_obj(read_text_file(path, "OBJ file", kMaxMeshFileBytes), name);

  // The libraries are read here, so a missing one does not stop the load.
  LoadedModel model;
  const std::vector<MtlLibrary> libraries =
      read_material_libraries(obj.material_libraries, path.parent_path(), model.missing_libraries);
  std::string all_libraries;
  for (const MtlLibrary& library : libraries) all_libraries += library.text;
  std::istringstream libraries_text(all_libraries);
  std::map<std::string, int> material_ids;  // the first of two materials of one name wins
  std::vector<tinyobj::material_t> materials;
  std::string warnings, errors;
  tinyobj::LoadMtl(&material_ids, &materials, &libraries_text, &warnings, &errors);
  const std::vector<MtlDefinition> definitions = mtl_definitions(libraries);

  ObjTextures textures(path.parent_path(), model.missing_images);
  std::vector<UvScaleOffset> uv_transforms;  // per material
  for (size_t i = 0; i < materials.size(); ++i) {
    tinyobj::material_t m = materials[i];
    if (i < definitions.size() && tr_is_meshlab_opacity(m, definitions[i])) {
      model.read_warnings.push_back(
          "material library " + quote_name(definitions[i].library) + ", material " + quote_name(m.name) +
          formatted(": Tr %g without d read as MeshLab writes it, an opacity (opaque), not as 1 − d (clear glass)",
                    1.0 - m.dissolve));
      m.dissolve = 1;
    }
    ModelMaterial material = model_material(m);
    material.color_texture = textures.get(m.diffuse_texname, TextureEncoding::srgb, m.diffuse_texopt.clamp);
    material.emission_texture = textures.get(m.emissive_texname, TextureEncoding::srgb, m.emissive_texopt.clamp);
    uv_transforms.push_back(uv_scale_offset(m.diffuse_texopt));
    set_alpha_map(m.alpha_texname, textures, material);
    const bool normal_map = !m.normal_texname.empty();
    const std::string& normals = normal_map ? m.normal_texname : m.bump_texname;
    if (auto t = textures.get(normals, TextureEncoding::linear); t && (normal_map || looks_like_normal_map(*t))) {
      material.normal_texture = t;
      material.normal_scale = (normal_map ? m.normal_texopt : m.bump_texopt).bump_multiplier;
    }
    model.materials.push_back(std::move(material));
  }
  // Each usemtl name's material; none for a name no library defines.
  std::vector<int32_t> material_of_name;
  std::vector<std::string> undefined;
  for (const std::string& used : obj.material_names) {
    // The whole name as newmtl gives it ("Hard Shiny Plastic White", as Max2Mtl writes
    // it), else its first word, as tinyobjloader reads "usemtl Glass left over".
    auto it = material_ids.find(used);
    if (it == material_ids.end()) it = material_ids.find(used.substr(0, used.find_first_of(" \t")));
    material_of_name.push_back(it == material_ids.end() ? LoadedModel::kNoMaterial : it->second);
    if (it == material_ids.end() && !used.empty()) undefined.push_back(quote_name(used));
  }
  // Said unless a library was not found (which is warned of, and likely defines them).
  if (!undefined.empty() && model.missing_libraries.empty()) {
    model.read_warnings.push_back("usemtl " + first_few(undefined, 4) +
                                  (obj.material_libraries.empty() ? ", but no mtllib" : ": in no mtllib") +
                                  " of the file; those faces take the object's material");
  }

  const auto& texcoords = obj.texcoords;
  // A corner's (u, v), v turned over (OBJ's v runs up from the image's bottom row);
  // zero for a corner without one.
  // The material's -s and -o are applied before the turn.
  const auto uv = [&](const ObjCorner& corner, const UvScaleOffset& t) -> std::array<float, 2> {
    if (corner.texcoord < 0 || static_cast<size_t>(corner.texcoord) >= texcoords.size()) return {0.0f, 0.0f};
    const auto [u, v] = texcoords[static_cast<size_t>(corner.texcoord)];
    return {std::isfinite(u) ? t.su * u + t.ou : 0.0f, std::isfinite(v) ? 1.0f - (t.sv * v + t.ov) : 0.0f};
  };
  const bool any_uv = !texcoords.empty();
  const auto& file_normals = obj.normals;
  // A corner's vn; zero (flat, by sanitize_file_normals) for a corner without one.
  const auto normal = [&](const ObjCorner& corner) -> std::array<float, 3> {
    if (corner.normal < 0 || static_cast<size_t>(corner.normal) >= file_normals.size()) return {0.0f, 0.0f, 0.0f};
    return file_normals[static_cast<size_t>(corner.normal)];
  };
  const bool any_normal = !file_normals.empty();
  model.skipped_primitives = obj.points_and_lines;
  // Corners whose vt or vn index lies outside the file's data (three.js' verify.obj has
  // them): read as none, as viewers read them, and said.
  const auto outside = [](int32_t index, size_t count) {
    return index != -1 && (index < 0 || static_cast<size_t>(index) >= count);
  };
  const size_t corners_outside =
      static_cast<size_t>(std::count_if(obj.corners.begin(), obj.corners.end(), [&](const ObjCorner& c) {
        return outside(c.texcoord, texcoords.size()) || outside(c.normal, file_normals.size());
      }));
  if (corners_outside > 0)
    model.read_warnings.push_back(std::to_string(corners_outside) +
                                  " face corner(s) name a texture coordinate (vt) or normal (vn) the file does "
                                  "not have; read as none");
  TriangleMesh& mesh = model.mesh;
  mesh.vertices = std::move(obj.positions);
  // Most faces of big models are triangles or quads: room for quads without regrowing.
  const size_t face_count = obj.face_ends.size();
  mesh.triangles.reserve(2 * face_count);
  model.triangle_material.reserve(2 * face_count);
  if (any_uv) model.corner_uvs.reserve(2 * face_count);

  const auto vertex = [&](const ObjCorner& corner) {
    if (corner.vertex < 0 || static_cast<size_t>(corner.vertex) >= mesh.vertices.size())
      throw InputError(name + ": a face refers to a vertex that does not exist (the file has " +
                       std::to_string(mesh.vertices.size()) + ")");
    return static_cast<uint32_t>(corner.vertex);
  };
  std::vector<std::vector<Vec3>> rings(1);
  std::vector<uint32_t> face;
  size_t first = 0;
  for (size_t f = 0; f < face_count; ++f) {
    const size_t n = obj.face_ends[f] - first;
    const ObjCorner* corners = obj.corners.data() + first;
    const int32_t named = obj.face_material_names[f];
    const int32_t material = named < 0 ? LoadedModel::kNoMaterial : material_of_name[static_cast<size_t>(named)];
    const UvScaleOffset& uv_transform =
        material == LoadedModel::kNoMaterial ? UvScaleOffset{} : uv_transforms[static_cast<size_t>(material)];
    const size_t before = mesh.triangles.size();
    face.clear();
    rings[0].clear();
    for (size_t k = 0; k < n; ++k) face.push_back(vertex(corners[k]));
    const auto add = [&](size_t a, size_t b, size_t c) {
      mesh.triangles.push_back({face[a], face[b], face[c]});
      if (any_uv)
        model.corner_uvs.push_back(
            {uv(corners[a], uv_transform), uv(corners[b], uv_transform), uv(corners[c], uv_transform)});
      if (any_normal) model.corner_normals.push_back({normal(corners[a]), normal(corners[b]), normal(corners[c])});
    };
    if (n == 3) {
      add(0, 1, 2);
    } else if (n > 3) {
      for (uint32_t i : face) rings[0].push_back(mesh.vertices[i]);
      for (const TriangleIndices& t : triangulate_polygon_3d(rings)) add(t[0], t[1], t[2]);
    }
    model.triangle_material.insert(model.triangle_material.end(), mesh.triangles.size() - before, material);
    first = obj.face_ends[f];
  }
  return model;
}

}  // namespace skylit
