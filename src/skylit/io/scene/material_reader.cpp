// The `materials` part of a scene file (docs/scene-format.md): named materials, each
// an object with a type, a preset's name, or a preset with some values replaced;
// every mistake is an InputError naming its JSON path.
#include <algorithm>
#include <cctype>
#include <optional>
#include <string_view>

#include "skylit/io/scene/scene_parts.h"
#include "skylit/material/optical_constants.h"
#include "skylit/material/presets.h"
#include "skylit/spectrum/color_space.h"
#include "skylit/spectrum/rgb_to_spectrum.h"

namespace skylit {

namespace {

Rgb read_rgb01(const JsonReader& j) {
  if (!j.is_array() || j.raw().size() != 3) j.fail_expected("an array of 3 numbers from 0 to 1");
  const auto e = j.elements();
  return {e[0].number_in(0, 1), e[1].number_in(0, 1), e[2].number_in(0, 1)};
}

Rgb linear_from_encoded(const Rgb& encoded) {
  return {srgb_decode(encoded[0]), srgb_decode(encoded[1]), srgb_decode(encoded[2])};
}

Rgb read_hex_colour(const JsonReader& j) {
  const std::string s = j.string();
  const bool ok = s.size() == 7 && s[0] == '#' &&
                  std::all_of(s.begin() + 1, s.end(), [](unsigned char c) { return std::isxdigit(c) != 0; });
  if (!ok) j.fail_expected("a colour '#rrggbb'");
  Rgb encoded{};
  for (int i = 0; i < 3; ++i) encoded[i] = std::stoi(s.substr(1 + 2 * i, 2), nullptr, 16) / 255.0;
  return encoded;
}

Spectrum read_sampled_reflectance(const JsonReader& j) {
  j.allow_only({"wavelength_nm", "value"});
  const auto wavelengths = j.required("wavelength_nm").elements();
  const auto values = j.required("value").elements();
  if (wavelengths.size() < 2) j.required("wavelength_nm").fail_expected("at least 2 wavelengths");
  if (values.size() != wavelengths.size())
    j.required("value").fail("needs as many values as wavelength_nm has (" + std::to_string(wavelengths.size()) + ")");
  std::vector<std::pair<double, double>> samples;
  for (size_t i = 0; i < wavelengths.size(); ++i) {
    samples.emplace_back(wavelengths[i].number_in(1, 1e5), values[i].number_in(0, 1));
    if (i > 0 && samples[i].first <= samples[i - 1].first) wavelengths[i].fail("wavelengths must increase");
  }
  return reflectance_from_samples(samples, j.source() + ": " + j.path());
}

}  // namespace

Spectrum read_reflectance(const JsonReader& j) {
  if (j.is_number()) return Spectrum(static_cast<float>(j.number_in(0, 1)));
  if (j.is_string()) return reflectance_from_linear_srgb(linear_from_encoded(read_hex_colour(j)));
  if (j.is_array()) return reflectance_from_linear_srgb(linear_from_encoded(read_rgb01(j)));
  if (j.is_object()) {
    j.allow_only({"srgb", "linear_srgb", "spectrum"});
    if (j.members().size() != 1) j.fail("give exactly one of srgb, linear_srgb, spectrum");
    if (auto s = j.optional("srgb")) return reflectance_from_linear_srgb(linear_from_encoded(read_rgb01(*s)));
    if (auto s = j.optional("linear_srgb")) return reflectance_from_linear_srgb(read_rgb01(*s));
    return read_sampled_reflectance(j.required("spectrum"));
  }
  j.fail_expected("a reflectance: a number from 0 to 1, [r,g,b] in sRGB, \"#rrggbb\", or an object");
}

namespace {

// The keys of each material type (besides "type"); docs/scene-format.md.
std::vector<std::string_view> keys_of_type(const std::string& type) {
  if (type == "diffuse") return {"reflectance"};
  if (type == "cook_torrance") return {"roughness", "metal", "ior", "dielectric", "diffuse_reflectance"};
  if (type == "layered") return {"reflectance", "roughness", "ior", "dielectric"};
  if (type == "road") return {"r_table", "q0"};
  return {"interior_reflectance", "thickness_mm", "roughness", "ior", "dielectric"};  // glass
}

std::string join(const std::vector<std::string_view>& words) {
  std::string out;
  for (std::string_view w : words) out += (out.empty() ? "" : ", ") + std::string(w);
  return out;
}

void allow_only_keys(const JsonReader& j, std::vector<std::string_view> allowed) {
  for (const auto& [key, value] : j.members())
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
      value.fail("unknown key; expected one of: " + join(allowed));
}

// `metal` as an object: n and k, each a number or an array over wavelength_nm.
ComplexIor read_metal_constants(const JsonReader& j) {
  j.allow_only({"wavelength_nm", "n", "k"});
  const JsonReader n = j.required("n"), k = j.required("k");
  if (!n.is_array() && !n.is_number()) n.fail_expected("a number or an array of numbers");
  if (!k.is_array() && !k.is_number()) k.fail_expected("a number or an array of numbers");
  if (n.is_number() && k.is_number()) {
    if (auto w = j.optional("wavelength_nm")) w->fail("only needed when n or k is an array");
    return constant_ior(n.number_in(0.01, 100), k.number_in(0, 100));
  }
  const auto wavelengths = j.required("wavelength_nm").elements();
  if (wavelengths.empty()) j.required("wavelength_nm").fail_expected("at least 1 wavelength");
  const auto column = [&](const JsonReader& c, double lo, double hi) {
    if (c.is_number()) return std::vector<double>(wavelengths.size(), c.number_in(lo, hi));
    const auto e = c.elements();
    std::vector<double> out;
    if (e.size() != wavelengths.size())
      c.fail("needs as many values as wavelength_nm has (" + std::to_string(wavelengths.size()) + ")");
    out.reserve(e.size());
    for (const JsonReader& v : e) out.push_back(v.number_in(lo, hi));
    return out;
  };
  const std::vector<double> n_values = column(n, 0.01, 100), k_values = column(k, 0, 100);
  std::vector<IorSample> samples;
  for (size_t i = 0; i < wavelengths.size(); ++i) {
    samples.push_back({wavelengths[i].number_in(1, 1e5), n_values[i], k_values[i]});
    if (i > 0 && samples[i].wavelength_nm <= samples[i - 1].wavelength_nm)
      wavelengths[i].fail("wavelengths must increase");
  }
  return ior_from_samples(samples);
}

// The interface's index: one of `metal` (if allowed), `ior` (a number), `dielectric`
// (a named glass); `fallback` when none is given (nullopt: one is required).
ComplexIor read_interface(const JsonReader& j, bool metal_allowed, const std::optional<ComplexIor>& fallback) {
  std::vector<std::string_view> choices = {"ior", "dielectric"};
  if (metal_allowed) choices.insert(choices.begin(), "metal");
  std::vector<std::string_view> given;
  for (std::string_view key : choices)
    if (j.has(key)) given.push_back(key);
  if (given.size() > 1) j.fail("give only one of " + join(choices));
  if (given.empty()) {
    if (fallback) return *fallback;
    j.fail("missing the interface's refractive index: give one of " + join(choices));
  }
  const JsonReader v = j.required(given[0]);
  if (given[0] == "ior") return constant_ior(v.number_in(1, 5));
  if (given[0] == "dielectric") {
    v.one_of({"glass"});
    return soda_lime_glass_ior();
  }
  if (v.is_object()) return read_metal_constants(v);
  if (!v.is_string()) v.fail_expected("a metal's name (aluminium) or an object {\"n\": …, \"k\": …}");
  v.one_of({"aluminium"});
  return aluminium_ior();
}

double read_roughness(const JsonReader& j, double fallback) {
  const auto r = j.optional("roughness");
  return r ? r->number_in(0, 1) : fallback;
}

// {"type": "road", "r_table": "R3", "q0": 0.07}: q0 defaults to the class's nominal Q0.
Material read_road(const JsonReader& j) {
  const JsonReader name = j.required("r_table");
  auto table = RoadReflectionTable::standard(name.string());
  if (!table) name.fail("unknown r-table '" + name.string() + "'; known: " + RoadReflectionTable::standard_names());
  const auto q0 = j.optional("q0");
  return RoadMaterial(table, q0 ? q0->number_in(0.01, 0.3) : table->nominal_q0());
}

Material read_typed_material(const JsonReader& j) {
  const std::string type = j.required("type").one_of({"diffuse", "cook_torrance", "layered", "glass", "road"});
  std::vector<std::string_view> allowed = keys_of_type(type);
  allowed.insert(allowed.begin(), "type");
  allow_only_keys(j, allowed);

  if (type == "diffuse") return DiffuseMaterial{read_reflectance(j.required("reflectance"))};
  if (type == "cook_torrance") {
    const double roughness = j.required("roughness").number_in(0, 1);
    const ComplexIor ior = read_interface(j, /*metal_allowed=*/true, std::nullopt);
    Spectrum diffuse;
    if (auto d = j.optional("diffuse_reflectance")) {
      if (j.has("metal") || ior.is_conductor())
        d->fail("a metal has no diffuse base: diffuse_reflectance needs a dielectric (ior or dielectric)");
      diffuse = read_reflectance(*d);
    }
    return CookTorranceMaterial(ior, roughness, diffuse);
  }
  if (type == "layered") {
    const ComplexIor ior = read_interface(j, /*metal_allowed=*/false, constant_ior(1.5));
    return CookTorranceMaterial(ior, read_roughness(j, 0.2), read_reflectance(j.required("reflectance")));
  }
  if (type == "road") return read_road(j);
  const ComplexIor ior = read_interface(j, /*metal_allowed=*/false, soda_lime_glass_ior());
  const auto thickness = j.optional("thickness_mm");
  const auto interior = j.optional("interior_reflectance");
  return GlassMaterial(ior, (thickness ? thickness->number_in(0, 100) : 6.0) * 1e-3, read_roughness(j, 0.0),
                       interior ? read_reflectance(*interior) : Spectrum(0.05f));
}

const MaterialPreset& find_preset(const JsonReader& name) {
  const std::string s = name.string();
  const MaterialPreset* preset = find_material_preset(s);
  if (!preset) name.fail("unknown material preset '" + s + "'; known presets: " + material_preset_names());
  return *preset;
}

// {"preset": name, key: value, …}: the preset's JSON with the given keys replaced.
// Giving one of the mutually exclusive index keys (metal, ior, dielectric) replaces
// the preset's own.
Material read_preset_with_overrides(const JsonReader& j) {
  if (j.has("type")) j.required("type").fail("give either type or preset, not both");
  const MaterialPreset& preset = find_preset(j.required("preset"));
  nlohmann::json merged = nlohmann::json::parse(preset.json);
  std::vector<std::string_view> allowed = keys_of_type(merged.at("type").get<std::string>());
  allowed.insert(allowed.begin(), "preset");
  allow_only_keys(j, allowed);
  if (j.has("metal") || j.has("ior") || j.has("dielectric"))
    for (const char* key : {"metal", "ior", "dielectric"}) merged.erase(key);
  for (const auto& [key, value] : j.members())
    if (key != "preset") merged[key] = value.raw();
  // Messages about the overridden values name the user's path; the preset's own
  // values are valid (tests/material/preset_test.cpp).
  return read_typed_material(JsonReader(merged, j.source(), j.path()));
}

}  // namespace

Material read_material(const JsonReader& m) {
  if (m.is_string()) {
    const nlohmann::json preset = nlohmann::json::parse(find_preset(m).json);
    return read_typed_material(JsonReader(preset, m.source(), m.path()));
  }
  if (m.is_object() && m.has("preset")) return read_preset_with_overrides(m);
  if (m.is_object()) return read_typed_material(m);
  m.fail_expected("a material: an object with a type, a preset's name (" + material_preset_names() +
                  "), or {\"preset\": name, …}");
}

std::vector<NamedMaterial> read_materials(const JsonReader& j) {
  std::vector<NamedMaterial> out;
  for (const auto& [name, m] : j.members()) {
    if (name.empty()) m.fail("a material needs a non-empty name");
    out.push_back({name, read_material(m)});
  }
  return out;
}

}  // namespace skylit
