#include "skylit/clouds/cloud_sky_share.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include <tbb/parallel_for.h>

#include "skylit/material/reflection_sampling.h"

namespace skylit {

namespace {

struct Footprint {
  double x_lo = 1e300, x_hi = -1e300, y_lo = 1e300, y_hi = -1e300;
  double mean_altitude_m = 0;
};

// The clouds' horizontal bounding box (each ellipse's circumscribed square) and their
// mean mid-plane altitude above the ground.
Footprint footprint(const CloudLayer& layer, double ground_z) {
  Footprint f;
  for (const Cloud& cloud : layer.clouds()) {
    const CloudShape& s = cloud.shape();
    const double r = std::max(s.semi_axis_a, s.semi_axis_b);
    f.x_lo = std::min(f.x_lo, s.center_x - r);
    f.x_hi = std::max(f.x_hi, s.center_x + r);
    f.y_lo = std::min(f.y_lo, s.center_y - r);
    f.y_hi = std::max(f.y_hi, s.center_y + r);
    f.mean_altitude_m += std::max(s.altitude - ground_z, 1.0);
  }
  f.mean_altitude_m /= static_cast<double>(std::max<size_t>(1, layer.clouds().size()));
  return f;
}

// Nodes along one axis spanning [lo, hi] with cells of at most `cell_m`, and their spacing.
std::pair<int, double> axis_nodes(double lo, double hi, double cell_m, int max_cells) {
  const int cells = std::clamp(static_cast<int>(std::ceil((hi - lo) / cell_m)), 1, std::max(1, max_cells));
  return {cells + 1, (hi - lo) / cells};
}

}  // namespace

CloudSkyShare::CloudSkyShare(const CloudLayer& layer, const CloudLighting& lighting, const SkyModel& sky,
                             const Vec3& camera_ground, int max_cells)
    : x0_m_(camera_ground.x), y0_m_(camera_ground.y) {
  add_directions(normalize(lighting.to_sun));
  for (Direction& d : directions_) {
    d.clear = sky.sky_radiance_near_ground(d.toward);
    for (int p = 0; p < kPlanes; ++p) {
      const double cosine = dot(d.toward, plane_normal(p));
      const auto weight = static_cast<float>(cosine > 0 ? cosine * d.solid_angle_sr : 0.0);
      d.plane_weight_sr[static_cast<size_t>(p)] = weight;
      clear_[static_cast<size_t>(p)] += d.clear.spectrum() * weight;
    }
  }
  if (!layer.empty()) place_grid(layer, camera_ground, max_cells);
  nodes_.resize(static_cast<size_t>(nodes_x_ * nodes_y_));
  tbb::parallel_for(0, nodes_x_ * nodes_y_, [&](int k) {
    const int i = k % nodes_x_, j = k / nodes_x_;  // the node's column and row
    const Vec3 ground{x0_m_ + i * cell_x_m_, y0_m_ + j * cell_y_m_, camera_ground.z};
    nodes_[static_cast<size_t>(k)] = measure(layer, lighting, sky, ground);
  });
}

void CloudSkyShare::add_directions(const Vec3& to_sun) {
  // The sun's cone: rings at θ = θ_c·u² (u at ring midpoints), dω = sin θ dθ dφ.
  const double cone_rad = radians(kSunCone_deg);
  Vec3 a, b;
  orthonormal_frame(to_sun, a, b);
  double cone_sr = 0;
  for (int i = 0; i < kSunConeRings; ++i) {
    const double u = (i + 0.5) / kSunConeRings, theta = cone_rad * u * u;
    const double d_theta = 2 * cone_rad * u / kSunConeRings;
    for (int j = 0; j < kSunConeAzimuths; ++j) {
      const double phi = 2 * kPi * (j + 0.5) / kSunConeAzimuths;
      const Vec3 d = normalize(std::cos(theta) * to_sun + std::sin(theta) * (std::cos(phi) * a + std::sin(phi) * b));
      if (d.z <= 0) continue;  // the cone's part below the horizon
      const double sr = std::sin(theta) * d_theta * 2 * kPi / kSunConeAzimuths;
      directions_.push_back({d, sr, Radiance{}, {}});
      cone_sr += sr;
    }
  }
  // The rest of the hemisphere: cells of equal solid angle (uniform in cos θ), those
  // whose centre lies in the cone left out and the others sharing what the cone leaves.
  const double cos_cone = std::cos(cone_rad);
  std::vector<Vec3> outside;
  for (int i = 0; i < kZenithRings; ++i) {
    const double mu = (i + 0.5) / kZenithRings, sine = std::sqrt(1 - mu * mu);
    for (int j = 0; j < kAzimuths; ++j) {
      const double phi = 2 * kPi * (j + 0.5) / kAzimuths;
      const Vec3 d{sine * std::cos(phi), sine * std::sin(phi), mu};
      if (dot(d, to_sun) <= cos_cone) outside.push_back(d);
    }
  }
  const double outside_sr = (2 * kPi - cone_sr) / static_cast<double>(outside.size());
  for (const Vec3& d : outside) directions_.push_back({d, outside_sr, Radiance{}, {}});
}

void CloudSkyShare::place_grid(const CloudLayer& layer, const Vec3& camera_ground, int max_cells) {
  const Footprint f = footprint(layer, camera_ground.z);
  const double widen = 2 * f.mean_altitude_m;
  const double x_lo = std::max(f.x_lo - widen, camera_ground.x - kMaxReach_m);
  const double x_hi = std::min(f.x_hi + widen, camera_ground.x + kMaxReach_m);
  const double y_lo = std::max(f.y_lo - widen, camera_ground.y - kMaxReach_m);
  const double y_hi = std::min(f.y_hi + widen, camera_ground.y + kMaxReach_m);
  if (!(x_hi > x_lo && y_hi > y_lo)) return;  // clouds far from the camera: one node below it
  const double cell_m = f.mean_altitude_m / 3;
  std::tie(nodes_x_, cell_x_m_) = axis_nodes(x_lo, x_hi, cell_m, max_cells);
  std::tie(nodes_y_, cell_y_m_) = axis_nodes(y_lo, y_hi, cell_m, max_cells);
  x0_m_ = x_lo;
  y0_m_ = y_lo;
}

Irradiance CloudSkyShare::mean_irradiance_up() const {
  Spectrum sum;
  for (const PlaneIrradiances& e : nodes_) sum += e[0];
  return Irradiance(sum * (1.0f / static_cast<float>(std::max<size_t>(1, nodes_.size()))));
}

Vec3 CloudSkyShare::plane_normal(int plane) {
  if (plane == 0) return {0, 0, 1};
  const double elevation = radians(kPlaneElevations_deg[static_cast<size_t>((plane - 1) / kPlaneAzimuths)]);
  const double azimuth = 2 * kPi * ((plane - 1) % kPlaneAzimuths) / kPlaneAzimuths;
  return {std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth), std::sin(elevation)};
}

