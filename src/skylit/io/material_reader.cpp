// The `materials` part of a scene file: named materials and their reflectances.
#include <algorithm>
#include <cctype>

#include "skylit/io/scene_parts.h"
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

std::vector<NamedMaterial> read_materials(const JsonReader& j) {
  std::vector<NamedMaterial> out;
  for (const auto& [name, m] : j.members()) {
    if (name.empty()) m.fail("a material needs a non-empty name");
    m.required("type").one_of({"diffuse"});
    m.allow_only({"type", "reflectance"});
    out.push_back({name, DiffuseMaterial{read_reflectance(m.required("reflectance"))}});
  }
  return out;
}

}  // namespace skylit
