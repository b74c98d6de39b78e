// A luminaire placed in the world: position, aim (the direction of its nadir, γ = 0)
// and a rotation about the aim, with a Type C intensity distribution (IES LM-63-02).
// Gives the intensity toward a world direction and the direct illuminance
// I·cos θ / d² it puts on a surface (no occlusion here). Frame: docs/lights.md.
#pragma once

#include "skylit/core/vec3.h"
#include "skylit/lights/photometry.h"

namespace skylit {

struct PhotometricAngles {
  double c_deg;      // [0, 360), counter-clockwise seen from above (from −aim)
  double gamma_deg;  // 0–180 from the nadir (the aim)
};

class Luminaire {
 public:
  // aim: any non-zero vector (normalised here), default straight down. rotation_deg
  // turns the luminaire about its aim, counter-clockwise seen from above (looking
  // along the aim), so the C0 plane moves toward where C90 was. tilt: LM-63 tilt
  // multipliers, evaluated at the angle between the aim and straight down.
  // Throws std::invalid_argument for a zero or non-finite aim.
  Luminaire(Vec3 position, IntensityDistribution distribution, Vec3 aim = {0, 0, -1}, double rotation_deg = 0,
            const TiltTable& tilt = {});

  const Vec3& position() const { return position_; }
  const Vec3& aim() const { return nadir_; }
  const IntensityDistribution& distribution() const { return distribution_; }
  // The lamp-output multiplier from the tilt table at this luminaire's tilt.
  double tilt_multiplier() const { return tilt_factor_; }

  // World unit vector toward photometric angles (C, γ), and back.
  Vec3 world_direction(double c_deg, double gamma_deg) const;
  PhotometricAngles photometric_angles(const Vec3& world_direction) const;

  // Candela toward a world direction (any length, non-zero).
  double intensity(const Vec3& world_direction) const;
  // Illuminance in lux at `point` on a surface with unit normal `normal`: I·cos θ / d²,
  // θ between the normal and the direction back to the luminaire; 0 when the surface
  // faces away or the point is at the luminaire.
  double illuminance(const Vec3& point, const Vec3& normal) const;

 private:
  Vec3 position_;
  IntensityDistribution distribution_;
  Vec3 nadir_, c0_, c90_;  // orthonormal: C0 × C90 = −nadir (right-handed, "up" = −nadir)
  double tilt_factor_ = 1;
};

}  // namespace skylit
