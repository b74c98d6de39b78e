// The luminous efficacy of daylight (lm/W) from an hour's irradiances: Perez, Ineichen,
// Seals, Michalsky and Stewart, "Modeling daylight availability and irradiance
// components from direct and global irradiance", Solar Energy 44(5), 271–289 (1990),
// Table 4 and Eqs. for the direct, global and diffuse efficacies. For weather files that
// give irradiances but no illuminances (PVGIS's and other satellite or reanalysis
// files): without it their hours' sun and sky could not be read at all.
//
// The sky is described by Perez's clearness ε (how much of the light comes straight from
// the sun, corrected for the sun's zenith angle Z) and brightness Δ (the diffuse light
// over the extraterrestrial beam, times the air mass); each efficacy is a linear law in
// the precipitable water W, a function of Z and ln Δ or Δ, with coefficients for each of
// eight ranges of ε that the authors fitted to hourly measurements. How closely they give
// another source's illuminances: tests/weather/luminous_efficacy_test.cpp.
#pragma once

#include <optional>

namespace skylit {

struct DaylightEfficacy {
  double global_lm_w = 0, direct_lm_w = 0, diffuse_lm_w = 0;
  double clearness = 1;   // ε
  double brightness = 0;  // Δ
};

// None where the sun is not up or there is no diffuse light (ε is then undefined).
// `extraterrestrial_normal_w_m2`: the Sun's irradiance at the top of the atmosphere that
// day (1367 W m⁻² at 1 AU in Perez's work, over the Earth–Sun distance squared).
std::optional<DaylightEfficacy> perez_daylight_efficacy(double direct_normal_w_m2, double diffuse_horizontal_w_m2,
                                                        double sun_zenith_deg, double precipitable_water_cm,
                                                        double extraterrestrial_normal_w_m2);

// The precipitable water (cm) Perez et al. (1990) take from the surface dew point (°C):
// W = exp(0.07·Td − 0.075) (Wright, Perez and Michalsky 1989).
double precipitable_water_cm_from_dew_point(double dew_point_c);

// Perez's extraterrestrial normal irradiance at 1 AU (W m⁻²), the one their Δ was fitted
// with.
inline constexpr double kPerezSolarConstantWm2 = 1367.0;

}  // namespace skylit
