#include "skylit/atmosphere/sky_view_table.h"

#include <algorithm>
#include <cmath>

namespace skylit {

namespace {
constexpr double kHalfPi = kPi / 2.0;
}

SkyDirectionMapping::SkyDirectionMapping(double observer_radius_m, double ground_radius_m)
    : horizon_(-std::acos(std::clamp(ground_radius_m / observer_radius_m, 0.0, 1.0))) {}

void SkyDirectionMapping::to_unit(const RelativeDirection& d, double& u_azimuth, double& u_elevation) const {
  u_azimuth = std::clamp(d.azimuth_from_sun_rad / kPi, 0.0, 1.0);
  const double e = std::clamp(d.elevation_rad, -kHalfPi, kHalfPi);
  // Square-root crowding toward the horizon on both sides.
  u_elevation = e >= horizon_ ? 0.5 + 0.5 * std::sqrt((e - horizon_) / (kHalfPi - horizon_))
                              : 0.5 - 0.5 * std::sqrt((horizon_ - e) / (kHalfPi + horizon_));
}

RelativeDirection SkyDirectionMapping::from_unit(double u_azimuth, double u_elevation) const {
  const double above = 2.0 * u_elevation - 1.0;
  const double e =
      above >= 0 ? horizon_ + (kHalfPi - horizon_) * above * above : horizon_ - (kHalfPi + horizon_) * above * above;
  return {e, u_azimuth * kPi};
}

namespace {

// acos to within 7e-5 rad (Abramowitz & Stegun 4.4.45, odd-extended), for the azimuth of
// table look-ups, whose samples are about 2° apart; libm's acos was 5 % of a frame.
double table_acos(double x) {
  const double a = std::abs(std::clamp(x, -1.0, 1.0));
  const double r = std::sqrt(1.0 - a) * (1.5707288 + a * (-0.2121144 + a * (0.0742610 + a * -0.0187293)));
  return x >= 0 ? r : kPi - r;
}

}  // namespace

RelativeDirection relative_direction(const Vec3& direction, const Vec3& to_sun) {
  // Exact: near the horizon the elevation rows are a hundredth of a degree apart.
  const double elevation = std::asin(std::clamp(direction.z / length(direction), -1.0, 1.0));
  const double horizontal = std::hypot(direction.x, direction.y);
  const double sun_horizontal = std::hypot(to_sun.x, to_sun.y);
  double azimuth = 0.0;
  if (horizontal > 1e-12 && sun_horizontal > 1e-12) {
    const double c = (direction.x * to_sun.x + direction.y * to_sun.y) / (horizontal * sun_horizontal);
    azimuth = table_acos(c);
  }
  return {elevation, azimuth};
}

RayCosines ray_cosines(const RelativeDirection& d, double sun_elevation_rad) {
  const double mu = std::sin(d.elevation_rad);
  return {mu, mu * std::sin(sun_elevation_rad) +
                  std::cos(d.elevation_rad) * std::cos(sun_elevation_rad) * std::cos(d.azimuth_from_sun_rad)};
}

SkyViewTable::SkyViewTable(const ScatteringIntegrator& integrator, const Spectrum& sun_irradiance,
                           double observer_radius_m, double ground_radius_m, double sun_elevation_rad)
    : mapping_(observer_radius_m, ground_radius_m), table_(kAzimuthSize, kElevationSize) {
  const double mu_sun = std::sin(sun_elevation_rad);
  mapping_.for_each_node(kAzimuthSize, kElevationSize, sun_elevation_rad, [&](int i, int j, const RayCosines& c) {
    table_.at(i, j) = integrator.along_ray(observer_radius_m, c.mu, mu_sun, c.nu, kSegments).radiance * sun_irradiance;
  });
}

SkyViewTable::SkyViewTable(FunctionRef<Spectrum(const RelativeDirection&)> radiance, double observer_radius_m,
                           double ground_radius_m)
    : mapping_(observer_radius_m, ground_radius_m), table_(kAzimuthSize, kElevationSize) {
  for (int j = 0; j < kElevationSize; ++j)
    for (int i = 0; i < kAzimuthSize; ++i)
      table_.at(i, j) = radiance(mapping_.from_unit(static_cast<double>(i) / (kAzimuthSize - 1),
                                                    static_cast<double>(j) / (kElevationSize - 1)));
}

void SkyViewTable::add(FunctionRef<Spectrum(const RelativeDirection&)> radiance) {
  for (int j = 0; j < kElevationSize; ++j)
    for (int i = 0; i < kAzimuthSize; ++i)
      table_.at(i, j) += radiance(mapping_.from_unit(static_cast<double>(i) / (kAzimuthSize - 1),
                                                     static_cast<double>(j) / (kElevationSize - 1)));
}

Spectrum SkyViewTable::radiance(const RelativeDirection& direction) const {
  double u_azimuth, u_elevation;
  mapping_.to_unit(direction, u_azimuth, u_elevation);
  return table_.interpolate(u_azimuth * (kAzimuthSize - 1), u_elevation * (kElevationSize - 1));
}

}  // namespace skylit
