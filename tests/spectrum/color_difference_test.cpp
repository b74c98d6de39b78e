// CIEDE2000 against the published test data of Sharma, Wu & Dalal (2005), Table 1
// (all 34 pairs, which were chosen to exercise the hue-mean, hue-difference and
// rotation-term branches), and CIELAB against values that follow from its definition.
#include "skylit/spectrum/color_difference.h"

#include <gtest/gtest.h>

namespace skylit {
namespace {

struct SharmaPair {
  Lab first, second;
  double delta_e;
};

// Sharma, Wu & Dalal 2005, Table 1: L1 a1 b1, L2 a2 b2, ΔE00 (4 decimals).
const SharmaPair kSharmaTable1[] = {
    {{50.0000, 2.6772, -79.7751}, {50.0000, 0.0000, -82.7485}, 2.0425},
    {{50.0000, 3.1571, -77.2803}, {50.0000, 0.0000, -82.7485}, 2.8615},
    {{50.0000, 2.8361, -74.0200}, {50.0000, 0.0000, -82.7485}, 3.4412},
    {{50.0000, -1.3802, -84.2814}, {50.0000, 0.0000, -82.7485}, 1.0000},
    {{50.0000, -1.1848, -84.8006}, {50.0000, 0.0000, -82.7485}, 1.0000},
    {{50.0000, -0.9009, -85.5211}, {50.0000, 0.0000, -82.7485}, 1.0000},
    {{50.0000, 0.0000, 0.0000}, {50.0000, -1.0000, 2.0000}, 2.3669},
    {{50.0000, -1.0000, 2.0000}, {50.0000, 0.0000, 0.0000}, 2.3669},
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0009}, 7.1792},
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0010}, 7.1792},
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0011}, 7.2195},
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0012}, 7.2195},
    {{50.0000, -0.0010, 2.4900}, {50.0000, 0.0009, -2.4900}, 4.8045},
    {{50.0000, -0.0010, 2.4900}, {50.0000, 0.0010, -2.4900}, 4.8045},
    {{50.0000, -0.0010, 2.4900}, {50.0000, 0.0011, -2.4900}, 4.7461},
    {{50.0000, 2.5000, 0.0000}, {50.0000, 0.0000, -2.5000}, 4.3065},
    {{50.0000, 2.5000, 0.0000}, {73.0000, 25.0000, -18.0000}, 27.1492},
    {{50.0000, 2.5000, 0.0000}, {61.0000, -5.0000, 29.0000}, 22.8977},
    {{50.0000, 2.5000, 0.0000}, {56.0000, -27.0000, -3.0000}, 31.9030},
    {{50.0000, 2.5000, 0.0000}, {58.0000, 24.0000, 15.0000}, 19.4535},
    {{50.0000, 2.5000, 0.0000}, {50.0000, 3.1736, 0.5854}, 1.0000},
    {{50.0000, 2.5000, 0.0000}, {50.0000, 3.2972, 0.0000}, 1.0000},
    {{50.0000, 2.5000, 0.0000}, {50.0000, 1.8634, 0.5757}, 1.0000},
    {{50.0000, 2.5000, 0.0000}, {50.0000, 3.2592, 0.3350}, 1.0000},
    {{60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}, 1.2644},
    {{63.0109, -31.0961, -5.8663}, {62.8187, -29.7946, -4.0864}, 1.2630},
    {{61.2901, 3.7196, -5.3901}, {61.4292, 2.2480, -4.9620}, 1.8731},
    {{35.0831, -44.1164, 3.7933}, {35.0232, -40.0716, 1.5901}, 1.8645},
    {{22.7233, 20.0904, -46.6940}, {23.0331, 14.9730, -42.5619}, 2.0373},
    {{36.4612, 47.8580, 18.3852}, {36.2715, 50.5065, 21.2231}, 1.4146},
    {{90.8027, -2.0831, 1.4410}, {91.1528, -1.6435, 0.0447}, 1.4441},
    {{90.9257, -0.5406, -0.9208}, {88.6381, -0.8985, -0.7239}, 1.5381},
    {{6.7747, -0.2908, -2.4247}, {5.8714, -0.0985, -2.2286}, 0.6377},
    {{2.0776, 0.0795, -1.1350}, {0.9033, -0.0636, -0.5514}, 0.9082},
};

TEST(ColorDifference, Ciede2000MatchesSharmaTable1) {
  // The table gives ΔE00 to 4 decimals, so a correct implementation is within half a
  // unit of the last place; 1e-4 allows for that rounding and nothing more.
  for (size_t i = 0; i < std::size(kSharmaTable1); ++i) {
    const SharmaPair& pair = kSharmaTable1[i];
    EXPECT_NEAR(delta_e_2000(pair.first, pair.second), pair.delta_e, 1e-4) << "pair " << i + 1;
  }
}

TEST(ColorDifference, Ciede2000IsSymmetricAndZeroForEqualColours) {
  for (const SharmaPair& pair : kSharmaTable1) {
    EXPECT_NEAR(delta_e_2000(pair.first, pair.second), delta_e_2000(pair.second, pair.first), 1e-12);
    EXPECT_EQ(delta_e_2000(pair.first, pair.first), 0.0);
  }
}

TEST(ColorDifference, LabOfWhiteGreyAndDarkColours) {
  const Xyz white{0.9505, 1.0, 1.089};
  const Lab lab_white = lab_from_xyz(white, white);
  EXPECT_NEAR(lab_white.l, 100.0, 1e-12);
  EXPECT_NEAR(lab_white.a, 0.0, 1e-12);
  EXPECT_NEAR(lab_white.b, 0.0, 1e-12);
  // Y = 0.18 of white: L* = 116 · 0.18^(1/3) − 16 = 49.4961 (neutral, so a* = b* = 0).
  const Lab grey = lab_from_xyz({0.18 * white.x, 0.18, 0.18 * white.z}, white);
  EXPECT_NEAR(grey.l, 49.4961, 1e-4);
  EXPECT_NEAR(grey.a, 0.0, 1e-12);
  // Below (6/29)³ the linear segment: L* = 116 · Y / (3 (6/29)²) = (29/3)³ Y = 903.2963 Y.
  EXPECT_NEAR(lab_from_xyz({0, 0.001, 0}, white).l, 0.9032963, 1e-7);
  // The two pieces of f meet with equal value and slope at (6/29)³.
  const double knee = 216.0 / 24389.0;
  EXPECT_NEAR(cielab_f(knee * (1 + 1e-12)), cielab_f(knee * (1 - 1e-12)), 1e-12);
  EXPECT_NEAR(cielab_f_derivative(knee * (1 + 1e-9)), cielab_f_derivative(knee * (1 - 1e-9)), 1e-6);
}

}  // namespace
}  // namespace skylit
