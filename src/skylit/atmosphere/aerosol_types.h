// Aerosol types with published optical properties, and the aerosol phase function.
//
// Each type of OPAC (Hess, Koepke & Schult 1998, Bull. Am. Meteor. Soc. 79, 831, Table 4,
// at 80 % relative humidity) brings its single-scattering albedo and asymmetry parameter
// at 550 nm and its Ångström exponents over 350–500 and 500–800 nm
// (data/aerosol_types.csv). The optical depth (the amount) is set apart: aod_550,
// a visibility or a Linke turbidity.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "skylit/atmosphere/atmosphere_settings.h"

namespace skylit {

// The scene-file names of the types, in the order of AerosolType.
const std::vector<std::string_view>& aerosol_type_names();
std::optional<AerosolType> aerosol_type_from_name(std::string_view name);

// `settings` with the optical properties of `type` (albedo, asymmetry, Ångström
// exponents); the amount, profile and phase-function shape are kept.
AerosolSettings with_aerosol_type(AerosolSettings settings, AerosolType type);

// τ(λ)/τ(550 nm) by the two-piece Ångström law of AerosolSettings.
double aerosol_relative_optical_depth(const AerosolSettings& aerosol, double wavelength_nm);

// The parameter g of the Cornette–Shanks phase function whose mean cosine is
// `mean_cosine`: ⟨cos θ⟩ = 3g(4 + g²)/(5(2 + g²)) (Cornette & Shanks 1992), solved for g.
double cornette_shanks_parameter(double mean_cosine);

// The aerosol phase function of the settings, with the mean cosine `asymmetry`:
// Cornette–Shanks with the parameter that gives that mean cosine, or Henyey–Greenstein
// (whose parameter is its mean cosine).
class AerosolPhaseFunction {
 public:
  explicit AerosolPhaseFunction(const AerosolSettings& aerosol);
  double operator()(double cos_theta) const;  // sr⁻¹

 private:
  AerosolPhase shape_;
  double parameter_;
};

}  // namespace skylit
