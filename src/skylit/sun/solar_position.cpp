// The NREL Solar Position Algorithm, step by step: I. Reda and A. Andreas, "Solar
// Position Algorithm for Solar Radiation Applications", NREL/TP-560-34302 (revised
// January 2008). Equation numbers below are the paper's. The periodic terms are in
// spa_earth_terms.cpp and spa_nutation_terms.cpp.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>
#include <stdexcept>
#include <string>

#include "skylit/sun/delta_t.h"
#include "skylit/sun/spa_steps.h"

namespace skylit {

namespace {

constexpr double kJ2000 = 2451545.0;  // Julian Day of 2000-01-01 12:00 TT
constexpr double kSunRadiusDeg = 0.26667;
constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

double radians(double degrees) { return degrees * kRadiansPerDegree; }
double degrees(double radians) { return radians / kRadiansPerDegree; }
double sin_deg(double d) { return std::sin(radians(d)); }
double cos_deg(double d) { return std::cos(radians(d)); }
double tan_deg(double d) { return std::tan(radians(d)); }

// An angle brought into [0, 360).
double wrap_360(double degrees) {
  const double wrapped = std::fmod(degrees, 360.0);
  return wrapped < 0 ? wrapped + 360.0 : (wrapped >= 360.0 ? 0.0 : wrapped);
}

double first_julian_day() { return julian_day_ut({kSolarPositionFirstYear, 1, 1, 0, 0, 0, 0}); }
double end_julian_day() { return julian_day_ut({kSolarPositionLastYear + 1, 1, 1, 0, 0, 0, 0}); }

void check_inputs(const SiteLocation& site, double julian_day_ut, const SpaOptions& options) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("solar_position: " + what); };
  if (!std::isfinite(site.latitude_deg) || std::abs(site.latitude_deg) > 90.0)
    fail("latitude " + std::to_string(site.latitude_deg) + "° is not within ±90°");
  if (!std::isfinite(site.longitude_deg) || !std::isfinite(site.elevation_m)) fail("longitude or elevation not finite");
  if (!(julian_day_ut >= first_julian_day() && julian_day_ut < end_julian_day()))
    fail("Julian Day " + std::to_string(julian_day_ut) + " is outside the years " +
         std::to_string(kSolarPositionFirstYear) + " to " + std::to_string(kSolarPositionLastYear));
  if (options.delta_t_s && !std::isfinite(*options.delta_t_s)) fail("ΔT not finite");
  if (options.pressure_mbar && !(*options.pressure_mbar >= 0)) fail("pressure below 0 mbar");
  if (options.temperature_c && !(*options.temperature_c > -273.15)) fail("temperature below absolute zero");
}

// §3.5, Eq. 24: the mean obliquity of the ecliptic in arcseconds (Laskar's
// polynomial), at U = JME/10 ten-thousands of years from J2000.0.
double mean_obliquity_arcsec(double u) {
  constexpr double kCoefficients[] = {84381.448, -4680.93, -1.55, 1999.25, -51.38, -249.67,
                                      -39.05,    7.12,     27.87, 5.79,    2.45};
  double value = 0;
  for (auto c = std::rbegin(kCoefficients); c != std::rend(kCoefficients); ++c) value = value * u + *c;
  return value;
}

// §3.14, Eq. 42: refraction of the sun's elevation e0 (degrees) for the given air,
// applied only while some of the sun can still be seen: its upper limb is above the
// refracted horizon.
double refraction_deg(double true_elevation_deg, double pressure_mbar, double temperature_c,
                      double horizon_refraction_deg) {
  if (true_elevation_deg < -(kSunRadiusDeg + horizon_refraction_deg)) return 0;
  return (pressure_mbar / 1010.0) * (283.0 / (273.0 + temperature_c)) * 1.02 /
         (60.0 * tan_deg(true_elevation_deg + 10.3 / (true_elevation_deg + 5.11)));
}

// §A.1, Eqs. A1–A2: the equation of time in minutes, between −20 and 20.
double equation_of_time_min(const spa::Steps& s) {
  const double jme = s.julian_ephemeris_millennium;
  const double sun_mean_longitude_deg = wrap_360(
      280.4664567 +
      jme * (360007.6982779 + jme * (0.03032028 + jme * (1.0 / 49931.0 + jme * (-1.0 / 15300.0 - jme / 2000000.0)))));
  double minutes = 4.0 * (sun_mean_longitude_deg - 0.0057183 - s.right_ascension_deg +
                          s.nutation.longitude_deg * cos_deg(s.true_obliquity_deg));
  if (minutes < -20.0) minutes += 1440.0;
  if (minutes > 20.0) minutes -= 1440.0;
  return minutes;
}

}  // namespace

double standard_temperature_c(double elevation_m) {
  // Troposphere to 11 km at −6.5 K/km from 15 °C, then isothermal at −56.5 °C to 20 km.
  constexpr double kTropopauseM = 11000.0;
  return 15.0 - 0.0065 * std::min(elevation_m, kTropopauseM);
}

