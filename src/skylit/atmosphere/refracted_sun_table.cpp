#include "skylit/atmosphere/refracted_sun_table.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "skylit/atmosphere/refracted_ray_impl.h"
#include "skylit/spectrum/spectral_math.h"

namespace skylit {

namespace {

// The air's properties on a 10 m grid of altitudes, read by linear interpolation: the
// table traces ~50,000 rays, and the densities and the index's gradient straight from
// the medium would cost five profile evaluations per sample. Linear interpolation of the
// aerosol's 1.2 km exponential at 10 m is exact to 1e-5.
class AirOnAGrid {
 public:
  AirOnAGrid(const AtmosphereMedium& medium, double bottom_m, double top_m)
      : bottom_m_(bottom_m), samples_(static_cast<size_t>((top_m - bottom_m) / kStepM) + 2) {
    for (size_t i = 0; i < samples_.size(); ++i)
      samples_[i] = refraction::air_sample(medium, bottom_m + kStepM * static_cast<double>(i));
  }

  refraction::AirSample operator()(double h) const {
    const double f = std::clamp((h - bottom_m_) / kStepM, 0.0, static_cast<double>(samples_.size() - 1));
    const size_t i = std::min(static_cast<size_t>(f), samples_.size() - 2);
    const double a = f - static_cast<double>(i);
    const refraction::AirSample &p = samples_[i], &q = samples_[i + 1];
    return {p.rayleigh + a * (q.rayleigh - p.rayleigh), p.aerosol + a * (q.aerosol - p.aerosol),
            p.ozone + a * (q.ozone - p.ozone), p.n + a * (q.n - p.n), p.dn_dr + a * (q.dn_dr - p.dn_dr)};
  }

 private:
  static constexpr double kStepM = 10.0;
  double bottom_m_;
  std::vector<refraction::AirSample> samples_;
};

constexpr int kSamplesPerLeg = 64;

}  // namespace

RefractedSunTable::RefractedSunTable(const AtmosphereMedium& medium, double ground_radius_m, double top_radius_m)
    : ground_radius_(ground_radius_m),
      top_radius_(top_radius_m),
      horizon_distance_(std::sqrt(top_radius_m * top_radius_m - ground_radius_m * ground_radius_m)),
      edge_mu_(kRSize),
      table_(kMuSize, kRSize) {
  const double earth = medium.earth_radius_m;
  const AirOnAGrid air(medium, ground_radius_m - earth, top_radius_m - earth);
  tbb::parallel_for(0, kRSize, [&](int j) {
    const double rho = horizon_distance_ * j / (kRSize - 1);
    const double r = std::sqrt(rho * rho + ground_radius_m * ground_radius_m);
    // The apparent direction of the ray that grazes the ground (nudged up by 1e-9 so
    // that rounding does not put its lowest point below the ground), then directions
    // up to the zenith crowded toward it.
    const double grazing = refraction::grazing_mu(air, earth, r, ground_radius_m) * (1.0 - 1e-9);
    std::vector<double> mu_true(kRaysPerRow), log_spreading(kRaysPerRow), z_apparent(kRaysPerRow), z_true(kRaysPerRow);
    std::vector<ColumnDensities> columns(kRaysPerRow);
    for (int i = 0; i < kRaysPerRow; ++i) {
      const double u = static_cast<double>(i) / (kRaysPerRow - 1);
      const double mu_a = grazing + (1.0 - grazing) * u * u;
      const RefractedRay ray = refraction::trace(air, earth, r, mu_a, ground_radius_m, top_radius_m, kSamplesPerLeg);
      mu_true[static_cast<size_t>(i)] = ray.mu_true;
      columns[static_cast<size_t>(i)] = ray.columns;
      z_apparent[static_cast<size_t>(i)] = std::acos(std::clamp(mu_a, -1.0, 1.0));
      z_true[static_cast<size_t>(i)] = std::acos(std::clamp(ray.mu_true, -1.0, 1.0));
    }
    // The beam's spreading: dz_a/dz_s in the vertical plane (by differences between
    // neighbouring rays) times sin z_a / sin z_s across it (which tends to dz_a/dz_s at
    // the zenith).
    for (int i = 0; i < kRaysPerRow; ++i) {
      const size_t lo = static_cast<size_t>(std::max(0, i - 1)),
                   hi = static_cast<size_t>(std::min(kRaysPerRow - 1, i + 1));
      const double dza_dzs = (z_apparent[hi] - z_apparent[lo]) / (z_true[hi] - z_true[lo]);
      const double sin_s = std::sin(z_true[static_cast<size_t>(i)]);
      const double across = sin_s > 1e-6 ? std::sin(z_apparent[static_cast<size_t>(i)]) / sin_s : dza_dzs;
      log_spreading[static_cast<size_t>(i)] = std::log(std::max(1e-30, dza_dzs * across));
    }
    // Resample onto the row's μ_s columns (μ_s rises with i).
    const double edge = mu_true[0];
    edge_mu_[static_cast<size_t>(j)] = edge;
    size_t i = 0;
    for (int k = 0; k < kMuSize; ++k) {
      const double x = static_cast<double>(k) / (kMuSize - 1);
      const double mu = edge + (1.0 - edge) * x * x;
      while (i + 2 < mu_true.size() && mu_true[i + 1] < mu) ++i;
      const double span = mu_true[i + 1] - mu_true[i];
      const double a = span > 0 ? std::clamp((mu - mu_true[i]) / span, 0.0, 1.0) : 0.0;
      const ColumnDensities &c0 = columns[i], &c1 = columns[i + 1];
      const Spectrum depth =
          medium.extinction(c0.rayleigh + a * (c1.rayleigh - c0.rayleigh), c0.aerosol + a * (c1.aerosol - c0.aerosol),
                            c0.ozone + a * (c1.ozone - c0.ozone));
      const float spreading = static_cast<float>(-(log_spreading[i] + a * (log_spreading[i + 1] - log_spreading[i])));
      table_.at(k, j) = depth + Spectrum(spreading);
    }
  });
}

double RefractedSunTable::shadow_edge_mu(double r) const {
  r = std::clamp(r, ground_radius_, top_radius_);
  const double f = std::sqrt(std::max(0.0, r * r - ground_radius_ * ground_radius_)) / horizon_distance_ * (kRSize - 1);
  const int j = std::min(static_cast<int>(f), kRSize - 2);
  const double a = f - j;
  return edge_mu_[static_cast<size_t>(j)] * (1 - a) + edge_mu_[static_cast<size_t>(j + 1)] * a;
}

std::optional<std::pair<double, double>> RefractedSunTable::place(double r, double mu_sun) const {
  r = std::clamp(r, ground_radius_, top_radius_);
  const double edge = shadow_edge_mu(r);
  if (mu_sun <= edge) return std::nullopt;
  const double x = std::sqrt(std::min(1.0, (mu_sun - edge) / (1.0 - edge)));
  const double fy =
      std::sqrt(std::max(0.0, r * r - ground_radius_ * ground_radius_)) / horizon_distance_ * (kRSize - 1);
  return std::pair{x * (kMuSize - 1), fy};
}

Spectrum RefractedSunTable::sunlight(double r, double mu_sun) const {
  const auto at = place(r, mu_sun);
  return at ? transmittance_of(table_.interpolate(at->first, at->second)) : Spectrum(0.0f);
}

void RefractedSunTable::sunlight_in_bins(double r, double mu_sun, std::span<const int> bins,
                                         std::span<float> out) const {
  transmittance_in_bins(table_, place(r, mu_sun), bins, out);
}

}  // namespace skylit
