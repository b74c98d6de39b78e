// The scattering orders' phase integral by azimuthal modes against the plain sum it
// stands for: every direction's row of ½[P(ω_d·ω_e) + P(ω_d·ω_e')]·dω_e over the grid,
// normalised to sum to one (the matrix the table used before the modes).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <tuple>
#include <vector>

#include "skylit/atmosphere/direction_grid_phase_quadrature.h"
#include "skylit/core/angles.h"

namespace skylit {
namespace {

constexpr size_t kChannels = 3;
using Values = std::array<float, kChannels>;

struct Direction {
  double x, y, z;
};

// Bands of μ: equal ones, or with edges at μ = x·|x|^p for equal steps of x (crowded
// toward the horizon when p > 0); each by its middle and its width.
struct Bands {
  std::vector<double> mu, width;
};
Bands bands(int count, double p) {
  auto edge = [&](int k) {
    const double x = -1.0 + 2.0 * k / count;
    return x * std::pow(std::abs(x), p);
  };
  Bands out;
  for (int k = 0; k < count; ++k) {
    out.mu.push_back(0.5 * (edge(k) + edge(k + 1)));
    out.width.push_back(edge(k + 1) - edge(k));
  }
  return out;
}

Direction grid_direction(int k, int q, const Bands& b, int azimuths, bool mirror) {
  const double mu = b.mu[static_cast<size_t>(k)], phi = kPi * (q + 0.5) / azimuths;
  const double s = std::sqrt(1.0 - mu * mu);
  return {s * std::cos(phi), (mirror ? -1.0 : 1.0) * s * std::sin(phi), mu};
}

// The plain sum, in double.
std::vector<std::array<double, kChannels>> direct_sum(const std::vector<Values>& field, const Bands& b, int azimuths,
                                                      const std::function<double(double)>& phase) {
  const int n = static_cast<int>(b.mu.size()) * azimuths;
  std::vector<std::array<double, kChannels>> out(static_cast<size_t>(n));
  for (int d = 0; d < n; ++d) {
    const Direction u = grid_direction(d / azimuths, d % azimuths, b, azimuths, false);
    double weight_sum = 0;
    std::array<double, kChannels> sum{};
    for (int e = 0; e < n; ++e) {
      const Direction v = grid_direction(e / azimuths, e % azimuths, b, azimuths, false);
      const Direction v_mirror = grid_direction(e / azimuths, e % azimuths, b, azimuths, true);
      const double w =
          0.5 *
          (phase(u.x * v.x + u.y * v.y + u.z * v.z) + phase(u.x * v_mirror.x + u.y * v_mirror.y + u.z * v_mirror.z)) *
          b.width[static_cast<size_t>(e / azimuths)];
      weight_sum += w;
      for (size_t c = 0; c < kChannels; ++c) sum[c] += w * field[static_cast<size_t>(e)][c];
    }
    for (size_t c = 0; c < kChannels; ++c) out[static_cast<size_t>(d)][c] = sum[c] / weight_sum;
  }
  return out;
}

std::vector<Values> by_modes(const std::vector<Values>& field, const Bands& b, int azimuths,
                             const std::function<double(double)>& phase) {
  const DirectionGridPhaseQuadrature quadrature(b.mu, b.width, azimuths, phase);
  std::vector<Values> modes(field.size()), out(field.size());
  quadrature.modes_of(field.data(), modes.data());
  quadrature.integrate(modes.data(), out.data());
  return out;
}

double henyey_greenstein(double cosine, double g) {
  return (1 - g * g) / (4 * kPi * std::pow(1 + g * g - 2 * g * cosine, 1.5));
}

TEST(DirectionGridPhaseQuadrature, EqualsTheRowNormalisedSumOverTheGrid) {
  // Random positive fields spanning three decades (the table's light across the
  // terminator), on the table's grid and on a smaller one; Rayleigh's phase function
  // and a strongly forward-peaked one. The modes are summed in float: 2e-5 of the
  // field's largest value bounds their rounding (measured: under 1e-6).
  std::mt19937 random(7);
  std::uniform_real_distribution<double> exponent(-3.0, 0.0);
  const std::function<double(double)> rayleigh = [](double c) { return 3.0 / (16 * kPi) * (1 + c * c); };
  const std::function<double(double)> forward = [](double c) { return henyey_greenstein(c, 0.85); };
  // Equal bands of μ and unequal ones (crowded toward the horizon; any widths will do).
  for (const auto& [mu_bands, azimuths, crowding] :
       {std::tuple{16, 8, 0.0}, std::tuple{10, 6, 0.0}, std::tuple{16, 8, 1.0}})
    for (const auto* phase : {&rayleigh, &forward}) {
      const Bands b = bands(mu_bands, crowding);
      std::vector<Values> field(static_cast<size_t>(mu_bands * azimuths));
      for (Values& v : field)
        for (float& c : v) c = static_cast<float>(std::pow(10.0, exponent(random)));
      const auto expected = direct_sum(field, b, azimuths, *phase);
      const std::vector<Values> got = by_modes(field, b, azimuths, *phase);
      for (size_t d = 0; d < field.size(); ++d)
        for (size_t c = 0; c < kChannels; ++c)
          EXPECT_NEAR(got[d][c], expected[d][c], 2e-5)
              << mu_bands << "×" << azimuths << " crowding " << crowding << " direction " << d;
    }
}

TEST(DirectionGridPhaseQuadrature, AUniformFieldIsScatteredUnchanged) {
  // Each row sums to one: light that is the same from every direction stays the same.
  const std::vector<Values> field(16 * 8, Values{1.0f, 2.0f, 0.5f});
  const std::vector<Values> got =
      by_modes(field, bands(16, 1.0), 8, [](double c) { return henyey_greenstein(c, 0.7); });
  for (const Values& v : got) {
    EXPECT_NEAR(v[0], 1.0f, 1e-5);
    EXPECT_NEAR(v[1], 2.0f, 2e-5);
    EXPECT_NEAR(v[2], 0.5f, 1e-5);
  }
}

}  // namespace
}  // namespace skylit
