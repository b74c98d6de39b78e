// Wavefront OBJ geometry as the file writes it, read in one pass: positions in double
// precision, texture coordinates, normals, faces with their corners' indices and the
// `usemtl` name in force for each face, and the `mtllib` lines. Index semantics are
// tinyobjloader's (which the project used before): positive indices count from 1,
// negative ones back from the last element read so far. Materials are not read here
// (obj_loader.cpp reads the libraries with tinyobjloader's MTL reader).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "skylit/core/huge_pages.h"
#include "skylit/core/vec3.h"

namespace skylit {

// One corner of a face: 0-based indices into the file's v, vt and vn lists; -1 when the
// corner gives none. An index may lie outside its list (the reader checks).
struct ObjCorner {
  int32_t vertex = -1;
  int32_t texcoord = -1;
  int32_t normal = -1;
};

// The per-vertex and per-face arrays of a large model are tens of MB each, new memory
// as they grow: in 2 MiB pages (core/huge_pages.h).
struct ObjGeometry {
  std::vector<Vec3> positions;                     // `v` (moved into the mesh)
  HugePageVector<std::array<float, 2>> texcoords;  // `vt` (u, v) as written (v up)
  HugePageVector<std::array<float, 3>> normals;    // `vn` as written
  HugePageVector<ObjCorner> corners;               // all faces' corners, face after face
  HugePageVector<uint32_t> face_ends;              // per face: one past its last corner
  HugePageVector<int32_t> face_material_names;     // per face: index in material_names, -1 before any usemtl
  std::vector<std::string> material_names;         // distinct `usemtl` names in order of use
  std::vector<std::string> material_libraries;     // each `mtllib` line's text after the keyword, trimmed
  int points_and_lines = 0;                        // `p` and `l` elements, which are not surfaces
};

// Throws InputError naming `file_name` and the line for a vertex that is not three
// finite numbers and for a face corner that is not an index (or is 0). Lines it does not
// know (o, g, s, l, p, comments) are skipped.
ObjGeometry parse_obj(std::string_view text, const std::string& file_name);

}  // namespace skylit