CloudSkyShare::PlaneWeights CloudSkyShare::plane_weights(const Vec3& n) {
  PlaneWeights w;
  const double elevation_deg = degrees(std::asin(std::clamp(n.z, -1.0, 1.0)));
  double azimuth = std::atan2(n.y, n.x) / (2 * kPi) * kPlaneAzimuths;
  if (azimuth < 0) azimuth += kPlaneAzimuths;
  const int k0 = std::min(static_cast<int>(azimuth), kPlaneAzimuths - 1), k1 = (k0 + 1) % kPlaneAzimuths;
  const auto fa = static_cast<float>(azimuth - k0);
  // A ring's two planes on either side of the normal's azimuth, weighted `weight` in all.
  auto ring = [&](int r, double weight) {
    w.add(1 + r * kPlaneAzimuths + k0, static_cast<float>(weight) * (1 - fa));
    w.add(1 + r * kPlaneAzimuths + k1, static_cast<float>(weight) * fa);
  };
  if (elevation_deg >= kPlaneElevations_deg[0]) {
    const double t = (elevation_deg - kPlaneElevations_deg[0]) / (90 - kPlaneElevations_deg[0]);
    w.add(0, static_cast<float>(t));
    ring(0, 1 - t);
    return w;
  }
  for (int r = 1; r < static_cast<int>(kPlaneElevations_deg.size()); ++r)
    if (elevation_deg >= kPlaneElevations_deg[static_cast<size_t>(r)]) {
      const double above = kPlaneElevations_deg[static_cast<size_t>(r - 1)];
      const double below = kPlaneElevations_deg[static_cast<size_t>(r)];
      const double t = (elevation_deg - below) / (above - below);
      ring(r - 1, t);
      ring(r, 1 - t);
      return w;
    }
  // Below the lowest ring, toward facing straight down, which sees no sky.
  ring(static_cast<int>(kPlaneElevations_deg.size()) - 1, (elevation_deg + 90) / (kPlaneElevations_deg.back() + 90));
  return w;
}

