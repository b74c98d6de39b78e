// Loading triangle meshes from files: glTF 2.0 (.gltf, .glb) and Wavefront OBJ.
// Only geometry is read; materials, normals, UVs, textures, cameras, lights and
// animation in the file are ignored (the scene file gives each object one material).
#pragma once

#include <filesystem>

#include "skylit/geometry/triangle_mesh.h"

namespace skylit {

// Which axis is "up" in the file. glTF says +Y (its spec); many OBJ exporters too.
// Files with +Y up are turned into skylit's +Z-up frame by (x, y, z) → (x, -z, y):
// x stays east, the file's up becomes +z, and the file's +z (glTF's "front")
// faces south (-y). A proper rotation, so winding and normals are kept.
enum class UpAxis { y, z };

// Loads every triangle of the file in metres, in skylit's frame. The format comes
// from the extension (.gltf, .glb, .obj; any case). For glTF, the node hierarchy
// of the default scene (else scene 0, else every root node) is applied, and only
// triangle-list primitives (mode 4) are taken; points, lines, strips and fans are
// skipped. Throws InputError, naming the file, when it is missing or unreadable,
// cannot be parsed, has an index out of range or a non-finite coordinate, holds no
// triangles, or has an unknown extension.
TriangleMesh load_mesh_file(const std::filesystem::path& path, UpAxis up_axis);

// The loaders behind load_mesh_file: the file's own axes, indices checked, but
// emptiness and non-finite coordinates are left to load_mesh_file. Throw InputError.
TriangleMesh load_obj_file(const std::filesystem::path& path);
TriangleMesh load_gltf_file(const std::filesystem::path& path);  // .gltf or .glb

}  // namespace skylit
