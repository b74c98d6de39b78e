// Luminaire placement and direct illuminance (Type C frame of IES LM-63-02).
// The local frame for aim = −z and no rotation is C0 = +x (east), C90 = +y (north),
// nadir = −z; another aim takes that frame along by the smallest rotation carrying
// −z onto the aim (so a small change of aim moves the C0 plane only a little), then
// the luminaire turns by rotation_deg about its aim.
#include "skylit/lights/luminaire.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace skylit {
namespace {

// Rodrigues: the rotation about unit axis k by angle (cos a, sin a) applied to v.
Vec3 rotate(const Vec3& v, const Vec3& k, double cos_a, double sin_a) {
  return v * cos_a + cross(k, v) * sin_a + k * (dot(k, v) * (1 - cos_a));
}

}  // namespace

Luminaire::Luminaire(Vec3 position, IntensityDistribution distribution, Vec3 aim, double rotation_deg,
                     const TiltTable& tilt)
    : position_(position), distribution_(std::move(distribution)) {
  const double len = length(aim);
  if (!(len > 0) || !std::isfinite(len)) throw std::invalid_argument("a luminaire's aim must be a non-zero vector");
  nadir_ = aim / len;
  const Vec3 down{0, 0, -1};
  Vec3 x{1, 0, 0}, y{0, 1, 0};
  const Vec3 axis = cross(down, nadir_);
  const double s = length(axis), c = dot(down, nadir_);
  if (s > 1e-12) {
    x = rotate(x, axis / s, c, s);
    y = rotate(y, axis / s, c, s);
  } else if (c < 0) {
    // Aimed straight up: half a turn about x (C0 stays east, C90 turns south).
    y = {0, -1, 0};
  }
  // Rotation about the aim, counter-clockwise seen from above (about −nadir).
  const double r = radians(rotation_deg);
  c0_ = normalize(x * std::cos(r) + y * std::sin(r));
  c90_ = normalize(cross(-nadir_, c0_));
  const double tilt_deg = degrees(std::acos(std::clamp(c, -1.0, 1.0)));
  tilt_factor_ = tilt.multiplier(tilt_deg);
}

Vec3 Luminaire::world_direction(double c_deg, double gamma_deg) const {
  const double c = radians(c_deg), g = radians(gamma_deg);
  return c0_ * (std::sin(g) * std::cos(c)) + c90_ * (std::sin(g) * std::sin(c)) + nadir_ * std::cos(g);
}

PhotometricAngles Luminaire::photometric_angles(const Vec3& world_direction) const {
  const Vec3 d = normalize(world_direction);
  const double gamma = degrees(std::acos(std::clamp(dot(d, nadir_), -1.0, 1.0)));
  double c = degrees(std::atan2(dot(d, c90_), dot(d, c0_)));
  if (c < 0) c += 360;
  if (c >= 360) c = 0;  // −tiny + 360 rounds to 360; keep C in [0, 360)
  return {c, gamma};
}

double Luminaire::intensity(const Vec3& world_direction) const {
  const PhotometricAngles a = photometric_angles(world_direction);
  return tilt_factor_ * distribution_.candela(a.c_deg, a.gamma_deg);
}

double Luminaire::illuminance(const Vec3& point, const Vec3& normal) const {
  const Vec3 v = point - position_;
  const double d2 = dot(v, v);
  if (!(d2 > 0)) return 0.0;
  const Vec3 dir = v / std::sqrt(d2);
  const double cos_theta = -dot(dir, normal);
  if (cos_theta <= 0) return 0.0;
  return intensity(dir) * cos_theta / d2;
}

}  // namespace skylit
