// Wavefront OBJ geometry through tinyobjloader: positions and faces only. Polygons,
// concave ones too, are split into triangles by our ear clipping
// (geometry/polygon_triangulation.h); tinyobjloader's own splitting cuts concave faces
// wrongly. Each face takes its `usemtl` material from the `mtllib` libraries beside
// the file (docs/model-materials.md gives the mapping), with its `map_Kd` and `map_Ke`
// textures and the faces' texture coordinates. Lines, points and normals are ignored.
// Vertex lines are also read here, in double precision, because tinyobjloader
// (Debian's float build) reads an unparsable number such as "nan" as 0 without a
// word, and rounds site coordinates (e.g. 500123.25 m east) to float.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <tiny_obj_loader.h>

#include "skylit/core/error.h"
#include "skylit/core/text_file.h"
#include "skylit/geometry/polygon_triangulation.h"
#include "skylit/io/model/mesh_io.h"
#include "skylit/io/model/texture_file.h"

namespace skylit {
namespace {

// tinyobjloader reports several problems on separate lines; the user gets one line.
std::string one_line(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// Positions of all `v` lines, in file order (the order faces index them). Throws
// InputError with the line number for a coordinate that is missing or not finite.
std::vector<Vec3> read_positions(const std::string& text, const std::string& name) {
  std::vector<Vec3> positions;
  size_t line_number = 0;
  for (size_t start = 0; start < text.size();) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    ++line_number;
    const char* p = text.data() + start;
    const char* const stop = text.data() + end;
    start = end + 1;
    while (p < stop && blank(*p)) ++p;
    if (stop - p < 2 || p[0] != 'v' || !blank(p[1])) continue;
    p += 2;
    double xyz[3];
    for (double& c : xyz) {
      while (p < stop && blank(*p)) ++p;
      if (p < stop && *p == '+') ++p;  // from_chars does not take a leading '+'
      const auto [next, ec] = std::from_chars(p, stop, c);
      if (ec != std::errc() || !std::isfinite(c) || (next < stop && !blank(*next)))
        throw InputError(name + ":" + std::to_string(line_number) +
                         ": a vertex needs three finite numbers: " + std::string(p, stop).substr(0, 40));
      p = next;
    }
    positions.emplace_back(xyz[0], xyz[1], xyz[2]);
  }
  return positions;
}

std::string trimmed(std::string_view s) {
  while (!s.empty() && (blank(s.front()) || s.front() == '\n')) s.remove_prefix(1);
  while (!s.empty() && (blank(s.back()) || s.back() == '\n')) s.remove_suffix(1);
  return std::string(s);
}

// The text of every `mtllib` the file names, read beside it. A name with spaces is
// tried whole first, then as several names. Libraries that cannot be read are listed
// in `missing`.
std::string read_material_libraries(const std::string& text, const std::filesystem::path& dir,
                                    std::vector<std::string>& missing) {
  std::string libraries;
  const auto read = [&](const std::string& file) {
    std::error_code ec;  // a folder, device or FIFO is not read (a FIFO would block)
    if (!std::filesystem::is_regular_file(dir / file, ec)) return false;
    std::ifstream in(dir / file, std::ios::binary);
    if (!in) return false;
    std::ostringstream buffer;
    buffer << in.rdbuf();
    libraries += buffer.str();
    libraries += '\n';
    return true;
  };
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    const std::string l = trimmed(line);
    if (l.rfind("mtllib", 0) != 0 || l.size() < 7 || !blank(l[6])) continue;
    const std::string names = trimmed(std::string_view(l).substr(7));
    if (read(names)) continue;
    std::istringstream words(names);
    for (std::string word; words >> word;)
      if (!read(word)) missing.push_back(word);
  }
  return libraries;
}

double largest(const tinyobj::real_t* rgb) { return std::max({rgb[0], rgb[1], rgb[2]}); }

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
  const bool transparent_illum = m.illum == 4 || m.illum == 6 || m.illum == 7 || m.illum == 9;
  if (m.dissolve < 0.99 || transparent_illum) {  // d, or Tr = 1 − d
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

  std::shared_ptr<const Texture> get(const std::string& name) {
    if (name.empty()) return nullptr;
    auto [it, added] = cache_.try_emplace(name);
    if (!added) return it->second;
    std::error_code ec;
    const std::filesystem::path file = folder_ / name;
    if (std::filesystem::is_regular_file(file, ec))
      it->second = read_texture_file(file, TextureEncoding::srgb);
    else
      missing_.push_back(name);
    return it->second;
  }

 private:
  std::filesystem::path folder_;
  std::vector<std::string>& missing_;
  std::map<std::string, std::shared_ptr<const Texture>> cache_;
};

}  // namespace

