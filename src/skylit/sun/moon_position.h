// The moon in a site's sky: its position by J. Meeus, Astronomical Algorithms (2nd ed.,
// 1998), chapter 47 (the ELP-2000/82 series truncated to the 60 + 60 terms of Tables
// 47.A and 47.B, data/moon_meeus_47.csv: about 10″ in longitude, 4″ in latitude), its
// phase angle (chapter 48) and the illuminance it gives outside the atmosphere
// (K. Krisciunas and B. E. Schaefer, "A model of the brightness of moonlight", PASP 103
// (1991) 1033, Eqs. 20–21). The topocentric place, parallax and refraction as for the
// sun (spa_steps.h). docs/night-sky.md.
#pragma once

#include "skylit/sun/solar_position.h"

namespace skylit {

// Geocentric ecliptic coordinates of the moon's centre, referred to the mean equinox
// of the date (Meeus 47: λ, β, Δ) at a Julian Ephemeris Day (TT).
struct MoonEcliptic {
  double longitude_deg;  // λ, [0, 360)
  double latitude_deg;   // β
  double distance_km;    // Δ, centre to centre
};
MoonEcliptic moon_ecliptic(double julian_ephemeris_day);

struct MoonPosition {
  double altitude_deg;         // apparent (topocentric, refracted)
  double azimuth_deg;          // clockwise from north
  double distance_km;          // geocentric
  double right_ascension_deg;  // geocentric, apparent (nutation included)
  double declination_deg;
  double phase_angle_deg;       // i: sun–moon–earth angle, 0 full, 180 new
  double illuminated_fraction;  // k = (1 + cos i) / 2
  double illuminance_lx;        // on a plane facing the moon, outside the atmosphere
  double angular_radius_deg;    // of the disc, seen from the Earth's centre
};

// Throws std::invalid_argument as solar_position does.
MoonPosition moon_position(const SiteLocation& site, double julian_day_ut, const SpaOptions& options = {});

// Krisciunas & Schaefer: the moon's V magnitude m = −12.73 + 0.026 |i| + 4e-9 i⁴ at the
// mean distance (384 400 km), and I = 10^(−0.4 (m + 16.57)) foot-candles (V = 0 gives
// 2.54e-6 lx), scaled to the distance by its inverse square. The opposition surge
// within a few degrees of full is not in the formula (up to +35 % there, they note).
double moon_illuminance_lx(double phase_angle_deg, double distance_km);

}  // namespace skylit
