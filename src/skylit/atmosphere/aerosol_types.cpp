#include "skylit/atmosphere/aerosol_types.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "skylit/atmosphere/phase_functions.h"
#include "skylit/core/embedded_data.h"
#include "skylit/spectrum/tabulated.h"

namespace skylit {

namespace {

struct TypeProperties {
  double single_scattering_albedo, asymmetry, angstrom_short, angstrom;
};

// data/aerosol_types.csv: a name, then numbers. The names must be those of
// aerosol_type_names(), in order (a build-time table, so a mismatch is a logic error).
const std::vector<TypeProperties>& type_table() {
  static const std::vector<TypeProperties> table = [] {
    const std::string_view text = data::embedded_file("aerosol_types.csv");
    std::string numbers;
    size_t start = 0, row = 0;
    while (start < text.size()) {
      size_t end = text.find('\n', start);
      if (end == std::string_view::npos) end = text.size();
      const std::string_view line = text.substr(start, end - start);
      start = end + 1;
      const size_t comma = line.find(',');
      if (line.empty() || comma == std::string_view::npos) continue;
      if (row > 0 && (row > aerosol_type_names().size() || line.substr(0, comma) != aerosol_type_names()[row - 1]))
        throw std::logic_error("data/aerosol_types.csv: row " + std::to_string(row) + " is not the expected type");
      numbers.append(line.substr(comma + 1)).push_back('\n');
      ++row;
    }
    const auto columns = parse_csv_columns(numbers, "aerosol_types.csv");
    std::vector<TypeProperties> out;
    for (size_t i = 0; i < columns.at(0).size(); ++i)
      out.push_back({columns[0][i], columns[1][i], columns[2][i], columns[3][i]});
    if (out.size() != aerosol_type_names().size())
      throw std::logic_error("data/aerosol_types.csv: one row per aerosol type expected");
    return out;
  }();
  return table;
}

}  // namespace

const std::vector<std::string_view>& aerosol_type_names() {
  static const std::vector<std::string_view> names = {"continental_clean",
                                                      "continental_average",
                                                      "continental_polluted",
                                                      "urban",
                                                      "maritime_clean",
                                                      "maritime_polluted",
                                                      "desert"};
  return names;
}

std::optional<AerosolType> aerosol_type_from_name(std::string_view name) {
  const auto& names = aerosol_type_names();
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<AerosolType>(i);
  return std::nullopt;
}

AerosolSettings with_aerosol_type(AerosolSettings settings, AerosolType type) {
  const TypeProperties& p = type_table().at(static_cast<size_t>(type));
  settings.type = type;
  settings.single_scattering_albedo = p.single_scattering_albedo;
  settings.asymmetry = p.asymmetry;
  settings.angstrom_exponent = p.angstrom;
  settings.angstrom_exponent_short = p.angstrom_short;
  return settings;
}

double aerosol_relative_optical_depth(const AerosolSettings& aerosol, double wavelength_nm) {
  if (wavelength_nm >= 500.0) return std::pow(wavelength_nm / 550.0, -aerosol.angstrom_exponent);
  return std::pow(500.0 / 550.0, -aerosol.angstrom_exponent) *
         std::pow(wavelength_nm / 500.0, -aerosol.angstrom_exponent_short);
}

double cornette_shanks_parameter(double mean_cosine) {
  // The mean cosine rises monotonically from 0 at g = 0 to 1 at g = 1: bisection.
  const auto mean_of = [](double g) { return 3.0 * g * (4.0 + g * g) / (5.0 * (2.0 + g * g)); };
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (mean_of(mid) < mean_cosine ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

AerosolPhaseFunction::AerosolPhaseFunction(const AerosolSettings& aerosol)
    : shape_(aerosol.phase),
      parameter_(aerosol.phase == AerosolPhase::cornette_shanks ? cornette_shanks_parameter(aerosol.asymmetry)
                                                                : aerosol.asymmetry) {}

double AerosolPhaseFunction::operator()(double cos_theta) const {
  return shape_ == AerosolPhase::cornette_shanks ? cornette_shanks_phase(cos_theta, parameter_)
                                                 : henyey_greenstein_phase(cos_theta, parameter_);
}

}  // namespace skylit
