// CityGML files (io/city/citygml_reader.h), parsed from the bytes in memory as the
// streaming reader parses a file's pieces; the appearances it gives are checked.
#include "city_fuzz_checks.h"
#include "fuzz_support.h"
#include "skylit/io/city/citygml_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return skylit::fuzz::accept_input_errors([&] {
    skylit::fuzz::check_city_appearances(skylit::parse_citygml(skylit::fuzz::text_of(data, size), "city.gml"));
  });
}
