#include "skylit/lights/headlamps.h"

#include <algorithm>
#include <cmath>

#include "skylit/core/angles.h"

namespace skylit {

namespace {

double gaussian(double x, double sigma) { return std::exp(-x * x / (2 * sigma * sigma)); }

double smoothstep(double edge0, double edge1, double x) {
  const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

// The low beam's cut-off: flat at 0.3°D left of the elbow (on the H–V vertical), rising
// at 15° to the right up to 0.64°U, flat beyond.
double cut_off_deg(double h_deg) {
  if (h_deg <= 0) return -0.3;
  return std::min(-0.3 + h_deg * std::tan(radians(15.0)), 0.64);
}

double low_beam(double h, double v) {
  const double body = 20000 * gaussian(h - 1.5, h < 1.5 ? 4.0 : 6.0) * gaussian(v + 1.2, 1.2);
  const double foreground = 4000 * gaussian(h, 12.0) * gaussian(v + 2.5, 1.5);
  // 1 well below the cut-off, 0 above it, over 0.4°.
  const double below = 1 - smoothstep(-0.2, 0.2, v - cut_off_deg(h));
  return (body + foreground) * below + 200 * gaussian(h, 30.0) * (1 - below);
}

double high_beam(double h, double v) {
  return 60000 * gaussian(h, 5.0) * gaussian(v, 2.0) + 3000 * gaussian(h, 15.0) * gaussian(v, 4.0);
}

}  // namespace

HeadlampPair place_headlamps(const Vec3& position, double heading_deg) {
  const double a = radians(heading_deg);
  const Vec3 forward{std::sin(a), std::cos(a), 0};
  const Vec3 right{std::cos(a), -std::sin(a), 0};
  const Vec3 centre = position + Vec3{0, 0, kHeadlampHeightM};
  return {centre - right * (kHeadlampSpacingM / 2), centre + right * (kHeadlampSpacingM / 2), forward};
}

double headlamp_candela(Beam beam, double h_deg, double v_deg) {
  // Behind the lamp's plane: dark.
  if (std::abs(h_deg) >= 90 || std::abs(v_deg) >= 90) return 0;
  return beam == Beam::low ? low_beam(h_deg, v_deg) : high_beam(h_deg, v_deg);
}

Luminaire headlamp_luminaire(const Vec3& lamp_position, const Vec3& forward, Beam beam) {
  const Luminaire frame(lamp_position, IntensityDistribution::isotropic(1), forward);
  const Vec3 f = normalize(forward);
  const Vec3 up{0, 0, 1};
  const Vec3 right = normalize(cross(f, up));
  std::vector<double> gammas, cs, candela;
  for (int k = 0; k <= 120; ++k) gammas.push_back(0.1 * k);
  for (int k = 1; k <= 156; ++k) gammas.push_back(12 + 0.5 * k);
  for (int c = 0; c <= 360; ++c) cs.push_back(c);
  for (double c : cs)
    for (double g : gammas) {
      const Vec3 d = frame.world_direction(c, g);
      const double v = degrees(std::asin(std::clamp(dot(d, up), -1.0, 1.0)));
      const double h = degrees(std::atan2(dot(d, right), dot(d, f)));
      candela.push_back(headlamp_candela(beam, h, v));
    }
  return Luminaire(lamp_position, IntensityDistribution::table(CSymmetry::kNone, cs, gammas, candela), forward);
}

std::vector<BeamTestPoint> ece_r112_test_points(Beam beam) {
  if (beam == Beam::low)
    return {
        {"B50L", -3.43, 0.57, 0, 350},   {"75R", 1.15, -0.57, 10100, 0}, {"75L", -3.43, -0.57, 0, 10600},
        {"50L", -3.43, -0.86, 0, 13200}, {"50R", 1.72, -0.86, 10100, 0}, {"50V", 0, -0.86, 5100, 0},
        {"25L", -9, -1.72, 1700, 0},     {"25R", 9, -1.72, 1700, 0},
    };
  return {
      {"HV", 0, 0, 48000, 215000}, {"2.5L", -2.58, 0, 15000, 0},  // 1125 mm at 25 m
      {"2.5R", 2.58, 0, 15000, 0}, {"5L", -5.15, 0, 3750, 0},     // 2250 mm at 25 m
      {"5R", 5.15, 0, 3750, 0},
  };
}

}  // namespace skylit
