// CIELAB (CIE 15:2018) and CIEDE2000 (Sharma, Wu & Dalal 2005, Eqs. 1–17); the
// equation numbers below are theirs.
#include "skylit/spectrum/color_difference.h"

#include <cmath>
#include <numbers>

namespace skylit {

namespace {
// CIE 15:2018 gives the break of the lightness function as exact fractions,
// (24/116)³ and 841/108, rather than the rounded 0.008856 and 7.787 of older
// editions, so that f is continuous with a continuous slope.
constexpr double kDelta = 6.0 / 29.0;
constexpr double kDeltaCubed = kDelta * kDelta * kDelta;

constexpr double kDegrees = 180.0 / std::numbers::pi;
double sin_deg(double degrees) { return std::sin(degrees / kDegrees); }
double cos_deg(double degrees) { return std::cos(degrees / kDegrees); }

// Hue angle in degrees in [0, 360); 0 for a neutral colour (Eq. 4).
double hue_deg(double b, double a_prime) {
  if (b == 0.0 && a_prime == 0.0) return 0.0;
  const double h = std::atan2(b, a_prime) * kDegrees;
  return h < 0.0 ? h + 360.0 : h;
}
}  // namespace

double cielab_f(double ratio) {
  return ratio > kDeltaCubed ? std::cbrt(ratio) : ratio / (3.0 * kDelta * kDelta) + 4.0 / 29.0;
}

double cielab_f_derivative(double ratio) {
  if (ratio > kDeltaCubed) {
    const double cube_root = std::cbrt(ratio);
    return 1.0 / (3.0 * cube_root * cube_root);
  }
  return 1.0 / (3.0 * kDelta * kDelta);
}

Lab lab_from_xyz(const Xyz& xyz, const Xyz& white) {
  const double fx = cielab_f(xyz.x / white.x);
  const double fy = cielab_f(xyz.y / white.y);
  const double fz = cielab_f(xyz.z / white.z);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

double delta_e_2000(const Lab& first, const Lab& second) {
  // Step 1: chroma with the a* axis stretched near neutral (Eqs. 2–5).
  const double pow25_7 = std::pow(25.0, 7.0);
  const double c1 = std::hypot(first.a, first.b), c2 = std::hypot(second.a, second.b);
  const double c_mean_7 = std::pow(0.5 * (c1 + c2), 7.0);
  const double g = 0.5 * (1.0 - std::sqrt(c_mean_7 / (c_mean_7 + pow25_7)));
  const double a1 = (1.0 + g) * first.a, a2 = (1.0 + g) * second.a;
  const double cp1 = std::hypot(a1, first.b), cp2 = std::hypot(a2, second.b);
  const double hp1 = hue_deg(first.b, a1), hp2 = hue_deg(second.b, a2);

  // Step 2: differences (Eqs. 8–11); the hue difference takes the short way round.
  const double delta_l = second.l - first.l;
  const double delta_c = cp2 - cp1;
  const bool either_neutral = cp1 * cp2 == 0.0;
  double delta_h_deg = hp2 - hp1;
  if (either_neutral)
    delta_h_deg = 0.0;
  else if (delta_h_deg > 180.0)
    delta_h_deg -= 360.0;
  else if (delta_h_deg < -180.0)
    delta_h_deg += 360.0;
  const double delta_hue = 2.0 * std::sqrt(cp1 * cp2) * sin_deg(0.5 * delta_h_deg);

  // Step 3: means and weighting functions (Eqs. 12–22); the mean hue also takes the
  // short way round, and is the plain sum when one colour is neutral.
  const double l_mean = 0.5 * (first.l + second.l);
  const double c_mean = 0.5 * (cp1 + cp2);
  double h_mean = hp1 + hp2;
  if (!either_neutral) {
    if (std::abs(hp1 - hp2) <= 180.0)
      h_mean *= 0.5;
    else if (h_mean < 360.0)
      h_mean = 0.5 * (h_mean + 360.0);
    else
      h_mean = 0.5 * (h_mean - 360.0);
  }
  const double t = 1.0 - 0.17 * cos_deg(h_mean - 30.0) + 0.24 * cos_deg(2.0 * h_mean) +
                   0.32 * cos_deg(3.0 * h_mean + 6.0) - 0.20 * cos_deg(4.0 * h_mean - 63.0);
  const double delta_theta_deg = 30.0 * std::exp(-std::pow((h_mean - 275.0) / 25.0, 2.0));
  const double c_mean_p7 = std::pow(c_mean, 7.0);
  const double r_c = 2.0 * std::sqrt(c_mean_p7 / (c_mean_p7 + pow25_7));
  const double l50_sq = (l_mean - 50.0) * (l_mean - 50.0);
  const double s_l = 1.0 + 0.015 * l50_sq / std::sqrt(20.0 + l50_sq);
  const double s_c = 1.0 + 0.045 * c_mean;
  const double s_h = 1.0 + 0.015 * c_mean * t;
  const double r_t = -sin_deg(2.0 * delta_theta_deg) * r_c;

  const double dl = delta_l / s_l, dc = delta_c / s_c, dh = delta_hue / s_h;
  return std::sqrt(dl * dl + dc * dc + dh * dh + r_t * dc * dh);
}

}  // namespace skylit
