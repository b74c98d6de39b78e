// Wavefront OBJ meshes (io/model/mesh_io.h). The loader reads files, so the bytes
// are written to one first, as a user's file would be.
#include "fuzz_support.h"
#include "skylit/io/model/mesh_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto file = skylit::fuzz::write_file("mesh.obj", skylit::fuzz::text_of(data, size));
  return skylit::fuzz::accept_input_errors([&] { skylit::load_mesh_file(file, skylit::UpAxis::y); });
}
