// EULUMDAT photometric files (lights/eulumdat_reader.h), from bytes.
#include "fuzz_support.h"
#include "skylit/lights/eulumdat_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(skylit::fuzz::text_of(data, size));
  return skylit::fuzz::accept_input_errors([&] { skylit::parse_eulumdat(text, "fuzz.ldt"); });
}
