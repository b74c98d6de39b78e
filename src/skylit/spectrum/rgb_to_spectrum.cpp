// sRGB → smooth reflectance by Jakob & Hanika (2019), solved per colour; measured
// reflectance samples → Spectrum.
//
// Jakob & Hanika fit the three coefficients of their sigmoid-of-a-quadratic by
// Gauss–Newton on the CIELAB difference to the target, and make the solve robust by
// continuation: they start at grey and walk the table outwards, each solve starting
// from its neighbour's solution. We have few materials, so instead of a table we walk
// one path per colour, from the grey of equal luminance to the target, with
// Levenberg–Marquardt steps and an analytic Jacobian.
#include "skylit/spectrum/rgb_to_spectrum.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "skylit/core/error.h"
#include "skylit/spectrum/cie.h"
#include "skylit/spectrum/illuminants.h"

namespace skylit {

namespace {

constexpr int kSamples1nm = static_cast<int>(kVisibleMaxNm - kVisibleMinNm) + 1;

double normalised_wavelength(double lambda_nm) { return (lambda_nm - kVisibleMinNm) / (kVisibleMaxNm - kVisibleMinNm); }

// D65 × CMF × trapezoid weight at every nm, scaled so that the perfect reflector has
// Y = 1: the 1 nm integration that the fit matches colours with.
struct D65Observer {
  std::array<double, kSamples1nm> t{}, weight_x{}, weight_y{}, weight_z{};
  Xyz white;
};

const D65Observer& d65_observer() {
  static const D65Observer observer = [] {
    D65Observer o;
    const ColourMatchingFunctions& cmf = cie1931();
    const Tabulated& d65 = cie_d65_table();
    double y_sum = 0.0;
    for (int i = 0; i < kSamples1nm; ++i) {
      const double lambda = kVisibleMinNm + i;
      const double trapezoid = (i == 0 || i == kSamples1nm - 1) ? 0.5 : 1.0;
      const size_t k = static_cast<size_t>(i);
      o.t[k] = normalised_wavelength(lambda);
      o.weight_x[k] = d65(lambda) * cmf.x(lambda) * trapezoid;
      o.weight_y[k] = d65(lambda) * cmf.y(lambda) * trapezoid;
      o.weight_z[k] = d65(lambda) * cmf.z(lambda) * trapezoid;
      y_sum += o.weight_y[k];
    }
    for (int i = 0; i < kSamples1nm; ++i) {
      const size_t k = static_cast<size_t>(i);
      o.weight_x[k] /= y_sum;
      o.weight_y[k] /= y_sum;
      o.weight_z[k] /= y_sum;
      o.white.x += o.weight_x[k];
      o.white.y += o.weight_y[k];
      o.white.z += o.weight_z[k];
    }
    return o;
  }();
  return observer;
}

// dS/dx = 1 / (2 (1 + x²)^{3/2}); hypot keeps it finite (→ 0) for huge |x|.
double sigmoid_slope(double x) {
  const double h = std::hypot(1.0, x);
  return 0.5 / (h * h * h);
}

using Vector3 = std::array<double, 3>;

// The Lab residual (fit − target) and its Jacobian with respect to (c0, c1, c2).
struct Residual {
  Vector3 value{};
  Matrix3 jacobian{};
  double norm = 0;  // ΔE*ab (CIE 1976) between fit and target
};

Residual residual(const SigmoidPolynomial& c, const Lab& target) {
  const D65Observer& o = d65_observer();
  Vector3 xyz{};
  Matrix3 d_xyz{};  // d_xyz[channel][coefficient]
  for (size_t k = 0; k < o.t.size(); ++k) {
    const double t = o.t[k];
    const double x = (c.c0 * t + c.c1) * t + c.c2;
    const double s = jakob_hanika_sigmoid(x);
    const double slope = sigmoid_slope(x);
    const Vector3 d_s{slope * t * t, slope * t, slope};
    const Vector3 weights{o.weight_x[k], o.weight_y[k], o.weight_z[k]};
    for (int ch = 0; ch < 3; ++ch) {
      xyz[ch] += weights[ch] * s;
      for (int j = 0; j < 3; ++j) d_xyz[ch][j] += weights[ch] * d_s[j];
    }
  }
  const Vector3 white{o.white.x, o.white.y, o.white.z};
  Vector3 f{}, df_dxyz{};
  for (int ch = 0; ch < 3; ++ch) {
    f[ch] = cielab_f(xyz[ch] / white[ch]);
    df_dxyz[ch] = cielab_f_derivative(xyz[ch] / white[ch]) / white[ch];
  }
  Residual r;
  r.value = {116.0 * f[1] - 16.0 - target.l, 500.0 * (f[0] - f[1]) - target.a, 200.0 * (f[1] - f[2]) - target.b};
  for (int j = 0; j < 3; ++j) {
    const double dfx = df_dxyz[0] * d_xyz[0][j], dfy = df_dxyz[1] * d_xyz[1][j], dfz = df_dxyz[2] * d_xyz[2][j];
    r.jacobian[0][j] = 116.0 * dfy;
    r.jacobian[1][j] = 500.0 * (dfx - dfy);
    r.jacobian[2][j] = 200.0 * (dfy - dfz);
  }
  r.norm = std::sqrt(r.value[0] * r.value[0] + r.value[1] * r.value[1] + r.value[2] * r.value[2]);
  return r;
}

struct Solve {
  SigmoidPolynomial c;
  double error;     // ΔE*ab at c
  int evaluations;  // work done, for the caller's budget
};

// Levenberg–Marquardt with Marquardt's diagonal scaling, which copes with the very
// different sizes of ∂Lab/∂c when the sigmoid saturates. Never returns a worse point
// than `start`, never a non-finite one.
Solve levenberg_marquardt(const SigmoidPolynomial& start, const Lab& target, int max_evaluations, double tolerance) {
  SigmoidPolynomial c = start;
  Residual r = residual(c, target);
  int evaluations = 1;
  double damping = 1e-3;
  while (r.norm > tolerance && evaluations < max_evaluations) {
    Matrix3 jtj{};
    Vector3 jtr{};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) jtj[i][j] += r.jacobian[k][i] * r.jacobian[k][j];
      for (int k = 0; k < 3; ++k) jtr[i] += r.jacobian[k][i] * r.value[k];
    }
    bool improved = false;
    while (!improved && evaluations < max_evaluations && damping < 1e12) {
      Matrix3 damped = jtj;
      for (int i = 0; i < 3; ++i) damped[i][i] += damping * jtj[i][i] + 1e-300;
      const Vector3 step = apply(inverse(damped), jtr);
      const SigmoidPolynomial candidate{c.c0 - step[0], c.c1 - step[1], c.c2 - step[2]};
      if (!std::isfinite(candidate.c0) || !std::isfinite(candidate.c1) || !std::isfinite(candidate.c2)) {
        damping *= 4.0;
        continue;
      }
      const Residual next = residual(candidate, target);
      ++evaluations;
      if (std::isfinite(next.norm) && next.norm < r.norm) {
        c = candidate;
        r = next;
        damping = std::max(damping / 3.0, 1e-12);
        improved = true;
      } else {
        damping *= 4.0;
      }
    }
    if (!improved) break;  // at a minimum that does not reach the target
  }
  return {c, r.norm, evaluations};
}