Transmittance CloudSkyShare::at(const Vec3& point, const Vec3& normal) const {
  if (nodes_.size() == 1) return share_of(nodes_[0], normal);
  const double u = std::clamp((point.x - x0_m_) / cell_x_m_, 0.0, nodes_x_ - 1.0);
  const double v = std::clamp((point.y - y0_m_) / cell_y_m_, 0.0, nodes_y_ - 1.0);
  const int i = std::min(static_cast<int>(u), nodes_x_ - 2), j = std::min(static_cast<int>(v), nodes_y_ - 2);
  const auto fu = static_cast<float>(u - i), fv = static_cast<float>(v - j);
  // Only the planes the normal takes, each interpolated between the four nodes.
  const PlaneWeights w = plane_weights(normal);
  Spectrum clear, clouded;
  for (int t = 0; t < w.count; ++t) {
    const auto p = static_cast<size_t>(w.terms[static_cast<size_t>(t)].plane);
    const float weight = w.terms[static_cast<size_t>(t)].weight;
    clear += clear_[p] * weight;
    clouded += ((node(i, j)[p] * (1 - fu) + node(i + 1, j)[p] * fu) * (1 - fv) +
                (node(i, j + 1)[p] * (1 - fu) + node(i + 1, j + 1)[p] * fu) * fv) *
               weight;
  }
  return ratio(clouded, clear);
}

Transmittance CloudSkyShare::share_of(const PlaneIrradiances& e, const Vec3& normal) const {
  const PlaneWeights w = plane_weights(normal);
  Spectrum clear, clouded;
  for (int t = 0; t < w.count; ++t) {
    const PlaneWeight& term = w.terms[static_cast<size_t>(t)];
    clear += clear_[static_cast<size_t>(term.plane)] * term.weight;
    clouded += e[static_cast<size_t>(term.plane)] * term.weight;
  }
  return ratio(clouded, clear);
}

Transmittance CloudSkyShare::ratio(const Spectrum& clouded, const Spectrum& clear) {
  Spectrum share;
  for (int k = 0; k < kSpectralBins; ++k) share[k] = clear[k] > 0 ? std::min(kMaxShare, clouded[k] / clear[k]) : 1.0f;
  return Transmittance(share);
}

CloudSkyShare::PlaneIrradiances CloudSkyShare::measure(const CloudLayer& layer, const CloudLighting& lighting,
                                                       const SkyModel& sky, const Vec3& ground_point) const {
  PlaneIrradiances e{};
  for (const Direction& d : directions_) {
    const CloudScattering c = layer.scatter(ground_point, d.toward, 0.0, 1e7, lighting);
    // As a view ray sees a cloud (view_path.h): through the air before it, in place of
    // the sky beyond it.
    const Radiance radiance =
        std::isfinite(c.distance)
            ? seen_past(d.clear, sky.aerial_perspective(d.toward, c.distance),
                        {Transmittance(static_cast<float>(c.transmittance)), Radiance(c.in_scattered)})
            : d.clear;
    for (size_t p = 0; p < kPlanes; ++p)
      if (d.plane_weight_sr[p] > 0) e[p] += radiance.spectrum() * d.plane_weight_sr[p];
  }
  return e;
}

}  // namespace skylit