double standard_pressure_mbar(double elevation_m) {
  constexpr double kSeaLevelMbar = 1013.25, kSeaLevelK = 288.15, kLapseKPerM = 0.0065, kTropopauseM = 11000.0;
  constexpr double kGravity = 9.80665, kGasConstantAir = 287.05287;         // m/s², J/(kg·K)
  constexpr double kExponent = kGravity / (kGasConstantAir * kLapseKPerM);  // 5.25588
  const double h = std::min(elevation_m, kTropopauseM);
  const double troposphere = kSeaLevelMbar * std::pow(1.0 - kLapseKPerM * h / kSeaLevelK, kExponent);
  if (elevation_m <= kTropopauseM) return troposphere;
  const double tropopause_k = kSeaLevelK - kLapseKPerM * kTropopauseM;
  return troposphere * std::exp(-kGravity * (elevation_m - kTropopauseM) / (kGasConstantAir * tropopause_k));
}

namespace spa {

Topocentric topocentric(const SiteLocation& site, double apparent_sidereal_time_deg, double right_ascension_deg,
                        double declination_deg, double equatorial_parallax_deg, const SpaOptions& options) {
  Topocentric t{};
  // §3.11: the observer's local hour angle, westward from the meridian.
  t.hour_angle_deg = wrap_360(apparent_sidereal_time_deg + site.longitude_deg - right_ascension_deg);  // Eq. 32

  // §3.12: parallax, seen from the observer on the Earth's surface rather than its centre.
  t.equatorial_parallax_deg = equatorial_parallax_deg;
  constexpr double kPolarOverEquatorialRadius = 0.99664719, kEquatorialRadiusM = 6378140.0;
  const double reduced_latitude = std::atan(kPolarOverEquatorialRadius * tan_deg(site.latitude_deg));  // Eq. 34
  const double x = std::cos(reduced_latitude) + site.elevation_m / kEquatorialRadiusM * cos_deg(site.latitude_deg);
  const double y = kPolarOverEquatorialRadius * std::sin(reduced_latitude) +
                   site.elevation_m / kEquatorialRadiusM * sin_deg(site.latitude_deg);  // Eqs. 35–36
  const double sin_xi = sin_deg(t.equatorial_parallax_deg);
  const double denominator = cos_deg(declination_deg) - x * sin_xi * cos_deg(t.hour_angle_deg);
  const double delta_alpha = std::atan2(-x * sin_xi * sin_deg(t.hour_angle_deg), denominator);  // Eq. 37
  t.parallax_in_right_ascension_deg = degrees(delta_alpha);
  t.right_ascension_deg = right_ascension_deg + t.parallax_in_right_ascension_deg;  // Eq. 38
  t.declination_deg =
      degrees(std::atan2((sin_deg(declination_deg) - y * sin_xi) * std::cos(delta_alpha), denominator));  // Eq. 39

  // §3.13–3.14: the topocentric elevation, then refraction.
  t.topocentric_hour_angle_deg = t.hour_angle_deg - t.parallax_in_right_ascension_deg;  // Eq. 40
  const double phi = site.latitude_deg, delta_p = t.declination_deg, h_p = t.topocentric_hour_angle_deg;
  t.true_elevation_deg =
      degrees(std::asin(sin_deg(phi) * sin_deg(delta_p) + cos_deg(phi) * cos_deg(delta_p) * cos_deg(h_p)));  // Eq. 41
  const double pressure_mbar = options.pressure_mbar.value_or(standard_pressure_mbar(site.elevation_m));
  const double temperature_c = options.temperature_c.value_or(standard_temperature_c(site.elevation_m));
  t.refraction_deg =
      refraction_deg(t.true_elevation_deg, pressure_mbar, temperature_c, options.horizon_refraction_deg);  // Eq. 42
  t.apparent_elevation_deg = t.true_elevation_deg + t.refraction_deg;                                      // Eq. 43

  // §3.15: azimuth; the astronomers' is from the south, the navigators' (ours) from the north.
  t.astronomers_azimuth_deg = wrap_360(
      degrees(std::atan2(sin_deg(h_p), cos_deg(h_p) * sin_deg(phi) - tan_deg(delta_p) * cos_deg(phi))));  // Eq. 45
  t.azimuth_deg = wrap_360(t.astronomers_azimuth_deg + 180.0);                                            // Eq. 46
  return t;
}

Steps compute_steps(const SiteLocation& site, double julian_day_utc, const SpaOptions& options) {
  check_inputs(site, julian_day_utc, options);
  Steps s{};
  // §3.1: time scales. The Julian Day counts UT1; JDE counts Terrestrial Time.
  s.julian_day = julian_day_utc + options.delta_ut1_s / 86400.0;
  const double delta_t_s = options.delta_t_s.value_or(delta_t_estimate_s(decimal_year_of_julian_day(s.julian_day)));
  s.julian_ephemeris_day = s.julian_day + delta_t_s / 86400.0;               // Eq. 5
  s.julian_century = (s.julian_day - kJ2000) / 36525.0;                      // Eq. 6
  s.julian_ephemeris_century = (s.julian_ephemeris_day - kJ2000) / 36525.0;  // Eq. 7
  s.julian_ephemeris_millennium = s.julian_ephemeris_century / 10.0;         // Eq. 8

  // §3.2–3.3: the Earth around the sun, turned into the sun around the Earth.
  s.earth = heliocentric_earth(s.julian_ephemeris_millennium);
  s.geocentric_longitude_deg = wrap_360(s.earth.longitude_deg + 180.0);  // Eq. 13
  s.geocentric_latitude_deg = -s.earth.latitude_deg;                     // Eq. 14

  // §3.4–3.5: nutation and the obliquity of the ecliptic.
  s.nutation = nutation(s.julian_ephemeris_century);
  s.mean_obliquity_arcsec = mean_obliquity_arcsec(s.julian_ephemeris_millennium / 10.0);
  s.true_obliquity_deg = s.mean_obliquity_arcsec / 3600.0 + s.nutation.obliquity_deg;  // Eq. 25

  // §3.6–3.7: aberration, and the apparent longitude of the sun.
  s.aberration_deg = -20.4898 / (3600.0 * s.earth.radius_au);                                               // Eq. 26
  s.apparent_sun_longitude_deg = s.geocentric_longitude_deg + s.nutation.longitude_deg + s.aberration_deg;  // Eq. 27

  // §3.8: sidereal time at Greenwich, mean and apparent.
  const double jc = s.julian_century;
  s.mean_sidereal_time_deg = wrap_360(280.46061837 + 360.98564736629 * (s.julian_day - kJ2000) +
                                      jc * jc * (0.000387933 - jc / 38710000.0));  // Eq. 28
  s.apparent_sidereal_time_deg =
      s.mean_sidereal_time_deg + s.nutation.longitude_deg * cos_deg(s.true_obliquity_deg);  // Eq. 29

  // §3.9–3.10: the sun's geocentric right ascension and declination.
  const double lambda = s.apparent_sun_longitude_deg, epsilon = s.true_obliquity_deg, beta = s.geocentric_latitude_deg;
  s.right_ascension_deg = wrap_360(degrees(
      std::atan2(sin_deg(lambda) * cos_deg(epsilon) - tan_deg(beta) * sin_deg(epsilon), cos_deg(lambda))));  // Eq. 30
  s.declination_deg = degrees(
      std::asin(sin_deg(beta) * cos_deg(epsilon) + cos_deg(beta) * sin_deg(epsilon) * sin_deg(lambda)));  // Eq. 31

  const Topocentric place = topocentric(site, s.apparent_sidereal_time_deg, s.right_ascension_deg, s.declination_deg,
                                        8.794 / (3600.0 * s.earth.radius_au), options);  // Eq. 33: ξ
  s.hour_angle_deg = place.hour_angle_deg;
  s.equatorial_parallax_deg = place.equatorial_parallax_deg;
  s.parallax_in_right_ascension_deg = place.parallax_in_right_ascension_deg;
  s.topocentric_right_ascension_deg = place.right_ascension_deg;
  s.topocentric_declination_deg = place.declination_deg;
  s.topocentric_hour_angle_deg = place.topocentric_hour_angle_deg;
  s.true_elevation_deg = place.true_elevation_deg;
  s.refraction_deg = place.refraction_deg;
  s.apparent_elevation_deg = place.apparent_elevation_deg;
  s.zenith_deg = 90.0 - s.apparent_elevation_deg;  // Eq. 44
  s.astronomers_azimuth_deg = place.astronomers_azimuth_deg;
  s.azimuth_deg = place.azimuth_deg;

  s.equation_of_time_min = equation_of_time_min(s);
  return s;
}

}  // namespace spa

