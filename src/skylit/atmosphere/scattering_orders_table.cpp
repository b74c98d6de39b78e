#include "skylit/atmosphere/scattering_orders_table.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "skylit/atmosphere/aerosol_types.h"
#include "skylit/atmosphere/direction_grid_phase_quadrature.h"
#include "skylit/atmosphere/phase_functions.h"
#include "skylit/atmosphere/shell_geometry.h"
#include "skylit/atmosphere/sun_zenith_rows.h"
#include "skylit/core/angles.h"
#include "skylit/spectrum/spectral_math.h"

namespace skylit {

namespace {

using Table = ScatteringOrdersTable;
using Bins = Table::Bins;
constexpr int kBins = Table::kBins;
constexpr int kDirections = Table::kMuSize * Table::kAzimuthSize;
constexpr int kPoints = Table::kAltitudeSize * Table::kMuSunSize;
// A segment's plane of S over (μ_s, φ): blend_segment.
constexpr size_t kPlaneSize = static_cast<size_t>(Table::kMuSunSize * Table::kAzimuthSize);

// The spectral bin that the table's bin b stands for: 0, 6, 11, …, 39.
int spectral_bin(int b) { return (b * (kSpectralBins - 1) + (kBins - 1) / 2) / (kBins - 1); }

// Grid coordinates (0 … size − 1) and back.
double altitude_from_unit(double x, double top) { return top * x * x * x; }
double unit_from_altitude(double h, double top) { return std::cbrt(std::clamp(h / top, 0.0, 1.0)); }
// Directions: equal bands of x ∈ [−1, 1] with μ = x − β sin(2πx)/(2π), and equal
// bands of φ ∈ [0, π]. With β = ½ the bands are twice as fine as equal bands of μ at the
// horizon and the poles and 1.5 times coarser at μ = ±½. Below the sun at −8° the
// shadowed air is lit mostly by the thin twilight arch just above the horizon toward
// the sun, which 16 equal bands (the lowest 7° tall) resolved poorly: views low in the
// sky away from the sun were up to 13 % too dark against the Monte Carlo reference,
// now within −2.7 … +5.2 % everywhere at the same cost (docs/atmosphere.md).
constexpr double kHorizonCrowding = 0.5;  // β
double mu_from_unit(double x) { return x - kHorizonCrowding * std::sin(2 * kPi * x) / (2 * kPi); }
// Its inverse, for the look-ups: tabulated over |μ| (the map is odd) from Newton's
// iterations, linear between the entries (within 4e-5 of a band).
double unit_from_mu(double mu) {
  constexpr int kSize = 512;
  static const std::array<double, kSize + 1> table = [] {
    std::array<double, kSize + 1> out{};
    for (int i = 0; i <= kSize; ++i) {
      const double m = static_cast<double>(i) / kSize;
      double x = m;
      for (int n = 0; n < 8; ++n) x -= (mu_from_unit(x) - m) / (1 - kHorizonCrowding * std::cos(2 * kPi * x));
      out[static_cast<size_t>(i)] = x;
    }
    return out;
  }();
  const double f = std::min(std::abs(mu), 1.0) * kSize;
  const int i = std::min(static_cast<int>(f), kSize - 1);
  const double x =
      table[static_cast<size_t>(i)] + (f - i) * (table[static_cast<size_t>(i) + 1] - table[static_cast<size_t>(i)]);
  return std::copysign(x, mu);
}
double mu_of(int k) { return mu_from_unit(-1.0 + 2.0 * (k + 0.5) / Table::kMuSize); }
double mu_band_width(int k) {
  return mu_from_unit(-1.0 + 2.0 * (k + 1) / Table::kMuSize) - mu_from_unit(-1.0 + 2.0 * k / Table::kMuSize);
}
double azimuth_of(int k) { return kPi * (k + 0.5) / Table::kAzimuthSize; }
// Each direction stands for its band and its mirror image across the sun's vertical.
double direction_weight(int k) { return mu_band_width(k) * (2.0 * kPi / Table::kAzimuthSize); }

// The cosine between a direction and the sun, both given in the point's frame.
double nu_of(double mu, double mu_sun, double azimuth) {
  return mu * mu_sun + std::sqrt((1.0 - mu * mu) * std::max(0.0, 1.0 - mu_sun * mu_sun)) * std::cos(azimuth);
}

struct Lerp {
  int i;
  float a;
};
Lerp lerp(double f, int size) {
  f = std::clamp(f, 0.0, static_cast<double>(size - 1));
  const int i = std::min(static_cast<int>(f), size - 2);
  return {i, static_cast<float>(f - i)};
}

// Values below the floor are taken as 0 (deep in the Earth's shadow).
constexpr float kFloor = 1e-30f;
const float kLogFloor = std::log(kFloor);

Bins log_of(const Bins& v) {
  Bins out;
  for (int k = 0; k < kBins; ++k) out[k] = std::log(std::max(v[k], kFloor));
  return out;
}

// Where a point (r, μ, μ_s, ν) falls in the table: each axis's lower grid index and
// the fraction toward the next, and how far past the outermost band of μ it lies (0 … 1).
struct TableCoordinates {
  uint8_t altitude, mu_sun, mu, azimuth;
  float a_altitude, a_mu_sun, a_mu, a_azimuth;
  float pole;
};

// The part of it that depends on the point's radius and direction alone: the same for
// every sun along a ray of the grid, so the grid's rays find it once.
struct RayCoordinates {
  Lerp altitude, mu;
  float pole;
};

RayCoordinates ray_coordinates(double rg, double rt, double r, double mu) {
  const double f_mu = (unit_from_mu(mu) + 1.0) * 0.5 * Table::kMuSize - 0.5;
  // Beyond the outermost band of μ toward the zenith or the nadir every azimuth meets
  // in one direction: blend toward the mean over φ of the outermost band, so that the
  // light there does not depend on the azimuth (clamping left a 2–4 % seam at the zenith).
  const float pole = static_cast<float>(std::clamp(2.0 * std::max(-f_mu, f_mu - (Table::kMuSize - 1)), 0.0, 1.0));
  return {lerp(unit_from_altitude(r - rg, rt - rg) * (Table::kAltitudeSize - 1), Table::kAltitudeSize),
          lerp(f_mu, Table::kMuSize), pole};
}

// arccos x within 2.2e-8 rad (Abramowitz & Stegun 1964, 4.4.46): the azimuth's place in the
// table to far below the float weights' rounding, at a fraction of libm's acos (7 % of
// the orders' build).
template <typename Real>
Real acos_polynomial(Real x) {
  const Real a = std::abs(x);
  Real p = Real(-0.0012624911);
  for (const Real c : {Real(0.0066700901), Real(-0.0170881256), Real(0.0308918810), Real(-0.0501743046),
                       Real(0.0889789874), Real(-0.2145988016), Real(1.5707963050)})
    p = p * a + c;
  const Real angle = std::sqrt(Real(1) - a) * p;
  return x < 0 ? Real(kPi) - angle : angle;
}

TableCoordinates coordinates(const RayCoordinates& ray, double mu, double mu_sun, double nu) {
  const double denominator = std::sqrt(std::max(0.0, (1.0 - mu * mu) * (1.0 - mu_sun * mu_sun)));
  const double azimuth =
      denominator < 1e-9 ? 0.0 : acos_polynomial(std::clamp((nu - mu * mu_sun) / denominator, -1.0, 1.0));
  const Lerp ls = lerp(unit_from_mu_sun(mu_sun) * (Table::kMuSunSize - 1), Table::kMuSunSize);
  const Lerp lp = lerp(azimuth / kPi * Table::kAzimuthSize - 0.5, Table::kAzimuthSize);
  return {static_cast<uint8_t>(ray.altitude.i),
          static_cast<uint8_t>(ls.i),
          static_cast<uint8_t>(ray.mu.i),
          static_cast<uint8_t>(lp.i),
          ray.altitude.a,
          ls.a,
          ray.mu.a,
          lp.a,
          ray.pole};
}

// a + f·(b − a), bin by bin.
Table::LogSource blend(const Table::LogSource& a, const Table::LogSource& b, float f) {
  Table::LogSource out;
  for (int k = 0; k < kBins; ++k) {
    out.rayleigh[k] = a.rayleigh[k] + f * (b.rayleigh[k] - a.rayleigh[k]);
    out.aerosol[k] = a.aerosol[k] + f * (b.aerosol[k] - a.aerosol[k]);
  }
  return out;
}

// S from its interpolated logarithms; 0 at the floor. Every bin through exp first and
// the floor after, so that both loops vectorise (the logarithms by value: inlined with
// references the compiler could not rule out that they alias the output, and left the
// loops scalar: the orders took 159 ms against 114).
void exp_above_floor(const Bins log_r, const Bins log_a, Bins& out_r, Bins& out_a) {
  for (int k = 0; k < kBins; ++k) {
    out_r[k] = exp_fast(log_r[k]);
    out_a[k] = exp_fast(log_a[k]);
  }
  for (int k = 0; k < kBins; ++k) {
    out_r[k] = log_r[k] <= kLogFloor + 1 ? 0.0f : out_r[k];
    out_a[k] = log_a[k] <= kLogFloor + 1 ? 0.0f : out_a[k];
  }
}

// S at a table position by multilinear interpolation of log S on the grid: the 16
// corners blended one axis at a time (azimuth, μ, μ_s, altitude), so that each bin
// waits on four blends in a row rather than on sixteen sums.
void gather(const HugePageVector<Table::LogSource>& logs, const TableCoordinates& c, Bins& out_r, Bins& out_a) {
  auto entry = [&logs](int altitude, int mu_sun, int mu, int azimuth) -> const Table::LogSource& {
    return logs[static_cast<size_t>((altitude * Table::kMuSunSize + mu_sun) * kDirections + mu * Table::kAzimuthSize +
                                    azimuth)];
  };
  auto along_azimuth = [&](int di, int dj, int dm) {
    return blend(entry(c.altitude + di, c.mu_sun + dj, c.mu + dm, c.azimuth),
                 entry(c.altitude + di, c.mu_sun + dj, c.mu + dm, c.azimuth + 1), c.a_azimuth);
  };
  auto along_mu = [&](int di, int dj) { return blend(along_azimuth(di, dj, 0), along_azimuth(di, dj, 1), c.a_mu); };
  auto along_mu_sun = [&](int di) { return blend(along_mu(di, 0), along_mu(di, 1), c.a_mu_sun); };
  const Table::LogSource sum = blend(along_mu_sun(0), along_mu_sun(1), c.a_altitude);
  Bins sum_r = sum.rayleigh, sum_a = sum.aerosol;
  if (c.pole > 0) {
    const int row = c.mu == 0 ? 0 : Table::kMuSize - 1;
    Bins mean_r{}, mean_a{};
    for (int corner = 0; corner < 4; ++corner) {
      const int di = corner & 1, dj = (corner >> 1) & 1;
      const float w = (di ? c.a_altitude : 1 - c.a_altitude) * (dj ? c.a_mu_sun : 1 - c.a_mu_sun) / Table::kAzimuthSize;
      for (int p = 0; p < Table::kAzimuthSize; ++p) {
        const Table::LogSource& e = entry(c.altitude + di, c.mu_sun + dj, row, p);
        for (int k = 0; k < kBins; ++k) {
          mean_r[k] += w * e.rayleigh[k];
          mean_a[k] += w * e.aerosol[k];
        }
      }
    }
    for (int k = 0; k < kBins; ++k) {
      sum_r[k] += c.pole * (mean_r[k] - sum_r[k]);
      sum_a[k] += c.pole * (mean_a[k] - sum_a[k]);
    }
  }
  exp_above_floor(sum_r, sum_a, out_r, out_a);
}

// Along one of the grid's rays, every segment's (r, μ) is fixed and only the sun's
// cosine and azimuth there change with the sun and the ray's azimuth: a segment's S over
// (μ_s, φ) is blended along altitude and μ (and toward the pole's mean) once, and each
// of the rays that share the path (every sun and azimuth) reads it with 4 corners
// instead of 16.
void blend_segment(const HugePageVector<Table::LogSource>& logs, const RayCoordinates& where, Table::LogSource* plane) {
  auto entry = [&logs](int altitude, int mu_sun, int mu, int azimuth) -> const Table::LogSource& {
    return logs[static_cast<size_t>((altitude * Table::kMuSunSize + mu_sun) * kDirections + mu * Table::kAzimuthSize +
                                    azimuth)];
  };
  const int i = where.altitude.i, m = where.mu.i;
  const int pole_row = m == 0 ? 0 : Table::kMuSize - 1;
  for (int j = 0; j < Table::kMuSunSize; ++j) {
    Table::LogSource mean{};  // the outermost band's mean over φ, blended along altitude
    if (where.pole > 0)
      for (int di = 0; di <= 1; ++di) {
        const float w = (di ? where.altitude.a : 1 - where.altitude.a) / Table::kAzimuthSize;
        for (int q = 0; q < Table::kAzimuthSize; ++q) {
          const Table::LogSource& e = entry(i + di, j, pole_row, q);
          for (int k = 0; k < kBins; ++k) {
            mean.rayleigh[k] += w * e.rayleigh[k];
            mean.aerosol[k] += w * e.aerosol[k];
          }
        }
      }
    for (int q = 0; q < Table::kAzimuthSize; ++q) {
      const Table::LogSource low = blend(entry(i, j, m, q), entry(i, j, m + 1, q), where.mu.a);
      const Table::LogSource high = blend(entry(i + 1, j, m, q), entry(i + 1, j, m + 1, q), where.mu.a);
      Table::LogSource& out = plane[j * Table::kAzimuthSize + q];
      out = blend(low, high, where.altitude.a);
      if (where.pole > 0) out = blend(out, mean, where.pole);
    }
  }
}

// Where the sun's cosine μ_s and the azimuth between the sun and a direction of zenith
// cosine μ (sine `sin_mu`) fall in a segment's plane, for cosine ν between them.
struct SunPlace {
  int mu_sun, azimuth;
  float a_mu_sun, a_azimuth;
};
SunPlace sun_place(float mu, float sin_mu, float mu_sun, float nu) {
  const float denominator = sin_mu * std::sqrt(std::max(0.0f, 1.0f - mu_sun * mu_sun));
  const float azimuth =
      denominator < 1e-6f ? 0.0f : acos_polynomial(std::clamp((nu - mu * mu_sun) / denominator, -1.0f, 1.0f));
  const Lerp ls = lerp(unit_from_mu_sun(mu_sun) * (Table::kMuSunSize - 1), Table::kMuSunSize);
  const Lerp lp = lerp(azimuth * static_cast<float>(1 / kPi) * Table::kAzimuthSize - 0.5f, Table::kAzimuthSize);
  return {ls.i, lp.i, ls.a, lp.a};
}

// S from a segment's plane (blend_segment) at the sun's place there.
void gather_from_plane(const Table::LogSource* plane, const SunPlace& c, Bins& out_r, Bins& out_a) {
  auto at = [plane](int j, int q) -> const Table::LogSource& { return plane[j * Table::kAzimuthSize + q]; };
  const Table::LogSource low = blend(at(c.mu_sun, c.azimuth), at(c.mu_sun, c.azimuth + 1), c.a_azimuth);
  const Table::LogSource high = blend(at(c.mu_sun + 1, c.azimuth), at(c.mu_sun + 1, c.azimuth + 1), c.a_azimuth);
  const Table::LogSource sum = blend(low, high, c.a_mu_sun);
  exp_above_floor(sum.rayleigh, sum.aerosol, out_r, out_a);
}

// The medium's coefficients in the table's bins.
struct Coefficients {
  Bins rayleigh, aerosol_scattering, aerosol_extinction, ozone;
  explicit Coefficients(const AtmosphereMedium& m) {
    for (int b = 0; b < kBins; ++b) {
      const int k = spectral_bin(b);
      rayleigh[b] = m.rayleigh_scattering[k];
      aerosol_scattering[b] = m.aerosol_scattering[k];
      aerosol_extinction[b] = m.aerosol_extinction[k];
      ozone[b] = m.ozone_absorption[k];
    }
  }
};

// One step along a ray: the densities at its middle and its attenuation.
struct Step {
  float rho_r, rho_a;
  Bins weight;       // ∫ over the step of the attenuation from its start: (1 − e^(−σ_t dt))/σ_t
  Bins attenuation;  // e^(−σ_t dt)
};
Step step(const AtmosphereMedium& m, const Coefficients& c, double h, double dt) {
  Step s{static_cast<float>(m.rayleigh_density(h)), static_cast<float>(m.aerosol_density(h)), {}, {}};
  const float rho_o = static_cast<float>(m.ozone_density(h)), fdt = static_cast<float>(dt);
  for (int k = 0; k < kBins; ++k) {
    const float extinction = c.rayleigh[k] * s.rho_r + c.aerosol_extinction[k] * s.rho_a + c.ozone[k] * rho_o;
    const float x = extinction * fdt;
    s.attenuation[k] = exp_nonpositive(-x);
    s.weight[k] = x < 1e-3f ? fdt * (1.0f - x * (0.5f - x * (1.0f / 6.0f))) : (1.0f - s.attenuation[k]) / extinction;
  }
  return s;
}

// A ray of the grid from radius r in direction μ: where it ends, and its segments with
// all that does not depend on the sun: the same for every sun and every order.
struct RayPath {
  struct Segment {
    double t, r_t, mu_t;    // the segment's middle: distance along the ray, radius, direction
    float mu_t_f, sin_t_f;  // μ_t and √(1 − μ_t²) for sun_place
    RayCoordinates where;
    Step step;
  };
  bool ground = false;
  double length = 0;
  std::vector<Segment> segments;
};

RayPath ray_path(const AtmosphereMedium& m, const Coefficients& c, double rg, double rt, double r, double mu) {
  RayPath path;
  path.ground = shell::hits_ground(r, mu, rg);
  path.length = path.ground ? shell::distance_to_ground(r, mu, rg) : shell::distance_to_outer_sphere(r, mu, rt);
  const std::vector<double> bounds = shell::crowded_boundaries(path.length, -r * mu, Table::kSegments);
  for (size_t i = 1; i < bounds.size(); ++i) {
    const double dt = bounds[i] - bounds[i - 1];
    if (dt <= 0) continue;
    const double t = 0.5 * (bounds[i] + bounds[i - 1]);
    const double r_t = std::clamp(shell::radius_at(r, mu, t), rg, rt);
    const double mu_t = shell::mu_at(r, mu, t, r_t);
    path.segments.push_back({t, r_t, mu_t, static_cast<float>(mu_t),
                             static_cast<float>(std::sqrt(std::max(0.0, 1.0 - mu_t * mu_t))),
                             ray_coordinates(rg, rt, r_t, mu_t), step(m, c, r_t - m.earth_radius_m, dt)});
  }
  return path;
}

}  // namespace

// The grid's points and the transport of one order along rays from them.
struct ScatteringOrdersTable::Grid {
  const AtmosphereMedium& medium;
  const TransmittanceTable& transmittance;
  Coefficients coefficients;
  float rayleigh_phase_gamma;
  AerosolPhaseFunction aerosol_phase;
  double ground_albedo;
  double rg, rt;

