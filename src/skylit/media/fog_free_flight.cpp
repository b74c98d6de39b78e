#include "skylit/media/fog_free_flight.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace skylit {

namespace {

// Rays longer than this inside a layer are taken as running on through it for ever (a
// level ray in a layer without horizontal bounds); 1e9 m puts any fog's optical depth
// far past opacity.
constexpr double kLongestM = 1e9;

double end_of(double t_end) { return std::isfinite(t_end) ? t_end : kLongestM; }

}  // namespace

Spectrum fog_transmittance(const FogLayer& fog, const Ray& ray, double t_end) {
  return fog.transmittance(fog.column(ray.origin.z, ray.direction.z, 0.0, end_of(t_end)));
}

FogFlight sample_fog_flight(const FogLayer& fog, const Ray& ray, double t_end, double u_bin, double u_depth) {
  FogFlight flight;
  const RaySpan span = fog.clip(ray.origin.z, ray.direction.z, 0.0, end_of(t_end));
  if (span.empty()) return flight;
  const auto& sigma = fog.unit_density_extinction_bins();
  const int hero = std::clamp(static_cast<int>(u_bin * kSpectralBins), 0, kSpectralBins - 1);
  const double target_column = -std::log1p(-u_depth) / sigma[static_cast<size_t>(hero)];
  const double total_column = fog.column(ray.origin.z, ray.direction.z, span.lo, span.hi);
  if (!(target_column < total_column)) {
    // Through the fog: each bin's chance of getting through over the bins' mean chance.
    const Spectrum through = fog.transmittance(total_column);
    const double mean = through.mean_value();
    for (int k = 0; k < kSpectralBins; ++k) flight.weight[k] = mean > 0 ? static_cast<float>(through[k] / mean) : 0.0f;
    return flight;
  }
  // The distance where the column reaches the target, by bisection (the column only
  // grows along the ray); 64 halvings of at most 1e9 m leave under a micrometre.
  double lo = span.lo, hi = span.hi;
  for (int i = 0; i < 64 && hi - lo > 1e-9 * std::max(1.0, hi); ++i) {
    const double mid = 0.5 * (lo + hi);
    (fog.column(ray.origin.z, ray.direction.z, span.lo, mid) < target_column ? lo : hi) = mid;
  }
  const double s = 0.5 * (lo + hi);
  flight.scattered = true;
  flight.distance = s;
  // Each bin's density of scattering here, σ_k ρ e^{−σ_k N}, over the bins' mean; the
  // density ρ(z) cancels; the albedo turns extinction into scattering.
  double mean = 0;
  std::array<double, kSpectralBins> density{};
  for (int k = 0; k < kSpectralBins; ++k) {
    const double sigma_k = sigma[static_cast<size_t>(k)];
    density[static_cast<size_t>(k)] = sigma_k * std::exp(-sigma_k * target_column);
    mean += density[static_cast<size_t>(k)];
  }
  mean /= kSpectralBins;
  for (int k = 0; k < kSpectralBins; ++k)
    flight.weight[k] = static_cast<float>(fog.single_scattering_albedo() * density[static_cast<size_t>(k)] / mean);
  return flight;
}

}  // namespace skylit
