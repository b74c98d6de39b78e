// The sun where it is seen and where it is. A scene gives the sun's apparent elevation
// (what SPA computes and what an observer measures: docs/scene-format.md); the
// atmosphere's tables are indexed by its true elevation, the direction of its light
// outside the air (refracted_ray.h). The air lifts the seen sun by about 33′ at the
// horizon and 5′ at 10°, so a scene at sunset (seen 0°) has its true sun at −0.55°,
// where the sky is markedly darker than at 0°.
//
// The elevations here are at the ground, where the scene's surfaces are. Below the
// horizon no sun is seen and an apparent elevation has no physical meaning: there the
// given elevation is taken as the true one less the horizon's lift, the lift fading
// linearly to nothing over the first degree below, so that a sweep of the sun through
// the horizon moves the sky continuously (a twilight's depression, −6° or −12°, is the
// true one, as in the almanacs).
#pragma once

#include <optional>

#include "skylit/atmosphere/transmittance_table.h"
#include "skylit/core/vec3.h"

namespace skylit {

class Atmosphere;

// The map between seen and true elevation (radians) at the ground of this air; the
// identity when the air does not refract (atmosphere.refraction false).
class SunRefraction {
 public:
  SunRefraction(const AtmosphereMedium& medium, double ground_radius_m, double top_radius_m);
  explicit SunRefraction(const Atmosphere& atmosphere);

  double true_elevation(double seen_elevation_rad) const;
  double seen_elevation(double true_elevation_rad) const;
  // The same for directions: the azimuth is kept.
  Vec3 true_direction(const Vec3& seen_to_sun) const;
  Vec3 seen_direction(const Vec3& true_to_sun) const;

  // The sun's beam at radius r along its bent path, for the cosine μ_true of its true
  // zenith angle there.
  struct Beam {
    bool shines = false;      // false: the ray, traced back, meets the ground
    double mu_seen = 0;       // the zenith cosine it arrives from at r
    ColumnDensities columns;  // along the bent path, r to the top
    // The beam's irradiance over what it would be unbent: n²·dμ_seen/dμ_true. A beam
    // that grazed lower bent more and fanned out vertically (the setting sun's flattened
    // disc, about 0.83 of its width at the horizon).
    double spreading = 1;
  };
  Beam beam(double r, double mu_true) const;
  // Per unit extraterrestrial irradiance normal to the sun: the beam's transmittance,
  // times its spreading when `spread` (the irradiance normal to the beam) or not (the
  // disc's radiance); 0 where it does not shine.
  Spectrum sunlight(double r, double mu_true, bool spread = true) const;

 private:
  double mu_true_of(double r, double mu_seen, bool& hits_ground) const;
  // The lowest seen zenith cosine at r whose ray does not come up from the ground.
  double lowest_mu(double r) const;
  // The seen zenith cosine at r of the sun whose true one is mu_true; empty where r lies
  // in the Earth's refracted shadow.
  std::optional<double> mu_seen_at(double r, double mu_true) const;

  const AtmosphereMedium& medium_;
  double ground_radius_, top_radius_;
  bool refracts_;
  double horizon_lift_rad_ = 0;  // the seen sun's lift at the horizon (about 33′)
  double fade_rad_ = 0;          // below the horizon the lift fades over this
};

}  // namespace skylit
