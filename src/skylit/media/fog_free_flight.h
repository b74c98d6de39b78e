// Where light travelling back along a ray last scattered in the fog, for the
// path-traced reference: free-flight distances drawn in the layer's exponential
// density (Eq. 2) by inverting its optical depth in closed form along the ray (the
// column N(s) of Eq. 10, fog_layer.h), not by stepping, so there is no step size to
// bias the result.
//
// With a spectral extinction (b > 0 in Eq. 9) each bin would want its own distances:
// one bin (the hero) is drawn to place the event, and every bin is weighed by its own
// probability over the mixture of all bins' (one-sample multiple importance sampling
// over wavelengths, after Wilkie et al. 2014, "Hero wavelength spectral sampling"). For
// the grey default (b = 0) the weights are exactly the single-scattering albedo and 1.
#pragma once

#include "skylit/geometry/ray_tracer.h"
#include "skylit/media/fog_layer.h"
#include "skylit/spectrum/spectrum.h"

namespace skylit {

struct FogFlight {
  bool scattered = false;  // in the fog, before `distance`
  double distance = 0;     // where it scattered (when it did)
  Spectrum weight{1.0f};   // what the path's throughput is multiplied by
};

// Along `ray` (unit direction) from its origin up to `t_end` (a surface; may be
// infinite), from two uniform numbers in [0, 1).
FogFlight sample_fog_flight(const FogLayer& fog, const Ray& ray, double t_end, double u_bin, double u_depth);

// The fog's transmittance along `ray` from its origin to `t_end` (may be infinite).
Spectrum fog_transmittance(const FogLayer& fog, const Ray& ray, double t_end);

}  // namespace skylit
