// CityJSON and CityJSONSeq city models (io/city/cityjson_reader.h), and the
// triangulation of what they give. The placement's PROJ step is left out: creating a
// transformation takes milliseconds, which would slow the search a hundredfold, and
// its input (finite coordinates) is what the reader guarantees. An input whose first
// byte is odd is read as a CityJSONSeq. The appearances it gives are checked.
#include "city_fuzz_checks.h"
#include "fuzz_support.h"
#include "skylit/geometry/polygon_triangulation.h"
#include "skylit/io/city/cityjson_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(skylit::fuzz::text_of(data, size));
  const bool sequence = size > 0 && (data[0] & 1) != 0;
  return skylit::fuzz::accept_input_errors([&] {
    const skylit::CityModel model = skylit::read_cityjson_text(text, sequence ? "f.city.jsonl" : "f.city.json");
    skylit::fuzz::check_city_appearances(model);
    for (const skylit::CityObject& object : model.objects)
      for (const skylit::CitySurface& surface : object.surfaces) skylit::triangulate_polygon_3d(surface.rings);
  });
}