SigmoidPolynomial flat(double reflectance) {
  // S(c2) = g  ⇔  c2 = (g − ½) / √(g (1 − g)); ±∞ at g = 0 and 1, which S maps exactly.
  const double g = reflectance;
  if (g <= 0.0) return {0, 0, -INFINITY};
  if (g >= 1.0) return {0, 0, INFINITY};
  return {0, 0, (g - 0.5) / std::sqrt(g * (1.0 - g))};
}

double clamp_unit(double v) { return v >= 0.0 ? std::min(v, 1.0) : 0.0; }  // NaN → 0

// Work bounds: one evaluation is 401 samples (a few µs). Continuation steps are
// solved loosely (they only need to land in the next step's basin), the final one
// tightly.
constexpr int kContinuationEvaluations = 400;
constexpr int kFinalEvaluations = 200;
constexpr int kEvaluationsPerStep = 30;
constexpr double kStepTolerance = 1e-2;   // ΔE*ab
constexpr double kFinalTolerance = 1e-6;  // ΔE*ab
constexpr double kMinStep = 1.0 / 256.0;

}  // namespace

double jakob_hanika_sigmoid(double x) {
  if (std::isinf(x)) return x > 0 ? 1.0 : 0.0;
  return 0.5 + x / (2.0 * std::hypot(1.0, x));
}

double SigmoidPolynomial::operator()(double lambda_nm) const {
  const double t = normalised_wavelength(lambda_nm);
  return jakob_hanika_sigmoid((c0 * t + c1) * t + c2);
}

