// The `weather` and `sky` parts of a scene file: the conditions of one hour of an EPW
// weather file, and a CIE standard general sky in place of the model's (docs/weather.md).
#include <cstdio>

#include "skylit/core/error.h"
#include "skylit/io/scene/scene_parts.h"
#include "skylit/io/weather/epw_reader.h"
#include "skylit/io/weather/weather_conditions.h"
#include "skylit/sun/time.h"

namespace skylit {

namespace {

struct HourOfYear {
  int month, day, hour, minute;
};

// "MM-DDThh:mm", local standard time of the file.
HourOfYear parse_hour_of_year(const JsonReader& j) {
  const std::string text = j.string();
  HourOfYear h{};
  char tail = 0;
  if (text.size() != 11 ||
      std::sscanf(text.c_str(), "%2d-%2dT%2d:%2d%c", &h.month, &h.day, &h.hour, &h.minute, &tail) != 4 ||
      text[2] != '-' || text[5] != 'T' || text[8] != ':')
    j.fail_expected("an hour of the year as \"MM-DDThh:mm\" (local standard time), e.g. \"06-21T13:00\"");
  if (h.month < 1 || h.month > 12 || h.day < 1 || h.day > (h.month == 2 ? 29 : days_in_month(2001, h.month)) ||
      h.hour < 0 || h.hour > 23 || h.minute < 0 || h.minute > 59)
    j.fail("no such date or time: " + text);
  return h;
}

}  // namespace

void read_weather(const JsonReader& j, const std::filesystem::path& base_dir, Scene& scene,
                  const std::optional<SiteLocation>& site) {
  j.allow_only({"epw", "hour"});
  const std::filesystem::path file = base_dir / j.required("epw").string();
  const HourOfYear h = parse_hour_of_year(j.required("hour"));
  const EpwFile epw = read_epw(file);
  const EpwHour& record = epw_hour_containing(epw, h.month, h.day, h.hour, h.minute, j.source() + ": " + j.path());
  apply_weather_hour(epw, record, scene, site);
}

std::optional<CieSkySettings> read_sky(const JsonReader& j, bool weather_gives_diffuse) {
  j.allow_only({"type", "cie_type", "diffuse_horizontal_lux", "direct_sun"});
  const std::string type = j.required("type").one_of({"physical", "cie", "cie_overcast"});
  if (type == "physical") {
    for (const char* key : {"cie_type", "diffuse_horizontal_lux", "direct_sun"})
      if (j.has(key)) j.required(key).fail(std::string(key) + " is for a CIE sky (type \"cie\" or \"cie_overcast\")");
    return std::nullopt;
  }
  CieSkySettings sky;
  if (type == "cie_overcast") {
    if (j.has("cie_type")) j.required("cie_type").fail("\"cie_overcast\" is CIE type 1; give type \"cie\" for others");
  } else {
    sky.type = j.required("cie_type").integer_in(1, kCieSkyTypes);
  }
  // Types 1–6 are the standard's overcast and heavily clouded skies: the sun hidden.
  sky.direct_sun = j.has("direct_sun") ? j.required("direct_sun").boolean() : sky.type >= 7;
  if (auto lux = j.optional("diffuse_horizontal_lux"))
    sky.diffuse_horizontal_lux = lux->number_in(1e-6, 200000);
  else if (!weather_gives_diffuse)
    j.fail("a CIE sky needs diffuse_horizontal_lux (or a weather file's hour to take it from)");
  return sky;
}

}  // namespace skylit
