// Wavefront OBJ geometry through tinyobjloader: positions and faces only. Polygons
// are split into triangles; lines, points, normals, UVs and materials are ignored.
// Vertex lines are also read here, in double precision, because tinyobjloader
// (Debian's float build) reads an unparsable number such as "nan" as 0 without a
// word, and rounds site coordinates (e.g. 500123.25 m east) to float.
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include <tiny_obj_loader.h>

#include "skylit/core/error.h"
#include "skylit/io/model/mesh_io.h"

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

}  // namespace

TriangleMesh load_obj_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(name + ": cannot open the file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw InputError(name + ": cannot read the file");
  const std::string text = std::move(buffer).str();
  std::vector<Vec3> positions = read_positions(text, name);

  // Parsing from a string makes tinyobjloader skip `mtllib`: materials come from
  // the scene file, and a missing .mtl must not stop the load.
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(text, "", config))
    throw InputError(name + ": cannot parse OBJ: " + one_line(reader.Error()));
  // tinyobjloader drops faces with bad indices with only a warning; a silently
  // missing wall would be worse than an error.
  if (reader.Warning().find("invalid vertex index") != std::string::npos)
    throw InputError(name + ": a face refers to a vertex that does not exist");

  TriangleMesh mesh;
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
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const auto& indices = shape.mesh.indices;
    size_t first = 0;
    for (unsigned char n : shape.mesh.num_face_vertices) {
      if (first + n > indices.size()) throw InputError(name + ": inconsistent face list");
      // Faces are triangles after triangulation; fan-split anything else anyway.
      for (size_t k = 1; k + 1 < n; ++k)
        mesh.triangles.push_back({vertex(indices[first]), vertex(indices[first + k]), vertex(indices[first + k + 1])});
      first += n;
    }
  }
  return mesh;
}

}  // namespace skylit