LoadedModel load_obj_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  const std::string text = read_text_file(path, "OBJ file", kMaxMeshFileBytes);
  std::vector<Vec3> positions = read_positions(text, name);

  // Parsing from strings: the libraries are read here, so a missing one does not stop
  // the load.
  LoadedModel model;
  const std::string libraries = read_material_libraries(text, path.parent_path(), model.missing_libraries);
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(text, libraries, config))
    throw InputError(name + ": cannot parse OBJ: " + one_line(reader.Error()));
  // tinyobjloader drops faces with bad indices with only a warning; a silently
  // missing wall would be worse than an error.
  if (reader.Warning().find("invalid vertex index") != std::string::npos)
    throw InputError(name + ": a face refers to a vertex that does not exist");

  ObjTextures textures(path.parent_path(), model.missing_libraries);
  for (const tinyobj::material_t& m : reader.GetMaterials()) {
    ModelMaterial material = model_material(m);
    material.color_texture = textures.get(m.diffuse_texname);
    material.emission_texture = textures.get(m.emissive_texname);
    model.materials.push_back(std::move(material));
  }
  const auto& texcoords = reader.GetAttrib().texcoords;
  // A corner's (u, v), v turned over (OBJ's v runs up from the image's bottom row);
  // zero for a corner without one.
  const auto uv = [&](const tinyobj::index_t& index) -> std::array<float, 2> {
    const auto i = static_cast<size_t>(index.texcoord_index);
    if (index.texcoord_index < 0 || 2 * i + 1 >= texcoords.size()) return {0.0f, 0.0f};
    const float u = texcoords[2 * i], v = texcoords[2 * i + 1];
    return {std::isfinite(u) ? u : 0.0f, std::isfinite(v) ? 1.0f - v : 0.0f};
  };
  const bool any_uv = !texcoords.empty();
  TriangleMesh& mesh = model.mesh;
  mesh.vertices = std::move(positions);
  // Should the two readers ever disagree on what is a vertex line (line
  // continuations, say), trust the one that also reads the faces.
  const auto& floats = reader.GetAttrib().vertices;
  if (mesh.vertices.size() != floats.size() / 3) {
    mesh.vertices.clear();
    for (size_t i = 0; i + 2 < floats.size(); i += 3)
      mesh.vertices.emplace_back(floats[i], floats[i + 1], floats[i + 2]);
  }

  const auto vertex = [&](const tinyobj::index_t& index) {
    if (index.vertex_index < 0 || static_cast<size_t>(index.vertex_index) >= mesh.vertices.size())
      throw InputError(name + ": a face refers to a vertex that does not exist (the file has " +
                       std::to_string(mesh.vertices.size()) + ")");
    return static_cast<uint32_t>(index.vertex_index);
  };
  std::vector<std::vector<Vec3>> rings(1);
  std::vector<uint32_t> face;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const auto& indices = shape.mesh.indices;
    size_t first = 0;
    for (size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
      const unsigned char n = shape.mesh.num_face_vertices[f];
      if (first + n > indices.size()) throw InputError(name + ": inconsistent face list");
      const int material = f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1;
      const size_t before = mesh.triangles.size();
      face.clear();
      rings[0].clear();
      for (size_t k = 0; k < n; ++k) {
        face.push_back(vertex(indices[first + k]));
        rings[0].push_back(mesh.vertices[face.back()]);
      }
      const auto add = [&](size_t a, size_t b, size_t c) {
        mesh.triangles.push_back({face[a], face[b], face[c]});
        if (any_uv)
          model.corner_uvs.push_back({uv(indices[first + a]), uv(indices[first + b]), uv(indices[first + c])});
      };
      if (n == 3)
        add(0, 1, 2);
      else
        for (const TriangleIndices& t : triangulate_polygon_3d(rings)) add(t[0], t[1], t[2]);
      const bool known = material >= 0 && static_cast<size_t>(material) < model.materials.size();
      model.triangle_material.insert(model.triangle_material.end(), mesh.triangles.size() - before,
                                     known ? material : LoadedModel::kNoMaterial);
      first += n;
    }
    // tinyobjloader counts a face's corners in a byte: a face of more than 255
    // corners leaves its indices unaccounted for.
    if (first != indices.size())
      throw InputError(name + ": a face has more than 255 corners, which the OBJ reader cannot take");
  }
  return model;
}

}  // namespace skylit
