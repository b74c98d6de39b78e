// EnergyPlus weather files (io/weather/epw_reader.h), from bytes, and the hour
// selection on what they hold.
#include "fuzz_support.h"
#include "skylit/io/weather/epw_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(skylit::fuzz::text_of(data, size));
  return skylit::fuzz::accept_input_errors([&] {
    const skylit::EpwFile file = skylit::parse_epw(text, "fuzz.epw");
    skylit::epw_hour_containing(file, 6, 21, 0, 0, "fuzz");
  });
}
