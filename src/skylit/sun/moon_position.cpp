// The moon's place and light (moon_position.h), Meeus chapters 47 and 48.
#include "skylit/sun/moon_position.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "skylit/core/angles.h"
#include "skylit/core/embedded_data.h"
#include "skylit/sun/spa_steps.h"

namespace skylit {

namespace {

constexpr double kJ2000 = 2451545.0;
constexpr double kMeanDistanceKm = 384400.0;
constexpr double kEarthEquatorialRadiusKm = 6378.14;
constexpr double kMoonRadiusKm = 1737.4;
constexpr double kLuxPerFootCandle = 10.7639;

double sin_deg(double d) { return std::sin(radians(d)); }
double cos_deg(double d) { return std::cos(radians(d)); }
double wrap_360(double d) {
  const double w = std::fmod(d, 360.0);
  return w < 0 ? w + 360 : w;
}

// One periodic term: the multiples of D, M, M′, F and its coefficients.
struct Term {
  int d, m, m_prime, f;
  double sine, cosine;
};

// Tables 47.A (Σl in 1e-6°, Σr in metres) and 47.B (Σb in 1e-6°).
struct Terms {
  std::vector<Term> longitude_distance, latitude;
};

const Terms& terms() {
  static const Terms t = [] {
    Terms out;
    const std::string_view text = data::embedded_file("moon_meeus_47.csv");
    size_t pos = text.find('\n') + 1;  // past the header
    while (pos < text.size()) {
      const size_t end = text.find('\n', pos);
      const std::string line(text.substr(pos, end == std::string_view::npos ? std::string_view::npos : end - pos));
      pos = end == std::string_view::npos ? text.size() : end + 1;
      if (line.empty()) continue;
      Term term{};
      char table[8] = {};
      if (std::sscanf(line.c_str(), "%7[^,],%d,%d,%d,%d,%lf,%lf", table, &term.d, &term.m, &term.m_prime, &term.f,
                      &term.sine, &term.cosine) != 7)
        throw std::logic_error("moon_meeus_47.csv: malformed line " + line);
      (std::string(table) == "47A" ? out.longitude_distance : out.latitude).push_back(term);
    }
    return out;
  }();
  return t;
}

}  // namespace

MoonEcliptic moon_ecliptic(double julian_ephemeris_day) {
  const double t = (julian_ephemeris_day - kJ2000) / 36525.0;  // Eq. 22.1
  const double t2 = t * t, t3 = t2 * t, t4 = t3 * t;
  // Eqs. 47.1–47.5: mean longitude, elongation, the sun's and moon's anomalies, argument of latitude.
  const double l_prime = 218.3164477 + 481267.88123421 * t - 0.0015786 * t2 + t3 / 538841 - t4 / 65194000;
  const double d = 297.8501921 + 445267.1114034 * t - 0.0018819 * t2 + t3 / 545868 - t4 / 113065000;
  const double m = 357.5291092 + 35999.0502909 * t - 0.0001536 * t2 + t3 / 24490000;
  const double m_prime = 134.9633964 + 477198.8675055 * t + 0.0087414 * t2 + t3 / 69699 - t4 / 14712000;
  const double f = 93.2720950 + 483202.0175233 * t - 0.0036539 * t2 - t3 / 3526000 + t4 / 863310000;
  const double a1 = 119.75 + 131.849 * t, a2 = 53.09 + 479264.290 * t, a3 = 313.45 + 481266.484 * t;
  const double e = 1 - 0.002516 * t - 0.0000074 * t2;  // Eq. 47.6: the Earth's orbit's eccentricity
  const auto eccentricity_factor = [&](int m_multiple) {
    return m_multiple == 0 ? 1.0 : (std::abs(m_multiple) == 1 ? e : e * e);
  };
  double sum_l = 0, sum_r = 0, sum_b = 0;
  for (const Term& term : terms().longitude_distance) {
    const double arg = term.d * d + term.m * m + term.m_prime * m_prime + term.f * f;
    const double factor = eccentricity_factor(term.m);
    sum_l += term.sine * factor * sin_deg(arg);
    sum_r += term.cosine * factor * cos_deg(arg);
  }
  for (const Term& term : terms().latitude)
    sum_b += term.sine * eccentricity_factor(term.m) *
             sin_deg(term.d * d + term.m * m + term.m_prime * m_prime + term.f * f);
  // The additive terms: Venus (A1), Jupiter (A2) and the Earth's flattening (L′ − F).
  sum_l += 3958 * sin_deg(a1) + 1962 * sin_deg(l_prime - f) + 318 * sin_deg(a2);
  sum_b += -2235 * sin_deg(l_prime) + 382 * sin_deg(a3) + 175 * sin_deg(a1 - f) + 175 * sin_deg(a1 + f) +
           127 * sin_deg(l_prime - m_prime) - 115 * sin_deg(l_prime + m_prime);
  return {wrap_360(l_prime + sum_l / 1e6), sum_b / 1e6, 385000.56 + sum_r / 1000};
}

double moon_illuminance_lx(double phase_angle_deg, double distance_km) {
  const double i = std::abs(phase_angle_deg);
  const double magnitude = -12.73 + 0.026 * i + 4e-9 * i * i * i * i;
  const double at_mean_distance = std::pow(10.0, -0.4 * (magnitude + 16.57)) * kLuxPerFootCandle;
  return at_mean_distance * (kMeanDistanceKm / distance_km) * (kMeanDistanceKm / distance_km);
}

MoonPosition moon_position(const SiteLocation& site, double julian_day_ut, const SpaOptions& options) {
  const spa::Steps sun = spa::compute_steps(site, julian_day_ut, options);
  const MoonEcliptic moon = moon_ecliptic(sun.julian_ephemeris_day);
  // Apparent longitude: nutation added (Meeus 47, example 47.a); the moon's aberration is
  // included in the series.
  const double lambda = moon.longitude_deg + sun.nutation.longitude_deg, beta = moon.latitude_deg;
  const double eps = sun.true_obliquity_deg;
  const double ra = wrap_360(degrees(std::atan2(sin_deg(lambda) * cos_deg(eps) - std::tan(radians(beta)) * sin_deg(eps),
                                                cos_deg(lambda))));  // Eq. 13.3
  const double dec =
      degrees(std::asin(sin_deg(beta) * cos_deg(eps) + cos_deg(beta) * sin_deg(eps) * sin_deg(lambda)));  // Eq. 13.4
  const double parallax = degrees(std::asin(kEarthEquatorialRadiusKm / moon.distance_km));                // Meeus 47
  const spa::Topocentric place = spa::topocentric(site, sun.apparent_sidereal_time_deg, ra, dec, parallax, options);
  // Phase angle (Meeus 48.2–48.3) from the geocentric elongation ψ of the moon from the sun.
  const double cos_psi = std::cos(radians(beta)) * cos_deg(lambda - sun.apparent_sun_longitude_deg);  // 48.2, β_sun ≈ 0
  const double psi = std::acos(std::clamp(cos_psi, -1.0, 1.0));
  const double sun_distance_km = sun.earth.radius_au * 149597870.7;
  const double phase =
      degrees(std::atan2(sun_distance_km * std::sin(psi), moon.distance_km - sun_distance_km * cos_psi));
  MoonPosition out{};
  out.altitude_deg = place.apparent_elevation_deg;
  out.azimuth_deg = place.azimuth_deg;
  out.distance_km = moon.distance_km;
  out.right_ascension_deg = ra;
  out.declination_deg = dec;
  out.phase_angle_deg = phase;
  out.illuminated_fraction = (1 + cos_deg(phase)) / 2;
  out.illuminance_lx = moon_illuminance_lx(phase, moon.distance_km);
  out.angular_radius_deg = degrees(std::asin(kMoonRadiusKm / moon.distance_km));
  return out;
}

}  // namespace skylit
