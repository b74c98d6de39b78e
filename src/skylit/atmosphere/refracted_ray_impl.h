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

// One leg from r_low up to r_high for the invariant p: r = r_low + u², midpoint rule in u,
// so that the 1/√(n²r² − p²) of a lowest point (r_low = r_t) becomes finite.
template <typename Air>
void add_leg(const Air& air, double earth_radius, double r_low, double r_high, double p, int samples,
             RefractedRay& ray) {
  if (r_high <= r_low) return;
  const double u_max = std::sqrt(r_high - r_low), du = u_max / samples;
  // n·r − p rises from the leg's start at least as fast as its slope there times
  // r − r_low = u² (n·r is convex where the density falls exponentially). A lowest point
  // found only to Newton's tolerance can leave n·r − p a rounding below zero just above
  // it, which on a leg micrometres long (a nearly horizontal ray) turned 1/√ into 1e150.
  const AirSample start = air(r_low - earth_radius);
  const double slope = start.n + r_low * start.dn_dr;  // d(n·r)/dr
  for (int k = 0; k < samples; ++k) {
    const double u = (k + 0.5) * du, r = r_low + u * u, dr = 2.0 * u * du;
    const AirSample a = air(r - earth_radius);
    const double nr = a.n * r;
    const double rise = std::max(nr - p, slope * u * u);               // n·r − p
    const double root = std::sqrt(std::max(rise * (nr + p), 1e-300));  // √(n²r² − p²)
    const double ds = nr * dr / root;
    ray.columns.rayleigh += a.rayleigh * ds;
    ray.columns.aerosol += a.aerosol * ds;
    ray.columns.ozone += a.ozone * ds;
    ray.bending_rad += -a.dn_dr * p / (a.n * root) * dr;
  }
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
  mu_apparent = std::clamp(mu_apparent, -1.0, 1.0);
  r = std::clamp(r, ground_radius, top_radius);
  const double sin_z = std::sqrt(1.0 - mu_apparent * mu_apparent);
  const double p = air(r - earth_radius).n * r * sin_z;
  if (mu_apparent >= 0) {
    add_leg(air, earth_radius, r, top_radius, p, samples, ray);
  } else {
    // Down to the lowest point, then up from it to the top.
    if (air(ground_radius - earth_radius).n * ground_radius > p) {
      ray.hits_ground = true;
      ray.mu_true = -1;
      return ray;
    }
    const double r_t = std::clamp(lowest_radius(air, earth_radius, p, r * sin_z), ground_radius, r);
    add_leg(air, earth_radius, r_t, r, p, samples, ray);
    add_leg(air, earth_radius, r_t, top_radius, p, samples, ray);
  }
  ray.mu_true = std::cos(std::min(std::acos(mu_apparent) + ray.bending_rad, 3.141592653589793));
  return ray;
}

}  // namespace skylit::refraction
