// An adaptive Gauss–Kronrod (7–15) quadrature for the tests: independent of the code
// under test, it is the reference physical integrals are checked against.
#pragma once

#include <cmath>

namespace skylit::testing {

constexpr double kXgk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                            0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                            0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                            0.207784955007898467600689403773245, 0.0};
constexpr double kWgk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                            0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                            0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                            0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr double kWg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                           0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

template <class F>
double integrate(const F& f, double a, double b, double rel_tol, int depth = 0) {
  if (!(b > a)) return 0.0;
  const double c = 0.5 * (a + b), h = 0.5 * (b - a);
  const double fc = f(c);
  double kronrod = kWgk[7] * fc, gauss = kWg[3] * fc;
  for (int j = 0; j < 7; ++j) {
    const double f1 = f(c - h * kXgk[j]), f2 = f(c + h * kXgk[j]);
    kronrod += kWgk[j] * (f1 + f2);
    if (j % 2 == 1) gauss += kWg[j / 2] * (f1 + f2);
  }
  kronrod *= h;
  gauss *= h;
  if (std::abs(kronrod - gauss) <= rel_tol * std::abs(kronrod) || depth >= 40) return kronrod;
  return integrate(f, a, c, rel_tol, depth + 1) + integrate(f, c, b, rel_tol, depth + 1);
}

}  // namespace skylit::testing
