// Mesh file dispatch by extension, the y-up → z-up turn, and the checks every
// loaded mesh must pass before it reaches the ray tracer (see mesh_io.h).
#include "skylit/io/model/mesh_io.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <system_error>

#include "skylit/core/error.h"
#include "skylit/core/file_names.h"

namespace skylit {
namespace {

// Embree stores single-precision coordinates, so a double that overflows float is
// as unusable as a NaN.
bool usable(double c) { return std::isfinite(c) && std::isfinite(static_cast<float>(c)); }

void check(const TriangleMesh& mesh, const std::filesystem::path& path) {
  if (mesh.triangles.empty()) throw InputError(path.string() + ": the file holds no triangles");
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3& v = mesh.vertices[i];
    if (!usable(v.x) || !usable(v.y) || !usable(v.z))
      throw InputError(path.string() + ": vertex " + std::to_string(i) +
                       " has a coordinate that is not a finite number");
  }
  // The loaders check indices already; this guards the ray tracer against a slip.
  for (const auto& t : mesh.triangles)
    for (uint32_t index : t)
      if (index >= mesh.vertices.size())
        throw InputError(path.string() + ": a triangle refers to vertex " + std::to_string(index) + " of " +
                         std::to_string(mesh.vertices.size()));
}

}  // namespace

TriangleMesh load_mesh_file(const std::filesystem::path& path, UpAxis up_axis) {
  return load_model_file(path, up_axis).mesh;
}

LoadedModel load_model_file(const std::filesystem::path& path, UpAxis up_axis) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path.string() + ": mesh file not found");
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path.string() + ": not a regular file");

  const std::string ext = lower_case_extension(path);
  LoadedModel model;
  if (ext == ".obj")
    model = load_obj_file(path);
  else if (ext == ".gltf" || ext == ".glb")
    model = load_gltf_file(path);
  else
    throw InputError(path.string() + ": unknown mesh file extension '" + path.extension().string() +
                     "' (expected .gltf, .glb or .obj)");

  if (up_axis == UpAxis::y) {
    for (Vec3& v : model.mesh.vertices) v = {v.x, -v.z, v.y};
    for (CornerNormals& corners : model.corner_normals)
      for (auto& n : corners) n = {n[0], -n[2], n[1]};
  }
  check(model.mesh, path);
  if (!model.corner_normals.empty()) {
    if (model.corner_normals.size() != model.mesh.triangles.size())  // a slip in a reader
      throw std::logic_error("load_model_file: normals per triangle are missing");
    sanitize_file_normals(model.mesh, model.corner_normals);
  }
  if (model.triangle_material.size() != model.mesh.triangles.size())  // a slip in a reader
    throw std::logic_error("load_model_file: a material per triangle is missing");
  if (!model.corner_uvs.empty() && model.corner_uvs.size() != model.mesh.triangles.size())
    throw std::logic_error("load_model_file: texture coordinates per triangle are missing");
  return model;
}

}  // namespace skylit
