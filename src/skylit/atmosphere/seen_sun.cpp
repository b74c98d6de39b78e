#include "skylit/atmosphere/seen_sun.h"

#include <algorithm>
#include <cmath>

#include "skylit/atmosphere/atmosphere.h"
#include "skylit/atmosphere/refracted_ray_impl.h"
#include "skylit/atmosphere/shell_geometry.h"
#include "skylit/core/angles.h"
#include "skylit/spectrum/spectral_math.h"

namespace skylit {

SunRefraction::SunRefraction(const AtmosphereMedium& medium, double ground_radius_m, double top_radius_m)
    : medium_(medium), ground_radius_(ground_radius_m), top_radius_(top_radius_m), refracts_(medium.refractivity > 0) {
  if (!refracts_) return;
  horizon_lift_rad_ = trace_refracted_ray(medium_, ground_radius_, 0.0, ground_radius_, top_radius_).bending_rad;
  // Fading over at least twice the lift keeps the map below the horizon increasing.
  fade_rad_ = std::max(radians(1.0), 2 * horizon_lift_rad_);
}

SunRefraction::SunRefraction(const Atmosphere& atmosphere)
    : SunRefraction(atmosphere.medium(), atmosphere.ground_radius(), atmosphere.transmittance().top_radius()) {}

double SunRefraction::true_elevation(double seen_elevation_rad) const {
  if (!refracts_) return seen_elevation_rad;
  if (seen_elevation_rad >= 0) {
    const RefractedRay ray =
        trace_refracted_ray(medium_, ground_radius_, std::sin(seen_elevation_rad), ground_radius_, top_radius_);
    return seen_elevation_rad - ray.bending_rad;
  }
  return seen_elevation_rad - horizon_lift_rad_ * std::max(0.0, 1.0 + seen_elevation_rad / fade_rad_);
}

double SunRefraction::seen_elevation(double true_elevation_rad) const {
  if (!refracts_) return true_elevation_rad;
  if (true_elevation_rad >= -horizon_lift_rad_) {
    const std::optional<double> mu = mu_seen_at(ground_radius_, std::sin(true_elevation_rad));
    return mu ? std::asin(std::clamp(*mu, 0.0, 1.0)) : 0.0;
  }
  // The inverse of true_elevation's linear fade below the horizon.
  if (true_elevation_rad >= -fade_rad_)
    return (true_elevation_rad + horizon_lift_rad_) / (1.0 - horizon_lift_rad_ / fade_rad_);
  return true_elevation_rad;
}

namespace {

Vec3 with_elevation(const Vec3& direction, double elevation_rad) {
  const double horizontal = std::hypot(direction.x, direction.y);
  if (horizontal < 1e-12) return direction;  // the zenith (or nadir): no azimuth to keep
  const double c = std::cos(elevation_rad) / horizontal;
  return {direction.x * c, direction.y * c, std::sin(elevation_rad)};
}

double elevation_of(const Vec3& direction) { return std::asin(std::clamp(normalize(direction).z, -1.0, 1.0)); }

}  // namespace

Vec3 SunRefraction::true_direction(const Vec3& seen_to_sun) const {
  return with_elevation(seen_to_sun, true_elevation(elevation_of(seen_to_sun)));
}

Vec3 SunRefraction::seen_direction(const Vec3& true_to_sun) const {
  return with_elevation(true_to_sun, seen_elevation(elevation_of(true_to_sun)));
}

double SunRefraction::mu_true_of(double r, double mu_seen, bool& hits_ground) const {
  const RefractedRay ray = trace_refracted_ray(medium_, r, mu_seen, ground_radius_, top_radius_);
  hits_ground = ray.hits_ground;
  return ray.mu_true;
}

double SunRefraction::lowest_mu(double r) const {
  const auto air = [this](double h) { return refraction::air_sample(medium_, h); };
  return refraction::grazing_mu(air, medium_.earth_radius_m, r, ground_radius_) + 1e-9;
}

std::optional<double> SunRefraction::mu_seen_at(double r, double mu_true) const {
  const double mu_lowest = lowest_mu(r);
  bool hits = false;
  // Refraction only lifts the seen sun: μ_seen ≥ μ_true. Regula falsi (Illinois) on
  // μ_true(μ_seen) − μ_true, which is increasing, between the two.
  double lo = std::max(mu_lowest, mu_true), hi = 1.0;
  double f_lo = mu_true_of(r, lo, hits) - mu_true;
  // Even the lowest ray that reaches r comes from above the sun: r is in the Earth's
  // refracted shadow.
  if (hits || (f_lo > 0 && lo == mu_lowest)) return std::nullopt;
  f_lo = std::min(f_lo, 0.0);                     // a lift of a rounding below zero, at the zenith
  double f_hi = 1.0 - mu_true;                    // the zenith's ray is not bent
  const double guess = std::min(1.0, lo + 0.04);  // the lift never reaches 2.3°
  if (const double f = mu_true_of(r, guess, hits) - mu_true; f >= 0) {
    hi = guess;
    f_hi = f;
  }
  int side = 0;
  double mu = lo;
  for (int i = 0; i < 60 && hi - lo > 1e-13; ++i) {
    mu = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    if (!(mu > lo && mu < hi)) mu = 0.5 * (lo + hi);
    const double f = mu_true_of(r, mu, hits) - mu_true;
    if (std::abs(f) < 1e-14) break;
    if (f < 0) {
      lo = mu;
      f_lo = f;
      if (side == -1) f_hi *= 0.5;
      side = -1;
    } else {
      hi = mu;
      f_hi = f;
      if (side == 1) f_lo *= 0.5;
      side = 1;
    }
  }
  return mu;
}

SunRefraction::Beam SunRefraction::beam(double r, double mu_true) const {
  r = std::clamp(r, ground_radius_, top_radius_);
  Beam b;
  if (!refracts_) {
    b.shines = !shell::hits_ground(r, mu_true, ground_radius_);
    b.mu_seen = mu_true;
    if (b.shines)
      b.columns = column_densities(medium_, r, mu_true, shell::distance_to_outer_sphere(r, mu_true, top_radius_));
    return b;
  }
  const std::optional<double> solved = mu_seen_at(r, mu_true);
  if (!solved) return b;
  const double mu = *solved;
  const RefractedRay ray = trace_refracted_ray(medium_, r, mu, ground_radius_, top_radius_);
  b.shines = !ray.hits_ground;
  if (!b.shines) return b;
  b.mu_seen = mu;
  b.columns = ray.columns;
  // dμ_true/dμ_seen by a difference, one-sided next to the grazing ray.
  constexpr double kStep = 1e-5;
  const double below = std::max(lowest_mu(r), mu - kStep), above = std::min(1.0, mu + kStep);
  bool hits_below = false, hits_above = false;
  const double slope = (mu_true_of(r, above, hits_above) - mu_true_of(r, below, hits_below)) / (above - below);
  // Étendue n²·dA·dΩ is conserved: the seen disc's solid angle is dμ_seen/dμ_true of
  // the unbent one's, and its radiance n² times (a vertical beam is not spread).
  const double n_here = refraction::air_sample(medium_, r - medium_.earth_radius_m).n;
  if (!hits_below && slope > 0) b.spreading = n_here * n_here / slope;
  return b;
}

Spectrum SunRefraction::sunlight(double r, double mu_true, bool spread) const {
  const Beam b = beam(r, mu_true);
  if (!b.shines) return Spectrum(0.0f);
  const ColumnDensities& c = b.columns;
  return transmittance_of(medium_.extinction(c.rayleigh, c.aerosol, c.ozone)) *
         static_cast<float>(spread ? b.spreading : 1.0);
}

}  // namespace skylit
