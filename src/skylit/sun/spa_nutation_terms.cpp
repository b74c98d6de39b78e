// Nutation in longitude (Δψ) and in obliquity (Δε): Reda & Andreas, NREL/TP-560-34302
// (revised 2008), §3.4, Eqs. 15–23, with the 63 periodic terms of the paper's Table
// A4.3 (the IAU 1980 theory of nutation, as in Meeus, Astronomical Algorithms, Table
// 22.A). The numbers below are those published numbers.
#include <cmath>
#include <iterator>
#include <numbers>

#include "skylit/sun/spa_steps.h"

namespace skylit::spa {

namespace {

// One row: the multiples Y0..Y4 of the arguments X0..X4, then the coefficients a, b
// (of sin, for Δψ) and c, d (of cos, for Δε), in units of 0.0001 arcsecond.
struct NutationTerm {
  int y[5];
  double a, b, c, d;
};

constexpr NutationTerm kTerms[] = {
    {{0, 0, 0, 0, 1}, -171996, -174.2, 92025, 8.9},
    {{-2, 0, 0, 2, 2}, -13187, -1.6, 5736, -3.1},
    {{0, 0, 0, 2, 2}, -2274, -0.2, 977, -0.5},
    {{0, 0, 0, 0, 2}, 2062, 0.2, -895, 0.5},
    {{0, 1, 0, 0, 0}, 1426, -3.4, 54, -0.1},
    {{0, 0, 1, 0, 0}, 712, 0.1, -7, 0},
    {{-2, 1, 0, 2, 2}, -517, 1.2, 224, -0.6},
    {{0, 0, 0, 2, 1}, -386, -0.4, 200, 0},
    {{0, 0, 1, 2, 2}, -301, 0, 129, -0.1},
    {{-2, -1, 0, 2, 2}, 217, -0.5, -95, 0.3},
    {{-2, 0, 1, 0, 0}, -158, 0, 0, 0},
    {{-2, 0, 0, 2, 1}, 129, 0.1, -70, 0},
    {{0, 0, -1, 2, 2}, 123, 0, -53, 0},
    {{2, 0, 0, 0, 0}, 63, 0, 0, 0},
    {{0, 0, 1, 0, 1}, 63, 0.1, -33, 0},
    {{2, 0, -1, 2, 2}, -59, 0, 26, 0},
    {{0, 0, -1, 0, 1}, -58, -0.1, 32, 0},
    {{0, 0, 1, 2, 1}, -51, 0, 27, 0},
    {{-2, 0, 2, 0, 0}, 48, 0, 0, 0},
    {{0, 0, -2, 2, 1}, 46, 0, -24, 0},
    {{2, 0, 0, 2, 2}, -38, 0, 16, 0},
    {{0, 0, 2, 2, 2}, -31, 0, 13, 0},
    {{0, 0, 2, 0, 0}, 29, 0, 0, 0},
    {{-2, 0, 1, 2, 2}, 29, 0, -12, 0},
    {{0, 0, 0, 2, 0}, 26, 0, 0, 0},
    {{-2, 0, 0, 2, 0}, -22, 0, 0, 0},
    {{0, 0, -1, 2, 1}, 21, 0, -10, 0},
    {{0, 2, 0, 0, 0}, 17, -0.1, 0, 0},
    {{2, 0, -1, 0, 1}, 16, 0, -8, 0},
    {{-2, 2, 0, 2, 2}, -16, 0.1, 7, 0},
    {{0, 1, 0, 0, 1}, -15, 0, 9, 0},
    {{-2, 0, 1, 0, 1}, -13, 0, 7, 0},
    {{0, -1, 0, 0, 1}, -12, 0, 6, 0},
    {{0, 0, 2, -2, 0}, 11, 0, 0, 0},
    {{2, 0, -1, 2, 1}, -10, 0, 5, 0},
    {{2, 0, 1, 2, 2}, -8, 0, 3, 0},
    {{0, 1, 0, 2, 2}, 7, 0, -3, 0},
    {{-2, 1, 1, 0, 0}, -7, 0, 0, 0},
    {{0, -1, 0, 2, 2}, -7, 0, 3, 0},
    {{2, 0, 0, 2, 1}, -7, 0, 3, 0},
    {{2, 0, 1, 0, 0}, 6, 0, 0, 0},
    {{-2, 0, 2, 2, 2}, 6, 0, -3, 0},
    {{-2, 0, 1, 2, 1}, 6, 0, -3, 0},
    {{2, 0, -2, 0, 1}, -6, 0, 3, 0},
    {{2, 0, 0, 0, 1}, -6, 0, 3, 0},
    {{0, -1, 1, 0, 0}, 5, 0, 0, 0},
    {{-2, -1, 0, 2, 1}, -5, 0, 3, 0},
    {{-2, 0, 0, 0, 1}, -5, 0, 3, 0},
    {{0, 0, 2, 2, 1}, -5, 0, 3, 0},
    {{-2, 0, 2, 0, 1}, 4, 0, 0, 0},
    {{-2, 1, 0, 2, 1}, 4, 0, 0, 0},
    {{0, 0, 1, -2, 0}, 4, 0, 0, 0},
    {{-1, 0, 1, 0, 0}, -4, 0, 0, 0},
    {{-2, 1, 0, 0, 0}, -4, 0, 0, 0},
    {{1, 0, 0, 0, 0}, -4, 0, 0, 0},
    {{0, 0, 1, 2, 0}, 3, 0, 0, 0},
    {{0, 0, -2, 2, 2}, -3, 0, 0, 0},
    {{-1, -1, 1, 0, 0}, -3, 0, 0, 0},
    {{0, 1, 1, 0, 0}, -3, 0, 0, 0},
    {{0, -1, 1, 2, 2}, -3, 0, 0, 0},
    {{2, -1, -1, 2, 2}, -3, 0, 0, 0},
    {{0, 0, 3, 2, 2}, -3, 0, 0, 0},
    {{2, -1, 0, 2, 2}, -3, 0, 0, 0},
};
static_assert(std::size(kTerms) == 63, "Table A4.3 has 63 rows");

// Eqs. 15–19: the fundamental arguments, in degrees, as cubics in JCE.
double cubic(double c0, double c1, double c2, double c3, double x) { return c0 + x * (c1 + x * (c2 + x * c3)); }

}  // namespace

Nutation nutation(double jce) {
  const double x[5] = {
      cubic(297.85036, 445267.111480, -0.0019142, 1.0 / 189474.0, jce),  // mean elongation of the moon from the sun
      cubic(357.52772, 35999.050340, -0.0001603, -1.0 / 300000.0, jce),  // mean anomaly of the sun
      cubic(134.96298, 477198.867398, 0.0086972, 1.0 / 56250.0, jce),    // mean anomaly of the moon
      cubic(93.27191, 483202.017538, -0.0036825, 1.0 / 327270.0, jce),   // moon's argument of latitude
      cubic(125.04452, -1934.136261, 0.0020708, 1.0 / 450000.0, jce),    // longitude of the moon's ascending node
  };
  double psi = 0, epsilon = 0;
  for (const NutationTerm& term : kTerms) {
    double argument_deg = 0;
    for (int j = 0; j < 5; ++j) argument_deg += x[j] * term.y[j];
    const double argument = argument_deg * (std::numbers::pi / 180.0);
    psi += (term.a + term.b * jce) * std::sin(argument);
    epsilon += (term.c + term.d * jce) * std::cos(argument);
  }
  // Eqs. 22–23: from units of 0.0001″ to degrees.
  constexpr double kTenThousandthArcsecondsPerDegree = 36000000.0;
  return {psi / kTenThousandthArcsecondsPerDegree, epsilon / kTenThousandthArcsecondsPerDegree};
}

}  // namespace skylit::spa
