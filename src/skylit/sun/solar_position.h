// Where the sun is in a site's sky at a given instant: the NREL Solar Position
// Algorithm (SPA) of I. Reda and A. Andreas, "Solar Position Algorithm for Solar
// Radiation Applications", NREL/TP-560-34302 (2003, revised January 2008); also
// Solar Energy 76(5), 577–589 (2004). Its stated uncertainty is ±0.0003° in zenith
// and azimuth for the years −2000 to 6000, given the true ΔT and UT1.
//
// Conventions (docs/sun-position.md): latitude north positive, longitude east positive,
// azimuth clockwise from north (east = 90°), altitude above the horizon including
// atmospheric refraction (the sun as it is seen).
#pragma once

#include <optional>

#include "skylit/sun/time.h"

namespace skylit {

// The years the algorithm is published for.
inline constexpr int kSolarPositionFirstYear = -2000;
inline constexpr int kSolarPositionLastYear = 6000;

struct SiteLocation {
  double latitude_deg = 0;   // geodetic, −90 to 90, north positive
  double longitude_deg = 0;  // −180 to 180, east positive
  double elevation_m = 0;    // above mean sea level
};

// The distance between two sites along the earth's surface, km: the great circle of the
// mean sphere (haversine), within 0.5 % of the ellipsoid's geodesic; for saying how far
// a weather station lies from the site, not for placing anything.
double surface_distance_km(const SiteLocation& a, const SiteLocation& b);

struct SpaOptions {
  // TT − UT in seconds. Unset: estimated from the date (delta_t.h, Espenak & Meeus).
  std::optional<double> delta_t_s;
  // UT1 − UTC in seconds (|value| < 0.9, published by the IERS). The time given is
  // UTC; leaving this 0 shifts the sun by up to 0.004° along its daily path.
  double delta_ut1_s = 0;
  // Air at the site, for refraction only. Unset: the ICAO standard atmosphere at the
  // site's elevation (1013.25 mbar and 15 °C at sea level; 6.5 K/km lapse rate).
  std::optional<double> pressure_mbar;
  std::optional<double> temperature_c;
  // Refraction at the horizon, which with the sun's radius (0.26667°) sets how far
  // below the horizon the refraction correction still applies (SPA's atmos_refract).
  double horizon_refraction_deg = 0.5667;
};

struct SolarPosition {
  double zenith_deg = 0;             // topocentric, refracted: 90 − altitude
  double azimuth_deg = 0;            // clockwise from north, [0, 360)
  double altitude_deg = 0;           // apparent elevation above the horizon, refracted
  double earth_sun_distance_au = 1;  // R: the sun's irradiance scales as 1/R²
  double equation_of_time_min = 0;   // apparent minus mean solar time, minutes
};

// Throws std::invalid_argument for latitude beyond ±90°, a Julian Day outside
// kSolarPositionFirstYear..LastYear, or non-finite inputs (callers that read user
// input check these first and report an InputError).
SolarPosition solar_position(const SiteLocation& site, double julian_day_ut, const SpaOptions& options = {});
SolarPosition solar_position(const SiteLocation& site, const OffsetDateTime& time, const SpaOptions& options = {});

// The ICAO standard atmosphere (ISO 2533) at an elevation, up to 20 km.
double standard_pressure_mbar(double elevation_m);
double standard_temperature_c(double elevation_m);

}  // namespace skylit
