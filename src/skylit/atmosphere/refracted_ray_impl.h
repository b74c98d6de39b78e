// The integration of refracted_ray.h over any source of the air's properties against
// altitude: the medium itself (exact, for tests and single rays) or a fine table of it
// (refracted_sun_table.cpp, which traces tens of thousands of rays).
#pragma once

#include <algorithm>
#include <cmath>

#include "skylit/atmosphere/refracted_ray.h"

namespace skylit::refraction {

// What a ray needs of the air at one altitude.
struct AirSample {
  double rayleigh, aerosol, ozone;  // relative densities
  double n;                         // refractive index
  double dn_dr;                     // its gradient (m⁻¹, < 0)
};

// The medium's air at altitude h, the gradient by a central difference over ±1 m: the
// US Standard Atmosphere's density is exponential within each 1 km row, so this is its
// slope but within 1 m of a row's edge.
AirSample air_sample(const AtmosphereMedium& medium, double h);

// One leg from r_from up to r_high for the invariant p: r = r_low + u², midpoint rule in
// u, so that the 1/√(n²r² − p²) of a lowest point (r_low = r_t) becomes finite. A ray
// that starts upward just above the horizontal has its lowest point (virtually) a little
// below its start: r_low there keeps the integrand smooth in u, where starting the
// substitution at r_from left it a boundary layer narrower than a sample (the sunlight
// 4 % low for rays leaving a point horizontally, 10 % low near the ground's horizon).
// Adds the leg's columns to `ray` and returns the angle θ it travels about the Earth's
// centre, dθ = tan z·dr/r. The bending follows from θ and the end directions
// (trace below) rather than from ∫ dn/dr: the US Standard Atmosphere's dn/dr jumps at
// each 1 km row, and a midpoint rule over a jump moves with the samples, which made the
// bending of neighbouring rays differ by noise (a 1e-5 step in μ gave the spreading
// ±3 % at 8192 samples, garbage at 96); n itself is continuous.
template <typename Air>
double add_leg(const Air& air, double earth_radius, double r_low, double r_from, double r_high, double p,
               double nr_slope, int samples, RefractedRay& ray) {
  if (r_high <= r_from) return 0.0;
  const double u_min = std::sqrt(std::max(0.0, r_from - r_low));
  // u = u_min + span·v², the midpoint rule in v: samples crowd toward the leg's start,
  // where the air is densest (with a virtual lowest point far below, a grid uniform in u
  // spaced them 1 km apart at the ground, coarse for the aerosols).
  const double span = std::sqrt(r_high - r_low) - u_min, dv = 1.0 / samples;
  // n·r − p rises from the lowest point at least as fast as nr_slope, d(n·r)/dr at the
  // lowest point or the ground, times r − r_low = u² (n·r is convex where the density
  // falls exponentially). A lowest point found only to Newton's tolerance can leave
  // n·r − p a rounding below zero just above it, which on a leg micrometres long (a
  // nearly horizontal ray) turned 1/√ into 1e150.
  // The same quadrature of a straight ray whose lowest point is r_low, whose θ is known
  // (acos(r_low/r_from) − acos(r_low/r_high)), takes out the quadrature's own error
  // (a control variate): the bending is θ less a difference of angles near 1 rad, and
  // without it weak refraction (n − 1 = 1e-6) came out 0.45 % high.
  double travel = 0.0, straight = 0.0;
  const auto angle_from_lowest = [r_low](double radius) {  // acos(r_low/radius), stably
    return std::atan2(std::sqrt(std::max(0.0, (radius - r_low) * (radius + r_low))), r_low);
  };
  for (int k = 0; k < samples; ++k) {
    const double v = (k + 0.5) * dv, u = u_min + span * v * v, du = 2.0 * span * v * dv;
    const double r = r_low + u * u, dr = 2.0 * u * du;
    const AirSample a = air(r - earth_radius);
    const double nr = a.n * r;
    const double rise = std::max(nr - p, nr_slope * u * u);            // n·r − p
    const double root = std::sqrt(std::max(rise * (nr + p), 1e-300));  // √(n²r² − p²)
    const double ds = nr * dr / root;
    ray.columns.rayleigh += a.rayleigh * ds;
    ray.columns.aerosol += a.aerosol * ds;
    ray.columns.ozone += a.ozone * ds;
    travel += p / (r * root) * dr;
    straight += r_low * 2.0 * du / (r * std::sqrt(r + r_low));  // r_low·dr/(r·√(r² − r_low²))
  }
  return travel - (straight - (angle_from_lowest(r_high) - angle_from_lowest(r_from)));
}

// The apparent zenith cosine, at radius r, of the ray whose lowest point is the ground
// (its n·r·sin z equal to the ground's n·r, Bouguer's invariant): rays arriving from
// lower come up from the ground.
template <typename Air>
double grazing_mu(const Air& air, double earth_radius, double r, double ground_radius) {
  const double s = air(ground_radius - earth_radius).n * ground_radius / (air(r - earth_radius).n * r);
  return -std::sqrt(std::max(0.0, 1.0 - s * s));
}

// The radius where n(r)·r = p (Newton's method; n·r grows with r unless the air ducts
// light, which needs dn/dr < −1/r, 25 times the standard gradient).
template <typename Air>
double lowest_radius(const Air& air, double earth_radius, double p, double r_start) {
  double r = r_start;
  for (int i = 0; i < 30; ++i) {
    const AirSample a = air(r - earth_radius);
    const double step = (a.n * r - p) / (a.n + r * a.dn_dr);
    r -= step;
    if (std::abs(step) < 1e-7) break;
  }
  return r;
}

template <typename Air>
RefractedRay trace(const Air& air, double earth_radius, double r, double mu_apparent, double ground_radius,
                   double top_radius, int samples) {
  RefractedRay ray;
  double travel = 0.0;  // θ
  mu_apparent = std::clamp(mu_apparent, -1.0, 1.0);
  r = std::clamp(r, ground_radius, top_radius);
  const double sin_z = std::sqrt(1.0 - mu_apparent * mu_apparent);
  const double p = air(r - earth_radius).n * r * sin_z;
  // The air is read no lower than the ground (a virtual lowest point may lie far below).
  const auto nr_slope_at = [&](double radius) {
    const double h = std::max(radius, ground_radius) - earth_radius;
    const AirSample a = air(h);
    return a.n + (h + earth_radius) * a.dn_dr;
  };
  if (mu_apparent >= 0) {
    // The virtual lowest point, where n·r = p below the start (one fixed-point step from
    // r·sin z, which lands just above it; below the ground the air's index taken as the
    // ground's).
    const double r_virtual = std::min(r, p / air(std::max(r * sin_z, ground_radius) - earth_radius).n);
    travel = add_leg(air, earth_radius, r_virtual, r, top_radius, p, nr_slope_at(r_virtual), samples, ray);
  } else {
    // Down to the lowest point, then up from it to the top.
    if (air(ground_radius - earth_radius).n * ground_radius > p) {
      ray.hits_ground = true;
      ray.mu_true = -1;
      return ray;
    }
    const double r_t = std::clamp(lowest_radius(air, earth_radius, p, r * sin_z), ground_radius, r);
    const double slope = nr_slope_at(r_t);
    travel = add_leg(air, earth_radius, r_t, r_t, r, p, slope, samples, ray) +
             add_leg(air, earth_radius, r_t, r_t, top_radius, p, slope, samples, ray);
  }
  // At the top the ray's zenith angle there is asin(p/(n·r_top)); seen from the point,
  // whose vertical is turned by θ from the top's, the ray comes from that plus θ.
  const double z_top = std::asin(std::min(1.0, p / (air(top_radius - earth_radius).n * top_radius)));
  ray.bending_rad = z_top + travel - std::acos(mu_apparent);
  ray.mu_true = std::cos(std::min(std::acos(mu_apparent) + ray.bending_rad, 3.141592653589793));
  return ray;
}

}  // namespace skylit::refraction
