// glTF 2.0 meshes, text (.gltf) or binary (.glb) (io/model/mesh_io.h). The loader
// reads files, so the bytes are written to one first; input starting with the GLB
// magic "glTF" goes to a .glb file, anything else to a .gltf file.
#include "fuzz_support.h"
#include "skylit/io/model/mesh_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes = skylit::fuzz::text_of(data, size);
  const bool binary = bytes.substr(0, 4) == "glTF";
  const auto file = skylit::fuzz::write_file(binary ? "mesh.glb" : "mesh.gltf", bytes);
  return skylit::fuzz::accept_input_errors([&] { skylit::load_mesh_file(file, skylit::UpAxis::y); });
}
