// The `lights` part of a scene file (docs/lights.md): luminaires with a position, an
// aim and a rotation, an intensity distribution from an IES or EULUMDAT file or a
// simple shape, and a lamp type that gives their spectrum.
#include <cmath>
#include <stdexcept>
#include <string>

#include "skylit/core/error.h"
#include "skylit/core/text_file.h"
#include "skylit/io/scene/scene_parts.h"
#include "skylit/lights/eulumdat_reader.h"
#include "skylit/lights/headlamps.h"
#include "skylit/lights/ies_reader.h"
#include "skylit/lights/lamp_rows.h"
#include "skylit/lights/lamp_spectrum.h"
#include "skylit/spectrum/tabulated.h"

namespace skylit {

namespace {

// Lights a scene may hold, rows included: each costs an intensity map (0.5 MB) and its
// shadow volumes, so far fewer are practical; the limit keeps a typo in a spacing from
// asking for millions.
constexpr size_t kMaxSceneLights = 100000;

struct Photometry {
  IntensityDistribution distribution;
  TiltTable tilt;
  std::string source;  // for skylit info (SceneLight::source)
};

std::string rounded_lumens(double lumens) { return std::to_string(std::lround(lumens)) + " lm"; }

Photometry read_shape(const JsonReader& j) {
  const std::string shape = j.required("shape").one_of({"isotropic", "cosine", "spot"});
  const double candela = j.required("candela").number_in(0, kMaxLuminousIntensityCd);
  if (shape == "isotropic") return {IntensityDistribution::isotropic(candela), {}, "isotropic shape"};
  if (shape == "cosine") return {IntensityDistribution::cosine(candela), {}, "cosine shape"};
  const double inner = j.required("inner_deg").number_in(0, 180);
  const double outer = j.required("outer_deg").number_in(0, 180);
  if (outer < inner) j.required("outer_deg").fail("outer_deg must not be below inner_deg");
  return {IntensityDistribution::spot(candela, inner, outer), {}, "spot shape"};
}

Photometry read_photometry(const JsonReader& j, const std::filesystem::path& base_dir) {
  const int given = int(j.has("ies")) + int(j.has("ldt")) + int(j.has("shape"));
  if (given != 1) j.fail("a light needs exactly one of 'ies' (file), 'ldt' (file) or 'shape'");
  for (const char* key : {"inner_deg", "outer_deg"})
    if (j.has(key) && (!j.has("shape") || j.required("shape").string() != "spot"))
      j.required(key).fail("only a spot shape has cone angles");
  if (j.has("ies")) {
    const std::string file = j.required("ies").string();
    IesPhotometry ies = read_ies(base_dir / file);
    std::string source = quote_name(file) + " (" + ies.format;
    if (ies.rated_lumens() > 0) source += ", lamps rated " + rounded_lumens(ies.rated_lumens());
    return {std::move(ies.distribution), std::move(ies.tilt), source + ")"};
  }
  if (j.has("ldt")) {
    const std::string file = j.required("ldt").string();
    EulumdatPhotometry ldt = read_eulumdat(base_dir / file);
    std::string source = quote_name(file) + " (EULUMDAT, lamps " + rounded_lumens(ldt.lamp_sets.front().total_lumens);
    if (ldt.light_output_ratio > 0)
      source += ", light output ratio " + std::to_string(std::lround(ldt.light_output_ratio)) + " %";
    return {std::move(ldt.distribution), {}, source + ")"};
  }
  return read_shape(j);
}

LampSpectrumSettings read_lamp(const JsonReader& j, const std::filesystem::path& base_dir) {
  LampSpectrumSettings lamp;
  const JsonReader type = j.required("lamp");
  if (!lamp_type_from_name(type.string(), lamp.type))
    type.fail_expected(
        "a lamp type: high_pressure_sodium, colour_enhanced_sodium, metal_halide, "
        "metal_halide_4000k, metal_halide_hp5, led, halogen, incandescent, blackbody or table");
  const bool needs_temperature = lamp.type == LampType::kLed || lamp.type == LampType::kBlackbody;
  if (j.has("temperature_k") && !needs_temperature)
    j.required("temperature_k").fail("only an led or a blackbody lamp takes temperature_k");
  if (j.has("spectrum_file") != (lamp.type == LampType::kTable))
    j.fail("a lamp of type 'table' needs 'spectrum_file' (and only it takes one)");
  if (lamp.type == LampType::kLed)
    lamp.temperature_k =
        j.optional("temperature_k") ? j.required("temperature_k").number_in(kLedMinCctK, kLedMaxCctK) : 4000.0;
  if (lamp.type == LampType::kBlackbody) lamp.temperature_k = j.required("temperature_k").number_in(500, 25000);
  if (lamp.type == LampType::kTable) {
    const std::filesystem::path file = base_dir / j.required("spectrum_file").string();
    const auto columns = parse_csv_columns(read_text_file(file, "spectrum table"), file.string());
    if (columns.size() < 2) throw InputError(file.string() + ":1: expected two columns: wavelength_nm, relative power");
    for (size_t i = 0; i < columns[0].size(); ++i)
      if (!std::isfinite(columns[0][i]) || (i > 0 && !(columns[0][i] > columns[0][i - 1])))
        throw InputError(file.string() + ":" + std::to_string(i + 2) +
                         ": wavelengths must be finite and strictly increasing");
    lamp.table = {columns[0], columns[1]};
  }
  return lamp;
}

// A file's relative photometry, or any distribution, may be set to a total flux.
void scale_to_lumens(const JsonReader& j, Photometry& photometry) {
  const auto lumens = j.optional("lumens");
  if (!lumens) return;
  const double wanted = lumens->number_in(0, 1e9);
  const double flux = photometry.distribution.luminous_flux();
  if (!(flux > 0)) lumens->fail("the distribution sends out no light to scale");
  photometry.distribution = photometry.distribution.scaled(wanted / flux);
  photometry.source += ", scaled to " + rounded_lumens(wanted);
  if (!(photometry.distribution.peak_candela() <= kMaxLuminousIntensityCd))
    lumens->fail("this flux from this distribution needs a peak over the limit of 1e9 cd");
}

// The spectrum of a light or a lamp row.
Spectrum read_spectrum(const JsonReader& j, const std::filesystem::path& base_dir) {
  try {
    return lamp_spectrum_per_candela(read_lamp(j, base_dir));
  } catch (const std::invalid_argument& e) {
    j.required("lamp").fail(e.what());
  }
}

SceneLight read_light(const JsonReader& j, const std::filesystem::path& base_dir) {
  j.allow_only({"name", "position", "aim", "rotation_deg", "ies", "ldt", "shape", "candela", "inner_deg", "outer_deg",
                "lumens", "lamp", "temperature_k", "spectrum_file"});
  const std::string name = j.optional("name") ? j.required("name").string() : j.path();
  const Vec3 position = j.required("position").point_m();
  const Vec3 aim = j.optional("aim") ? j.required("aim").vec3() : Vec3{0, 0, -1};
  if (!(length(aim) > 0) || !std::isfinite(length(aim)))
    j.required("aim").fail("the aim must be a non-zero vector of moderate length");
  const double rotation = j.optional("rotation_deg") ? j.required("rotation_deg").number_in(-360, 360) : 0.0;
  if (j.has("candela") && !j.has("shape")) j.required("candela").fail("candela is for a shape; files give their own");
  Photometry photometry = read_photometry(j, base_dir);
  scale_to_lumens(j, photometry);
  const Spectrum spectrum = read_spectrum(j, base_dir);
  return {name, Luminaire(position, std::move(photometry.distribution), aim, rotation, photometry.tilt), spectrum,
          photometry.source};
}

LampRowSettings read_row_geometry(const JsonReader& j) {
  LampRowSettings row;
  const JsonReader line = j.required("centre_line");
  if (!line.is_array() || line.elements().size() < 2) line.fail_expected("an array of at least two points [x, y, z]");
  for (const JsonReader& p : line.elements()) row.centre_line.push_back(p.point_m());
  row.road_width_m = j.required("road_width_m").number_in(0, 200);
  row.spacing_m = j.required("spacing_m").number_in(0.5, 10000);
  if (auto f = j.optional("first_at_m")) row.first_at_m = f->number_in(0, kSceneExtentM);
  row.height_m = j.required("height_m").number_in(0.5, 100);
  if (auto o = j.optional("overhang_m")) row.overhang_m = o->number_in(-50, 50);
  if (auto t = j.optional("tilt_deg")) row.tilt_deg = t->number_in(-45, 45);
  if (auto a = j.optional("arrangement")) {
    const std::string s = a->one_of({"single_sided", "opposite", "staggered"});
    row.arrangement = s == "opposite"    ? LampArrangement::opposite
                      : s == "staggered" ? LampArrangement::staggered
                                         : LampArrangement::single_sided;
  }
  if (auto side = j.optional("side"))
    row.side = side->one_of({"right", "left"}) == "left" ? RoadSide::left : RoadSide::right;
  return row;
}

// {"centre_line": [...], "road_width_m", "spacing_m", "height_m", "overhang_m",
// "tilt_deg", "arrangement", "side", "first_at_m", "name"} and a light's photometry
// and lamp keys: every luminaire of the row alike.
void read_lamp_row(const JsonReader& j, const std::filesystem::path& base_dir, std::vector<SceneLight>& out) {
  j.allow_only({"name",      "centre_line", "road_width_m", "spacing_m", "first_at_m",    "height_m",     "overhang_m",
                "tilt_deg",  "arrangement", "side",         "ies",       "ldt",           "shape",        "candela",
                "inner_deg", "outer_deg",   "lumens",       "lamp",      "temperature_k", "spectrum_file"});
  const std::string name = j.optional("name") ? j.required("name").string() : j.path();
  const LampRowSettings row = read_row_geometry(j);
  if (j.has("candela") && !j.has("shape")) j.required("candela").fail("candela is for a shape; files give their own");
  Photometry photometry = read_photometry(j, base_dir);
  scale_to_lumens(j, photometry);
  const Spectrum spectrum = read_spectrum(j, base_dir);
  std::vector<LampPlacement> placements;
  try {
    placements = place_lamp_row(row);
  } catch (const std::invalid_argument& e) {
    j.fail(e.what());
  }
  if (out.size() + placements.size() > kMaxSceneLights)
    j.fail("the scene would hold more than " + std::to_string(kMaxSceneLights) + " lights");
  for (size_t i = 0; i < placements.size(); ++i)
    out.push_back({name + " " + std::to_string(i + 1),
                   Luminaire(placements[i].position, photometry.distribution, placements[i].aim,
                             placements[i].rotation_deg, photometry.tilt),
                   spectrum, photometry.source});
}

// {"name", "position", "heading_deg", "beam", "ies"}: a car's pair of headlamps
// (lights/headlamps.h), halogen lamps; a file's distribution has its γ = 0 straight ahead.
void read_car(const JsonReader& j, const std::filesystem::path& base_dir, std::vector<SceneLight>& out) {
  j.allow_only({"name", "position", "heading_deg", "beam", "ies"});
  const std::string name = j.optional("name") ? j.required("name").string() : j.path();
  const Vec3 position = j.required("position").point_m();
  const double heading = j.required("heading_deg").number_in(-360, 360);
  const Beam beam = j.optional("beam") && j.required("beam").one_of({"low", "high"}) == "high" ? Beam::high : Beam::low;
  const HeadlampPair pair = place_headlamps(position, heading);
  const Spectrum spectrum = lamp_spectrum_per_candela({LampType::kHalogen, 3000.0, {}});
  for (const auto& [side, at] : {std::pair{"left", pair.left}, std::pair{"right", pair.right}}) {
    const std::string lamp = name + " " + side + " headlamp";
    if (auto ies = j.optional("ies")) {
      IesPhotometry file = read_ies(base_dir / ies->string());
      out.push_back({lamp, Luminaire(at, std::move(file.distribution), pair.forward, 0, file.tilt), spectrum,
                     "headlamp " + quote_name(ies->string()) + " (" + file.format + ")"});
    } else {
      out.push_back({lamp, headlamp_luminaire(at, pair.forward, beam), spectrum,
                     beam == Beam::high ? "headlamp (high beam)" : "headlamp (low beam)"});
    }
  }
}

}  // namespace

void read_cars(const JsonReader& j, const std::filesystem::path& base_dir, std::vector<SceneLight>& lights) {
  if (!j.is_array()) j.fail_expected("an array of cars");
  for (const JsonReader& car : j.elements()) {
    if (lights.size() + 2 > kMaxSceneLights)
      car.fail("the scene would hold more than " + std::to_string(kMaxSceneLights) + " lights");
    read_car(car, base_dir, lights);
  }
}

std::vector<SceneLight> read_lights(const JsonReader& j, const std::filesystem::path& base_dir) {
  if (!j.is_array()) j.fail_expected("an array of lights");
  std::vector<SceneLight> lights;
  for (const JsonReader& light : j.elements()) lights.push_back(read_light(light, base_dir));
  return lights;
}

void read_lamp_rows(const JsonReader& j, const std::filesystem::path& base_dir, std::vector<SceneLight>& lights) {
  if (!j.is_array()) j.fail_expected("an array of lamp rows");
  for (const JsonReader& row : j.elements()) read_lamp_row(row, base_dir, lights);
}

}  // namespace skylit
