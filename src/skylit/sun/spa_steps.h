// The steps of the NREL Solar Position Algorithm (Reda & Andreas, NREL/TP-560-34302,
// revised 2008), each quantity named after the paper's symbol and section, so that
// every intermediate can be checked against the paper's worked example (its Table
// A5.1). solar_position.h is the interface for everyone else.
#pragma once

#include "skylit/sun/solar_position.h"

namespace skylit::spa {

// §3.2: the Earth's heliocentric position from the periodic terms of Table A4.2
// (a truncation of VSOP87), at JME Julian ephemeris millennia from J2000.0.
struct HeliocentricEarth {
  double longitude_deg;  // L, [0, 360)
  double latitude_deg;   // B
  double radius_au;      // R
};
HeliocentricEarth heliocentric_earth(double julian_ephemeris_millennium);

// §3.4: nutation in longitude (Δψ) and obliquity (Δε), from the 63 terms of Table
// A4.3 (the IAU 1980 series), at JCE Julian ephemeris centuries from J2000.0.
struct Nutation {
  double longitude_deg;  // Δψ
  double obliquity_deg;  // Δε
};
Nutation nutation(double julian_ephemeris_century);

// §3.11–3.15 for any body at a geocentric right ascension and declination (degrees,
// apparent) and equatorial horizontal parallax ξ: its place in the site's sky, with
// refraction. The sun's ξ is 8.794″/R; the moon's asin(6378.14 km / Δ) (Meeus 40).
struct Topocentric {
  double hour_angle_deg;                   // H, geocentric
  double equatorial_parallax_deg;          // ξ
  double parallax_in_right_ascension_deg;  // Δα
  double right_ascension_deg;              // α′
  double declination_deg;                  // δ′
  double topocentric_hour_angle_deg;       // H′
  double true_elevation_deg;               // e0
  double refraction_deg;                   // Δe
  double apparent_elevation_deg;           // e
  double astronomers_azimuth_deg;          // Γ
  double azimuth_deg;                      // Φ
};
Topocentric topocentric(const SiteLocation& site, double apparent_sidereal_time_deg, double right_ascension_deg,
                        double declination_deg, double equatorial_parallax_deg, const SpaOptions& options);

// Every quantity of §3.1–3.15, for tests and for whoever wants to look inside.
struct Steps {
  double julian_day;                       // JD (UT1)
  double julian_ephemeris_day;             // JDE
  double julian_century;                   // JC
  double julian_ephemeris_century;         // JCE
  double julian_ephemeris_millennium;      // JME
  HeliocentricEarth earth;                 // L, B, R
  double geocentric_longitude_deg;         // Θ
  double geocentric_latitude_deg;          // β
  Nutation nutation;                       // Δψ, Δε
  double mean_obliquity_arcsec;            // ε0
  double true_obliquity_deg;               // ε
  double aberration_deg;                   // Δτ
  double apparent_sun_longitude_deg;       // λ
  double mean_sidereal_time_deg;           // ν0, at Greenwich
  double apparent_sidereal_time_deg;       // ν, at Greenwich
  double right_ascension_deg;              // α, geocentric
  double declination_deg;                  // δ, geocentric
  double hour_angle_deg;                   // H, measured westward from south
  double equatorial_parallax_deg;          // ξ
  double parallax_in_right_ascension_deg;  // Δα
  double topocentric_right_ascension_deg;  // α′
  double topocentric_declination_deg;      // δ′
  double topocentric_hour_angle_deg;       // H′
  double true_elevation_deg;               // e0, without refraction
  double refraction_deg;                   // Δe
  double apparent_elevation_deg;           // e
  double zenith_deg;                       // θ
  double astronomers_azimuth_deg;          // Γ, westward from south
  double azimuth_deg;                      // Φ, eastward from north
  double equation_of_time_min;             // E (§A.1)
};
Steps compute_steps(const SiteLocation& site, double julian_day_ut, const SpaOptions& options);

}  // namespace skylit::spa
