// CityJSON 1.0, 1.1 and 2.0 (https://www.cityjson.org/specs/) and CityJSONSeq
// (one CityJSON header line, then one CityJSONFeature per line: *.city.jsonl) read
// into a CityModel (city_model.h): every city object with the surfaces of one
// geometry (MultiSurface, CompositeSurface, Solid, MultiSolid, CompositeSolid, or a
// GeometryInstance of a template), quantised vertices decoded with `transform`,
// semantic surface types kept, appearances (materials, textures with their texture
// coordinates) of one theme taken, the CRS taken from metadata.referenceSystem.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "skylit/io/city/city_model.h"

namespace skylit {

struct CityJsonOptions {
  // The level of detail to take, ×10 (LoD2.2 → 22; LoD2 → 20): each object's geometry
  // of the highest LoD not above it (objects with none are left out). Empty: each
  // object's most detailed geometry.
  std::optional<int> lod;
  CityAppearanceOptions appearance;
};

// A city model file's size limit: 1 GiB, several times a large city district.
inline constexpr std::uintmax_t kMaxCityFileBytes = 1ull << 30;

// Throws InputError "<file>: <JSON path>: <what is wrong>" (or "<file>:<line>:<column>"
// for broken JSON; "<file>:<line>: ..." in a CityJSONSeq) for anything malformed: a
// vertex index out of range, a ring without points, a semantic, material or texture
// index the file does not have, texture values that do not match a ring's points, a
// template that does not exist, ... A ring of one or two points is no error: as a hole
// it is dropped, as an exterior its surface is kept (and placed as one of zero area).
CityModel read_cityjson_file(const std::filesystem::path& file, const CityJsonOptions& options = {});
// The same from text; `source` names it in messages, and a name ending in ".jsonl"
// marks a CityJSONSeq.
CityModel read_cityjson_text(const std::string& text, const std::string& source, const CityJsonOptions& options = {});

// A LoD as CityJSON writes it ("2.2", "2", or the number 2 of version 1.0), ×10;
// empty if it is not one.
std::optional<int> parse_lod(const std::string& text);

}  // namespace skylit
