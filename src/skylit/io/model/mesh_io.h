// Loading triangle meshes from files: glTF 2.0 (.gltf, .glb) and Wavefront OBJ with
// its MTL libraries. Geometry, each triangle's material with its textures (PNG, JPEG, BMP, TGA),
// texture coordinates and the file's vertex normals are read; cameras, lights and
// animation in the file are ignored.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "skylit/geometry/triangle_mesh.h"
#include "skylit/geometry/vertex_normals.h"
#include "skylit/material/model_material.h"

namespace skylit {

// Which axis is "up" in the file. glTF says +Y (its spec); many OBJ exporters too.
// Files with +Y up are turned into skylit's +Z-up frame by (x, y, z) → (x, -z, y):
// x stays east, the file's up becomes +z, and the file's +z (glTF's "front")
// faces south (-y). A proper rotation, so winding and normals are kept.
enum class UpAxis { y, z };

// A model file's triangles and the materials it gives them.
struct LoadedModel {
  static constexpr int32_t kNoMaterial = -1;
  TriangleMesh mesh;
  std::vector<ModelMaterial> materials;
  // Per triangle of `mesh`: an index into `materials`, or kNoMaterial where the file
  // gives none (the scene's object material is used there).
  std::vector<int32_t> triangle_material;
  // Per triangle of `mesh`, its corners' texture coordinates (zero where the file gives
  // none); empty when the file gives none at all.
  std::vector<CornerUvs> corner_uvs;
  // Per triangle of `mesh`, the file's own normals at its corners (glTF NORMAL, OBJ vn),
  // made safe by sanitize_file_normals (flat where the file gives none); empty when the
  // file gives none at all.
  std::vector<CornerNormals> corner_normals;
  // Material libraries (OBJ `mtllib`) the file names that could not be read (their
  // triangles get kNoMaterial), and texture images (their materials are used without
  // them).
  std::vector<std::string> missing_libraries;
  std::vector<std::string> missing_images;
  // glTF primitives and OBJ elements (`p`, `l`) of points or lines, which are not
  // surfaces and are not drawn.
  int skipped_primitives = 0;
  // Where the file was read other than by its format's letter, because read so it would
  // describe what no model means (MTL's `Tr 1` from MeshLab): one line each, naming the
  // file and the rule, for `skylit info` and `render` to warn with.
  std::vector<std::string> read_warnings;
};

// Per-corner data (texture coordinates) kept with its corners when a mirroring
// transform reverses the triangles' winding (geometry/transform.h, transformed(): corners
// 1 and 2 trade places).
template <typename Corners>
void reverse_corner_order(std::vector<Corners>& per_triangle) {
  for (Corners& c : per_triangle) std::swap(c[1], c[2]);
}

// The largest mesh file (OBJ, glTF, GLB, or a glTF buffer) read, bytes: 1 GiB, a city
// model of tens of millions of triangles. Only regular files are read (not folders,
// devices, FIFOs).
inline constexpr std::uintmax_t kMaxMeshFileBytes = std::uintmax_t{1} << 30;

// Loads every triangle of the file in metres, in skylit's frame. The format comes
// from the extension (.gltf, .glb, .obj; any case). For glTF, the node hierarchy
// of the default scene (else scene 0, else every root node) is applied, morph targets
// at their default weights, and the primitives of triangles, triangle strips and fans
// are taken; points and lines are skipped (and counted). Throws InputError, naming the
// file, when it is missing or unreadable, cannot be parsed, has an index out of range or
// a non-finite coordinate, holds no triangles, or has an unknown extension.
// A material library the file names that cannot be read is not an error: its
// triangles get kNoMaterial.
LoadedModel load_model_file(const std::filesystem::path& path, UpAxis up_axis);
// The geometry alone.
TriangleMesh load_mesh_file(const std::filesystem::path& path, UpAxis up_axis);

// The loaders behind load_model_file: the file's own axes, indices checked, but
// emptiness and non-finite coordinates are left to load_model_file. Throw InputError.
LoadedModel load_obj_file(const std::filesystem::path& path);
LoadedModel load_gltf_file(const std::filesystem::path& path);  // .gltf or .glb

}  // namespace skylit