  double radius(int i) const { return rg + altitude_from_unit(static_cast<double>(i) / (kAltitudeSize - 1), rt - rg); }
  static double mu_sun(int j) { return mu_sun_from_unit(static_cast<double>(j) / (kMuSunSize - 1)); }

  Bins sun_at(double r, double mu_sun) const {
    static const std::array<int, kBins> bins = [] {
      std::array<int, kBins> out;
      for (int b = 0; b < kBins; ++b) out[static_cast<size_t>(b)] = spectral_bin(b);
      return out;
    }();
    Bins out;
    transmittance.sun_in_bins(r, mu_sun, bins, out);
    return out;
  }

  std::vector<RayPath> paths;  // [altitude][μ], filled by the table's constructor
  const RayPath& path(int altitude, int mu) const { return paths[static_cast<size_t>(altitude * kMuSize + mu)]; }

  // L along the grid's ray `path` from radius r with the sun at μ_s, ν. Order 1 (`planes`
  // null): sunlight scattered once and the sunlit ground. Order n: σ·S_{n−1} (from the
  // path's segments' planes of its logarithms, blend_segment), and the ground's
  // reflection of E_{n−1}.
  Bins transport(const std::vector<LogSource>* planes, const std::vector<Bins>& ground_irradiance, const RayPath& path,
                 double r, double mu_sun, double nu) const {
    const float phase_r = static_cast<float>(rayleigh_phase(nu, rayleigh_phase_gamma));
    const float phase_a = static_cast<float>(aerosol_phase(nu));
    const float nu_f = static_cast<float>(nu);
    Bins throughput, light{}, s_r, s_a;
    throughput.fill(1.0f);
    for (size_t i = 0; i < path.segments.size(); ++i) {
      const RayPath::Segment& segment = path.segments[i];
      const double mu_sun_t = std::clamp((r * mu_sun + segment.t * nu) / segment.r_t, -1.0, 1.0);
      const Step& s = segment.step;
      if (planes) {
        gather_from_plane(planes->data() + i * kPlaneSize,
                          sun_place(segment.mu_t_f, segment.sin_t_f, static_cast<float>(mu_sun_t), nu_f), s_r, s_a);
      } else {
        const Bins sun = sun_at(segment.r_t, mu_sun_t);
        for (int k = 0; k < kBins; ++k) {
          s_r[k] = phase_r * sun[k];
          s_a[k] = phase_a * sun[k];
        }
      }
      for (int k = 0; k < kBins; ++k) {
        const float source =
            coefficients.rayleigh[k] * s.rho_r * s_r[k] + coefficients.aerosol_scattering[k] * s.rho_a * s_a[k];
        light[k] += throughput[k] * source * s.weight[k];
        throughput[k] *= s.attenuation[k];
      }
    }
    if (path.ground) {
      const double mu_sun_g = std::clamp((r * mu_sun + path.length * nu) / rg, -1.0, 1.0);
      Bins e{};
      if (planes) {
        const Lerp ls = lerp(unit_from_mu_sun(mu_sun_g) * (kMuSunSize - 1), kMuSunSize);
        for (int k = 0; k < kBins; ++k)
          e[k] = ground_irradiance[static_cast<size_t>(ls.i)][k] * (1 - ls.a) +
                 ground_irradiance[static_cast<size_t>(ls.i + 1)][k] * ls.a;
      } else if (mu_sun_g > 0) {
        const Bins sun = sun_at(rg, mu_sun_g);
        for (int k = 0; k < kBins; ++k) e[k] = sun[k] * static_cast<float>(mu_sun_g);
      }
      for (int k = 0; k < kBins; ++k) light[k] += throughput[k] * e[k] * static_cast<float>(ground_albedo / kPi);
    }
    return light;
  }

