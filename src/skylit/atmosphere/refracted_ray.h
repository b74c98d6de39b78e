// Sunlight bent by the air on its way to a point: the ray through a spherically
// stratified atmosphere whose refractive index n(r) falls with height. Along it
// Bouguer's invariant n(r)·r·sin z = p holds (z: the ray's zenith angle where it is),
// so the path and its turning follow from one-dimensional integrals over r (Born & Wolf,
// Principles of Optics, §3.2.2; the astronomical refraction integral, Explanatory
// Supplement to the Astronomical Almanac 1992, §3.28):
//   turning    dB = −(dn/dr) · tan z / n · dr,   tan z = p / √(n²r² − p²),
//   path       ds = n·r·dr / √(n²r² − p²).
// A ray that reaches the point from below its local horizontal first passed a lowest
// point, r_t with n(r_t)·r_t = p, and both of its legs are integrated. The turning
// always bends the ray toward the denser air, so the direction it came from outside the
// atmosphere is the apparent one turned down by B: z_true = z_apparent + B.
// The refractivity is n − 1 = (n₀ − 1)·ρ/ρ₀ (Gladstone–Dale), with n₀ the air's index
// at sea level at 550 nm (optical_properties.h); docs/atmosphere.md, "Twilight".
#pragma once

#include "skylit/atmosphere/optical_properties.h"
#include "skylit/atmosphere/transmittance_table.h"

namespace skylit {

struct RefractedRay {
  bool hits_ground = false;  // the ray, traced back, meets the ground: no sunlight
  double mu_true = 1;        // zenith cosine, at the point, of the ray's direction outside the atmosphere
  double bending_rad = 0;    // B: how far the ray turned between the top and the point
  ColumnDensities columns;   // ∫ρ ds along the bent path, from the point to the top
};

// The ray that arrives at radius r from apparent zenith cosine μ_a (the direction it
// comes from), traced back to the top of the atmosphere. `samples` per leg, crowded
// toward the leg's lowest point (the integrands there are finite after r = r_low + u²).
RefractedRay trace_refracted_ray(const AtmosphereMedium& medium, double r, double mu_apparent, double ground_radius_m,
                                 double top_radius_m, int samples = 96);

}  // namespace skylit
