// Texture images (io/model/texture_file.h): PNG and JPEG bytes as a glTF buffer or data
// URI hands them over, decoded by stb_image into a mip-mapped texture.
#include "fuzz_support.h"
#include "skylit/io/model/texture_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return skylit::fuzz::accept_input_errors(
      [&] { skylit::decode_texture(data, size, skylit::TextureEncoding::srgb, "texture"); });
}