  // Irradiance on the ground from the radiance on the grid's lowest row, per μ_s.
  static std::vector<Bins> ground_irradiance(const HugePageVector<Bins>& radiance) {
    std::vector<Bins> e(kMuSunSize, Bins{});
    for (int j = 0; j < kMuSunSize; ++j)
      for (int d = 0; d < kDirections; ++d) {
        const double mu = mu_of(d / kAzimuthSize);
        if (mu <= 0) continue;
        const float w = static_cast<float>(mu * direction_weight(d / kAzimuthSize));
        for (int k = 0; k < kBins; ++k)
          e[static_cast<size_t>(j)][k] += radiance[static_cast<size_t>(j * kDirections + d)][k] * w;
      }
    return e;
  }
};

ScatteringOrdersTable::ScatteringOrdersTable(const AtmosphereMedium& medium, const TransmittanceTable& transmittance,
                                             const AerosolSettings& aerosol, double ground_albedo)
    : ground_radius_(transmittance.ground_radius()), top_radius_(transmittance.top_radius()) {
  Grid grid{medium,
            transmittance,
            Coefficients(medium),
            static_cast<float>(medium.rayleigh_gamma),
            AerosolPhaseFunction(aerosol),
            ground_albedo,
            ground_radius_,
            top_radius_,
            {}};
  for (int i = 0; i < kAltitudeSize; ++i)
    for (int m = 0; m < kMuSize; ++m)
      grid.paths.push_back(ray_path(medium, grid.coefficients, ground_radius_, top_radius_, grid.radius(i), mu_of(m)));
  const double gamma = medium.rayleigh_gamma;
  std::vector<double> band_mu, band_width;
  for (int m = 0; m < kMuSize; ++m) {
    band_mu.push_back(mu_of(m));
    band_width.push_back(mu_band_width(m));
  }
  const DirectionGridPhaseQuadrature phase_r(band_mu, band_width, kAzimuthSize,
                                             [gamma](double c) { return rayleigh_phase(c, gamma); });
  const DirectionGridPhaseQuadrature phase_a(band_mu, band_width, kAzimuthSize,
                                             [&grid](double c) { return grid.aerosol_phase(c); });

  const size_t size = static_cast<size_t>(kPoints * kDirections);
  // The orders' tables are 2.4–4.7 MB each, new memory: in 2 MiB pages (core/huge_pages.h).
  HugePageVector<Bins> radiance(size), order_r(size), order_a(size);
  std::vector<Bins> ground;
  HugePageVector<LogSource> logs(size);
  HugePageVector<Bins> total_r(size, Bins{}), total_a(size, Bins{});
  Bins last_sum_r{}, last_sum_a{}, before_sum_r{}, before_sum_a{};
  for (int order = 1; order <= kOrders; ++order) {
    // L_order at every point and direction, path by path: the rays from one altitude in
    // one band of μ share their segments, whatever the sun and the azimuth.
    tbb::parallel_for(0, kAltitudeSize * kMuSize, [&](int path_index) {
      const int altitude = path_index / kMuSize, m = path_index % kMuSize;
      const RayPath& path = grid.path(altitude, m);
      thread_local std::vector<LogSource> planes;
      if (order > 1) {
        planes.resize(path.segments.size() * kPlaneSize);
        for (size_t i = 0; i < path.segments.size(); ++i)
          blend_segment(logs, path.segments[i].where, &planes[i * kPlaneSize]);
      }
      const double r = grid.radius(altitude);
      for (int j = 0; j < kMuSunSize; ++j) {
        const double mu_sun = Grid::mu_sun(j);
        const size_t base = static_cast<size_t>((altitude * kMuSunSize + j) * kDirections + m * kAzimuthSize);
        for (int q = 0; q < kAzimuthSize; ++q)
          radiance[base + static_cast<size_t>(q)] = grid.transport(order == 1 ? nullptr : &planes, ground, path, r,
                                                                   mu_sun, nu_of(mu_of(m), mu_sun, azimuth_of(q)));
      }
    });
    ground = Grid::ground_irradiance(radiance);
    // S_order = ∫ P L_order dω at every point.
    tbb::parallel_for(0, kPoints, [&](int p) {
      const size_t base = static_cast<size_t>(p * kDirections);
      thread_local std::vector<Bins> modes(kDirections);
      phase_r.modes_of(&radiance[base], modes.data());
      phase_r.integrate(modes.data(), &order_r[base]);
      phase_a.integrate(modes.data(), &order_a[base]);
      for (size_t i = base; i < base + kDirections; ++i) logs[i] = {log_of(order_r[i]), log_of(order_a[i])};
    });
    before_sum_r = last_sum_r;
    before_sum_a = last_sum_a;
    last_sum_r = last_sum_a = Bins{};
    for (size_t i = 0; i < size; ++i)
      for (int k = 0; k < kBins; ++k) {
        total_r[i][k] += order_r[i][k];
        total_a[i][k] += order_a[i][k];
        last_sum_r[k] += order_r[i][k];
        last_sum_a[k] += order_a[i][k];
      }
  }
  // The orders past the last: a geometric series with the ratio of the last two orders'
  // totals over the whole table (per bin, at most 0.9).
  for (int k = 0; k < kBins; ++k) {
    const float q_r = before_sum_r[k] > 0 ? std::clamp(last_sum_r[k] / before_sum_r[k], 0.0f, 0.9f) : 0.0f;
    const float q_a = before_sum_a[k] > 0 ? std::clamp(last_sum_a[k] / before_sum_a[k], 0.0f, 0.9f) : 0.0f;
    for (size_t i = 0; i < size; ++i) {
      total_r[i][k] += order_r[i][k] * q_r / (1 - q_r);
      total_a[i][k] += order_a[i][k] * q_a / (1 - q_a);
    }
  }
  log_source_.resize(size);
  for (size_t i = 0; i < size; ++i) {
    log_source_[i] = {log_of(total_r[i]), log_of(total_a[i])};
  }
}

ScatteringOrdersTable::Source ScatteringOrdersTable::at(double r, double mu, double mu_sun, double nu) const {
  Bins s_r, s_a;
  gather(log_source_, coordinates(ray_coordinates(ground_radius_, top_radius_, r, mu), mu, mu_sun, nu), s_r, s_a);
  // Linear in wavelength between the table's bins.
  Source out;
  for (int b = 0; b + 1 < kBins; ++b) {
    const int k0 = spectral_bin(b), k1 = spectral_bin(b + 1);
    for (int k = k0; k <= k1; ++k) {
      const float a = static_cast<float>(k - k0) / static_cast<float>(k1 - k0);
      out.rayleigh[k] = s_r[b] * (1 - a) + s_r[b + 1] * a;
      out.aerosol[k] = s_a[b] * (1 - a) + s_a[b + 1] * a;
    }
  }
  return out;
}

}  // namespace skylit
