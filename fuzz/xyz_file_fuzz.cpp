// Shards' exact XYZ images (io/image/xyz_file.h), from bytes.
#include "fuzz_support.h"
#include "skylit/io/image/xyz_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(skylit::fuzz::text_of(data, size));
  return skylit::fuzz::accept_input_errors([&] { skylit::decode_xyz_file(bytes, "fuzz.xyz"); });
}