SolarPosition solar_position(const SiteLocation& site, double julian_day_ut, const SpaOptions& options) {
  const spa::Steps s = spa::compute_steps(site, julian_day_ut, options);
  return {s.zenith_deg, s.azimuth_deg, s.apparent_elevation_deg, s.earth.radius_au, s.equation_of_time_min};
}

SolarPosition solar_position(const SiteLocation& site, const OffsetDateTime& time, const SpaOptions& options) {
  return solar_position(site, julian_day_ut(time), options);
}

double surface_distance_km(const SiteLocation& a, const SiteLocation& b) {
  constexpr double kMeanRadiusKm = 6371.0088;  // IUGG R1 of GRS 80
  const double phi_a = radians(a.latitude_deg), phi_b = radians(b.latitude_deg);
  const double half_dphi = 0.5 * (phi_b - phi_a), half_dlambda = 0.5 * radians(b.longitude_deg - a.longitude_deg);
  const double h = std::sin(half_dphi) * std::sin(half_dphi) +
                   std::cos(phi_a) * std::cos(phi_b) * std::sin(half_dlambda) * std::sin(half_dlambda);
  return 2 * kMeanRadiusKm * std::asin(std::sqrt(std::clamp(h, 0.0, 1.0)));
}

}  // namespace skylit