Lab lab_under_d65(const SigmoidPolynomial& reflectance) {
  const D65Observer& o = d65_observer();
  Xyz xyz;
  for (size_t k = 0; k < o.t.size(); ++k) {
    const double s = reflectance(kVisibleMinNm + static_cast<double>(k));
    xyz.x += o.weight_x[k] * s;
    xyz.y += o.weight_y[k] * s;
    xyz.z += o.weight_z[k] * s;
  }
  return lab_from_xyz(xyz, o.white);
}

Lab lab_of_linear_srgb(const Rgb& linear_srgb) {
  return lab_from_xyz(xyz_from_linear_srgb(linear_srgb), xyz_from_linear_srgb({1.0, 1.0, 1.0}));
}

SigmoidPolynomial fit_reflectance_to_linear_srgb(const Rgb& linear_srgb) {
  const Rgb target{clamp_unit(linear_srgb[0]), clamp_unit(linear_srgb[1]), clamp_unit(linear_srgb[2])};
  if (target[0] == target[1] && target[1] == target[2]) return flat(target[0]);

  // The path runs from the grey of the target's luminance (same L*, so only chroma
  // changes along it) to the target; every colour on it lies inside the sRGB cube.
  const double grey = xyz_from_linear_srgb(target).y;
  auto colour_at = [&](double alpha) {
    Rgb rgb{};
    for (int i = 0; i < 3; ++i) rgb[i] = grey + alpha * (target[i] - grey);
    return lab_of_linear_srgb(rgb);
  };

  SigmoidPolynomial c = flat(grey);
  double alpha = 0.0, step = 0.25;
  int budget = kContinuationEvaluations;
  while (alpha < 1.0 && budget > 0) {
    const double next_alpha = std::min(1.0, alpha + step);
    const Solve s =
        levenberg_marquardt(c, colour_at(next_alpha), std::min(budget, kEvaluationsPerStep), kStepTolerance);
    budget -= s.evaluations;
    if (s.error <= kStepTolerance || step <= kMinStep) {
      // Converged, or the step cannot be made smaller: keep the best point and go on.
      c = s.c;
      alpha = next_alpha;
      step = std::min(2.0 * step, 0.5);
    } else {
      step *= 0.5;
    }
  }
  return levenberg_marquardt(c, colour_at(1.0), kFinalEvaluations, kFinalTolerance).c;
}

Tabulated tabulate_at_1nm(const SigmoidPolynomial& reflectance) {
  Tabulated table;
  for (int i = 0; i < kSamples1nm; ++i) {
    const double lambda = kVisibleMinNm + i;
    table.x.push_back(lambda);
    table.y.push_back(reflectance(lambda));
  }
  return table;
}

Spectrum reflectance_from_linear_srgb(const Rgb& linear_srgb) {
  return Spectrum::from_table(tabulate_at_1nm(fit_reflectance_to_linear_srgb(linear_srgb)));
}

Spectrum reflectance_from_samples(const std::vector<std::pair<double, double>>& samples_nm_value,
                                  std::string_view where) {
  auto fail = [&](const std::string& what) { throw InputError(std::string(where) + ": reflectance samples: " + what); };
  if (samples_nm_value.empty()) fail("need at least one (wavelength_nm, value) pair");
  Tabulated table;
  for (size_t i = 0; i < samples_nm_value.size(); ++i) {
    const auto [lambda, value] = samples_nm_value[i];
    std::ostringstream at;
    at << "sample " << i << " (" << lambda << " nm, " << value << ")";
    if (!std::isfinite(lambda) || !std::isfinite(value)) fail(at.str() + " is not a finite number");
    if (!table.x.empty() && lambda <= table.x.back()) fail(at.str() + ": wavelengths must increase strictly");
    if (value < 0.0 || value > 1.0)
      fail(at.str() + ": a reflectance must be within [0, 1]" +
           (value > 1.0 && value <= 100.0 ? " (percentages must be divided by 100)" : ""));
    table.x.push_back(lambda);
    table.y.push_back(value);
  }
  // Hold the end values out to the visible range's ends (Tabulated is zero outside).
  if (table.x.front() > kVisibleMinNm) {
    table.x.insert(table.x.begin(), kVisibleMinNm);
    table.y.insert(table.y.begin(), table.y.front());
  }
  if (table.x.back() < kVisibleMaxNm) {
    table.x.push_back(kVisibleMaxNm);
    table.y.push_back(table.y.back());
  }
  return Spectrum::from_table(table);
}

}  // namespace skylit
