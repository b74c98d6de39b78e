// One cloud (§6, Eq. 16): its solid (cloud_shape.h), the march through it
// (cloud_march.h), the optical depth toward the sun tabulated once per sun direction
// (sun_depth_grid.h) and the light it scatters (cloud_scattering.h), held together for
// the cloud layer (cloud_layer.h) and the renderer. Each concern lives in its own unit;
// this class only keeps a cloud's geometry and its sun grid side by side and says which
// one a query uses.
#pragma once

#include "skylit/clouds/cloud_march.h"
#include "skylit/clouds/cloud_scattering.h"
#include "skylit/clouds/cloud_shape.h"
#include "skylit/clouds/sun_depth_grid.h"
#include "skylit/core/vec3.h"
#include "skylit/spectrum/spectrum.h"

namespace skylit {

// A cloud is its solid (shape(), thickness, contains, clip, ...) with a sun grid.
class Cloud : public CloudGeometry {
 public:
  // Negative or non-finite sizes are taken as 0 (an empty cloud).
  explicit Cloud(const CloudShape& shape) : CloudGeometry(shape) {}

  // Optical depth (grey) along o + t·d, t in [t_min, t_max], d a unit vector (marched).
  double optical_depth(const Vec3& o, const Vec3& d, double t_min, double t_max) const {
    return cloud_optical_depth(*this, o, d, t_min, t_max);
  }
  double transmittance(const Vec3& o, const Vec3& d, double t_min, double t_max) const;
  // e^{−t'} from p toward the sun through this cloud: one look-up where the ray enters
  // the bounding volume if the sun grid is prepared for to_sun, else marched.
  double sun_transmittance(const Vec3& p, const Vec3& to_sun) const;

  // Makes room for t' toward to_sun and the depth away from it (SunDepthGrid), whose
  // nodes look-ups march as they need them. Call once per scene / sun direction; not
  // thread-safe against concurrent scatter() calls (look-ups are safe among themselves).
  // A zero or non-finite direction clears the grid.
  void prepare_sun(const Vec3& to_sun) { sun_depths_.prepare(*this, to_sun); }
  void clear_sun() { sun_depths_.clear(); }
  // Whether scatter() with this (unit or not) sun direction will use the grid.
  bool sun_prepared_for(const Vec3& to_sun) const { return sun_depths_.prepared_for(to_sun); }
  // t' at p toward the prepared sun by trilinear interpolation of the grid (p inside the
  // bounding volume or clamped onto it). Only meaningful when a grid is prepared.
  double interpolated_sun_depth(const Vec3& p) const { return sun_depths_.depth_at(*this, p); }
  // The sun grid's depths marched so far, toward and away from the sun (for the tests).
  int marched_sun_nodes() const { return sun_depths_.marched_nodes(); }

  // In-scattered radiance and transmittance of the segment of the viewing ray o + t·d
  // (d unit, from the viewer), t in [t_min, t_max] (Eq. 16 without I_behind;
  // scatter_through_cloud). t' comes from the grid if prepare_sun was called with
  // light.to_sun, else is marched.
  CloudScattering scatter(const Vec3& o, const Vec3& d, double t_min, double t_max, const CloudLighting& light) const {
    return scatter_through_cloud(*this, sun_depths_, o, d, t_min, t_max, light);
  }
  // Eq. 16 in full: I_behind · e^{−t_total} + in-scattered.
  Spectrum radiance(const Vec3& o, const Vec3& d, double t_min, double t_max, const Spectrum& behind,
                    const CloudLighting& light) const;

 private:
  SunDepthGrid sun_depths_;
};

}  // namespace skylit
