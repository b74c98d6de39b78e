#include "skylit/sky/sky_light.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <memory>

#include <tbb/parallel_for.h>

#include "skylit/core/counter_random.h"
#include "skylit/geometry/transform.h"
#include "skylit/material/reflection.h"
#include "skylit/spectrum/cie.h"

namespace skylit {

SkyLight::SkyLight(const SkyModel& sky, const RayTracer& tracer, ObstacleRadiance obstacle_radiance,
                   std::vector<SkyElement> elements, const FogSurfaceLight* fog,
                   const FogShadowedSunlight* shadowed_fog_sunlight, Cells cells, Turning turning)
    : sky_(sky),
      tracer_(tracer),
      obstacle_radiance_(std::move(obstacle_radiance)),
      elements_(std::move(elements)),
      cell_detail_(cells),
      turning_(turning),
      fog_(fog),
      shadowed_fog_sunlight_(fog ? shadowed_fog_sunlight : nullptr) {
  for (const SkyElement& e : elements_) element_radiance_.push_back(sky_.sky_radiance_near_ground(e.direction));
  if (fog_) {
    std::vector<Vec3> directions;
    for (const SkyElement& e : elements_) directions.push_back(e.direction);
    fog_elements_ = std::make_unique<FogSurfaceLight::Directions>(*fog_, directions);
  }
  if (cell_detail_ != Cells::kCentres) find_cells();
  assert(turning_ == Turning::kNone || cell_detail_ == Cells::kCentres);  // cells are laid for the directions as given
  if (turning_ == Turning::kPerPoint) turn_elements();
  // Bands of equal height with about 2 × 16 elements per band for each band, so that a
  // packet of 16 rays spans about as much in height as in azimuth; within a band by
  // azimuth.
  const int bands = std::max(1, static_cast<int>(std::lround(std::sqrt(elements_.size() / 32.0))));
  auto band_of = [&](uint32_t i) {
    return std::min(bands - 1, static_cast<int>((1 - elements_[i].direction.z) / 2 * bands));
  };
  packet_order_.resize(elements_.size());
  for (uint32_t i = 0; i < packet_order_.size(); ++i) packet_order_[i] = i;
  std::sort(packet_order_.begin(), packet_order_.end(), [&](uint32_t a, uint32_t b) {
    const int band_a = band_of(a), band_b = band_of(b);
    if (band_a != band_b) return band_a < band_b;
    const double azimuth_a = std::atan2(elements_[a].direction.y, elements_[a].direction.x);
    const double azimuth_b = std::atan2(elements_[b].direction.y, elements_[b].direction.x);
    return azimuth_a != azimuth_b ? azimuth_a < azimuth_b : a < b;
  });
}

void SkyLight::turn_elements() {
  // Turn 0 is the set as given; turns 1… are rotations of the sphere drawn uniformly
  // (Shoemake's unit quaternions, from a fixed sequence: the same for every run). About
  // the vertical alone would not do: a Fibonacci set keeps its points' heights under
  // such a turn, and near the zenith its rings of height are a few degrees apart, which
  // misjudged a canyon's slit of sky by 2.7 % on average over any number of points. The
  // sky's radiance is looked up once per turned direction here, not per integral.
  turned_elements_.assign(kTurns, elements_);
  turned_radiance_.assign(kTurns, element_radiance_);
  tbb::parallel_for(1, kTurns, [&](int k) {
    // The n-th number of turn k: SplitMix64 of (k + n) golden-ratio steps.
    auto uniform = [k, n = uint64_t{0}]() mutable {
      return static_cast<double>(splitmix64(0x9e3779b97f4a7c15ULL * (static_cast<uint64_t>(k) + n++)) >> 11) *
             0x1.0p-53;
    };
    const double u1 = uniform(), u2 = uniform(), u3 = uniform();
    const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
    const Transform turn = Transform::rotation_quaternion(a * std::sin(2 * kPi * u2), a * std::cos(2 * kPi * u2),
                                                          b * std::sin(2 * kPi * u3), b * std::cos(2 * kPi * u3));
    for (size_t i = 0; i < elements_.size(); ++i) {
      Vec3& d = turned_elements_[static_cast<size_t>(k)][i].direction;
      d = normalize(turn.apply_vector(d));
      turned_radiance_[static_cast<size_t>(k)][i] = sky_.sky_radiance_near_ground(d);
    }
  });
}

void SkyLight::find_cells() {
  // Each element's 3 × 3 sub-cells, a third of its width wide and (but where the
  // horizon crosses it) a third tall, and the sky's mean radiance over each from 4 × 4
  // samples; the element's radiance is their mean, each weighed by its share of it
  // (its height / 9).
  cells_.resize(elements_.size());
  tbb::parallel_for(size_t{0}, elements_.size(), [&](size_t i) {
    const Vec3& d = elements_[i].direction;
    const double step = std::sqrt(elements_[i].solid_angle) / 3;  // a sub-cell's width
    const Vec3 t1 = normalize(cross(d, std::abs(d.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0}));
    const Vec3 t2 = cross(d, t1);
    CellGrid& c = cells_[i];
    c.across_u = step * t1;
    c.across_v = step * t2;
    auto across = [&](double u, double v) { return c.toward(d, u, v); };
    // The rows' bounds along t2 (vertical: t1 is horizontal), in sub-cell widths. Where
    // the horizon crosses the element it is made a bound between rows (one or two rows
    // on each side of it), so that no sub-cell holds both sky and far ground: its ray
    // could count only one of them.
    std::array<double, 4>& rows = c.rows;
    rows = {-1.5, -0.5, 0.5, 1.5};
    const double v_horizon = std::abs(t2.z) > 1e-9 ? -d.z / (step * t2.z) : 1e9;
    c.straddles_horizon = std::abs(v_horizon) < 1.5;
    if (c.straddles_horizon) {
      const int low_rows = std::clamp(static_cast<int>(std::lround(v_horizon + 1.5)), 1, 2);
      for (int r = 0; r <= 3; ++r)
        rows[static_cast<size_t>(r)] = r <= low_rows ? -1.5 + r * (v_horizon + 1.5) / low_rows
                                                     : v_horizon + (r - low_rows) * (1.5 - v_horizon) / (3 - low_rows);
    }
    int next = 0;
    Radiance total;
    for (int u = -1; u <= 1; ++u)
      for (size_t r = 0; r < 3; ++r) {
        const double low = rows[r], high = rows[r + 1];
        const size_t slot = (u == 0 && r == 1) ? kSubCells - 1 : static_cast<size_t>(next++);
        c.directions[slot] = across(u, c.centre(r));
        Radiance mean;
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b < 4; ++b)
            mean += sky_.sky_radiance_near_ground(across(u + (a - 1.5) / 4, low + (b + 0.5) / 4 * (high - low)));
        c.radiance[slot] = mean * (1.0f / 16);
        total += c.radiance[slot] * static_cast<float>((high - low) / 9);  // its share of the element
      }
    element_radiance_[i] = total;
  });
  for (const Radiance& r : element_radiance_) element_cd_.push_back(luminance(r));
  // The open sky's irradiance from the same radiances, over normals.
  tbb::parallel_for(0, kOpenElevations * kOpenAzimuths, [&](int g) {
    const int row = g / kOpenAzimuths, column = g % kOpenAzimuths;
    const double elevation = -kPi / 2 + kPi * row / (kOpenElevations - 1);
    const double azimuth = 2 * kPi * column / (kOpenAzimuths - 1);
    const Vec3 n{std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth), std::sin(elevation)};
    Spectrum e(0.0f);
    for (size_t i = 0; i < elements_.size(); ++i) {
      const double c = dot(n, elements_[i].direction);
      if (c > 0) e += element_radiance_[i].spectrum() * static_cast<float>(c * elements_[i].solid_angle);
    }
    open_irradiance_.at(column, row) = e;
  });
  // Elements whose sub-cells differ by more than kVaryingCell × the sky's mean (the
  // aureole, the horizon where the step is large) or that straddle the horizon, and
  // their nearest neighbours.
  double sum = 0;
  int count = 0;
  for (size_t i = 0; i < elements_.size(); ++i)
    if (elements_[i].direction.z > 0) {
      sum += luminance(element_radiance_[i]);
      ++count;
    }
  const double threshold = kVaryingCell * sum / std::max(1, count);
  tbb::parallel_for(size_t{0}, elements_.size(), [&](size_t i) {
    CellGrid& c = cells_[i];
    double least = std::numeric_limits<double>::infinity(), most = 0;
    for (const Radiance& r : c.radiance) {
      least = std::min(least, luminance(r));
      most = std::max(most, luminance(r));
    }
    c.varying = most - least > threshold;
    // (With Cells::kMeans any element may be traced apart where an outline crosses it.)
    if (!c.varying && !c.straddles_horizon && cell_detail_ != Cells::kMeans) return;
    const Vec3& d = elements_[i].direction;
    const double near_cosine = std::cos(3 * std::sqrt(elements_[i].solid_angle));
    std::vector<std::pair<double, uint32_t>> near;
    for (uint32_t j = 0; j < elements_.size(); ++j)
      if (j != i && dot(d, elements_[j].direction) > near_cosine) near.emplace_back(dot(d, elements_[j].direction), j);
    const size_t keep = std::min<size_t>(kNeighbours, near.size());
    std::partial_sort(
        near.begin(), near.begin() + static_cast<std::ptrdiff_t>(keep), near.end(),
        [](const auto& x, const auto& y) { return x.first > y.first || (x.first == y.first && x.second < y.second); });
    for (size_t n = 0; n < kNeighbours; ++n) c.neighbours[n] = n < keep ? near[n].second : static_cast<uint32_t>(i);
  });
}

bool SkyLight::refined(const CellGrid& c, const Vec3& normal) const {
  if (c.varying) return true;
  if (!c.straddles_horizon || cell_detail_ == Cells::kMeansAcrossTheAureole) return false;
  return above_surface(c, normal);
}

bool SkyLight::above_surface(const CellGrid& c, const Vec3& normal) {
  for (const Vec3& d : c.directions)
    if (dot(normal, d) <= 0) return false;
  return true;
}

Spectrum SkyLight::open_irradiance(const Vec3& normal) const {
  const double elevation = std::asin(std::clamp(normal.z, -1.0, 1.0));
  double azimuth = std::atan2(normal.y, normal.x);
  if (azimuth < 0) azimuth += 2 * kPi;
  return open_irradiance_.interpolate(azimuth / (2 * kPi) * (kOpenAzimuths - 1),
                                      (elevation + kPi / 2) / kPi * (kOpenElevations - 1));
}

Radiance SkyLight::specular_radiance(const Vec3& point, const Vec3& normal, const Vec3& to_viewer,
                                     const Material& material) const {
  if (!has_specular(material)) return Radiance(0.0f);
  const Vec3 origin = offset_from_surface(point, normal);
  // The bands' frame: axis a ⟂ n and ⟂ r; the element (α, δ) lies in direction
  // cos α·a + sin α (cos δ·r + sin δ·b), b = a × r. The mirror direction r is (90°, 0)
  // and the surface's hemisphere is |δ − β| < 90° with n = cos β·r + sin β·b.
  const Vec3 r = normalize(mirror_direction(normal, to_viewer));
  Vec3 a = cross(normal, r);
  if (length(a) < 1e-6) a = cross(normal, std::abs(normal.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0});
  a = normalize(a);
  const Vec3 b = cross(a, r);
  const double beta = std::atan2(dot(normal, b), dot(normal, r));
  const double width =
      std::clamp(kSpecularElementPerRoughness * specular_roughness(material), radians(1.0), radians(5.0));
  const int half_segments = static_cast<int>(std::ceil(0.5 * kPi / width));  // along α, each way from 90°
  Radiance sum;
  double peak = 0;  // the largest G met: ε is relative to it

  // Element (band k, segment j): δ = k·width, α = 90° + j·width. Adds it when its G
  // is at least ε of the peak; returns G.
  auto direction_at = [&](double alpha, double delta) {
    return std::cos(alpha) * a + std::sin(alpha) * (std::cos(delta) * r + std::sin(delta) * b);
  };
  // The sky's mean radiance over an element. Where the element straddles the horizon
  // (the sky above, the far ground below: a step in radiance), from 4 × 4 points
  // across it: a single point there would count all of the element as sky or as ground,
  // and a wall seen head-on reflects exactly that part of the dome.
  // In a fog that lights the point, the fog's light from each direction stands for the
  // sky's, and an obstacle is seen through the fog in front of it.
  const bool in_fog = lights_in_fog(point.z);
  auto sky_toward = [&](const Vec3& direction) {
    return in_fog ? Radiance(fog_->incoming(point.z, direction)) : sky_.sky_radiance_near_ground(direction);
  };
  // Seen through the fog (δ-M): the fog's light here, plus the difference between the
  // obstacle's light and the fog's light, dimmed by the fog between. The fog's light is
  // taken here rather than at the obstacle (as the diffuse part does): a second look-up
  // of the field per element showed in `perf` at a few per cent of a glossy fog frame,
  // and the glossy lobe sees obstacles near the mirror direction, mostly at the point's
  // own height.
  auto obstacle_seen = [&](const Ray& ray, const Hit& hit) {
    const Radiance light = obstacle_radiance_(ray, hit, width).radiance;
    if (!in_fog) return light;
    const Radiance fog = sky_toward(ray.direction);
    return fog + (light - fog) * Transmittance(fog_->transmittance(point, ray.direction, hit.t));
  };
  auto sky_over = [&](double alpha, double delta, const Vec3& centre) {
    if (std::abs(centre.z) > 0.75 * width) return sky_toward(centre);
    Radiance mean;
    double total = 0;
    for (int u = 0; u < 4; ++u)
      for (int w = 0; w < 4; ++w) {
        const double sub_alpha = alpha + (u - 1.5) * width / 4, sub_delta = delta + (w - 1.5) * width / 4;
        const double weight = std::sin(sub_alpha);
        mean += sky_toward(direction_at(sub_alpha, sub_delta)) * static_cast<float>(weight);
        total += weight;
      }
    return mean * static_cast<float>(1.0 / total);
  };
  // The elements whose G reaches ε, found by the walk; their light is gathered after.
  struct Element {
    int k, j;
    double alpha, delta, solid_angle;
    Vec3 direction;
    Radiance sky;
  };
  std::vector<Element> found;
  auto visit = [&](int k, int j) {
    const double alpha = kPi / 2 + j * width, delta = k * width;
    if (alpha <= 0 || alpha >= kPi) return 0.0;
    const Vec3 l = direction_at(alpha, delta);
    const double solid_angle = std::sin(alpha) * width * width;
    const double weight = specular_weight(material, normal, l, to_viewer);
    if (weight <= 0) return 0.0;
    const Radiance sky = sky_over(alpha, delta, l);
    const double g = luminance(sky) * weight * solid_angle;
    peak = std::max(peak, g);
    if (g >= kSpecularThreshold * peak) found.push_back({k, j, alpha, delta, solid_angle, l, sky});
    return g;
  };
  // Steps 2(a)–(b): along band k from its segment nearest the mirror direction, both
  // ways while G ≥ ε; returns G at that nearest segment.
  auto walk_band = [&](int k) {
    const double g0 = visit(k, 0);
    if (g0 < kSpecularThreshold * peak || g0 <= 0) return g0;
    for (int direction : {-1, +1})
      for (int j = direction; std::abs(j) <= half_segments; j += direction)
        if (const double g = visit(k, j); g < kSpecularThreshold * peak || g <= 0) break;
    return g0;
  };
  // Steps 3–5: bands on either side, outward, until the band's nearest element falls
  // below ε or the band leaves the surface's hemisphere.
  walk_band(0);
  for (int direction : {-1, +1}) {
    for (int k = direction;; k += direction) {
      if (std::abs(k * width - beta) >= kPi / 2 || std::abs(k * width) > kPi) break;
      if (const double g = walk_band(k); g < kSpecularThreshold * peak || g <= 0) break;
    }
  }

  // Which elements obstacles hide, one ray each; where an element's neighbours disagree
  // an obstacle's edge crosses it, and 3 × 3 rays across it find how much of it is
  // hidden. (A whole element hidden or not, 4–9° wide, made the blurred reflection of a
  // building opposite blotchy from one surface point to the next.)
  std::map<std::pair<int, int>, size_t> index;
  for (size_t i = 0; i < found.size(); ++i) index[{found[i].k, found[i].j}] = i;
  // The elements' rays go to the tracer together (the walk keeps neighbours together: a
  // coherent packet), and so do the 3 × 3 rays of every element an edge crosses.
  thread_local std::vector<Ray> rays, edge_rays;
  thread_local std::vector<std::optional<Hit>> hits, edge_hits;
  rays.clear();
  for (const Element& e : found) rays.push_back(Ray{origin, e.direction});
  tracer_.intersect(rays, hits);
  std::vector<std::optional<Radiance>> obstacle(found.size());  // the obstacle's light, if hidden
  for (size_t i = 0; i < found.size(); ++i)
    if (hits[i]) obstacle[i] = obstacle_seen(rays[i], *hits[i]);
  std::vector<bool> edge(found.size(), false);
  edge_rays.clear();
  for (size_t i = 0; i < found.size(); ++i) {
    const Element& e = found[i];
    for (const auto& [dk, dj] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
      const auto it = index.find({e.k + dk, e.j + dj});
      edge[i] = edge[i] || (it != index.end() && obstacle[it->second].has_value() != obstacle[i].has_value());
    }
    if (!edge[i]) continue;
    for (int u = -1; u <= 1; ++u)
      for (int w = -1; w <= 1; ++w)
        edge_rays.push_back(Ray{origin, direction_at(e.alpha + u * width / 3, e.delta + w * width / 3)});
  }
  tracer_.intersect(edge_rays, edge_hits);
  size_t next_edge_ray = 0;
  for (size_t i = 0; i < found.size(); ++i) {
    const Element& e = found[i];
    Radiance incoming_light = obstacle[i] ? *obstacle[i] : e.sky;
    if (edge[i]) {
      Radiance mixed;
      for (int sub = 0; sub < 9; ++sub, ++next_edge_ray) {
        const std::optional<Hit>& hit = edge_hits[next_edge_ray];
        mixed += hit ? obstacle_seen(edge_rays[next_edge_ray], *hit) : e.sky;
      }
      incoming_light = mixed * (1.0f / 9.0f);
    }
    sum += specular_reflection(material, normal, e.direction, to_viewer).reflect(incoming_light, e.solid_angle);
  }
  return sum;
}

Irradiance SkyLight::diffuse_irradiance(const Vec3& point, const Vec3& normal, double* obstacle_distance_m,
                                        uint64_t turn_drawn) const {
  // Per bin: the hidden elements' radiance × cos dω changes the irradiance. In a fog
  // that lights the point, the unobstructed light is the fog field's, and what a hidden
  // element changes is seen through the fog in front of its obstacle.
  const bool in_fog = lights_in_fog(point.z);
  Spectrum irradiance = in_fog            ? fog_->irradiance(point, normal)
                        : !cells_.empty() ? open_irradiance(normal)
                                          : sky_.sky_irradiance(normal).spectrum();
  const Vec3 origin = offset_from_surface(point, normal);
  // (Not in a fog that lights the point: its light is tabulated for the directions as given.)
  const size_t turn = turning_ == Turning::kPerPoint && !in_fog ? static_cast<size_t>(turn_drawn % kTurns) : 0;
  const std::vector<SkyElement>& elements = turn == 0 ? elements_ : turned_elements_[turn];
  const std::vector<Radiance>& element_radiance = turn == 0 ? element_radiance_ : turned_radiance_[turn];
  // The rays toward the elements above the surface's horizon, traced together in packet
  // order; then each element's change in the elements' own order (the sum is clamped
  // at every step, so its order is kept). The buffers are kept per thread, one set for
  // each depth of nesting: an obstacle's light may itself come from a diffuse integral
  // (render/obstacle_sky_light.h).
  struct Buffers {
    std::vector<Ray> rays, edge_rays;
    std::vector<std::optional<Hit>> hits, edge_hits;
    std::vector<int32_t> ray_of_element, edge_ray_of_element;
    std::vector<OutlineCrossing> crossings;
    std::vector<Ray> bisection_rays;
    std::vector<std::optional<Hit>> bisection_hits;
    std::vector<ObstacleLight> centre_lights;
    std::vector<double> centre_light_cd;  // their luminance
    std::vector<int32_t> centre_light_of_element;
    std::vector<std::pair<double, uint32_t>> candidates;  // (potential error, element)
  };
  thread_local std::vector<std::unique_ptr<Buffers>> buffers_by_depth;
  thread_local size_t depth = 0;
  if (buffers_by_depth.size() <= depth) buffers_by_depth.push_back(std::make_unique<Buffers>());
  Buffers& buffers = *buffers_by_depth[depth];
  struct Nesting {
    size_t& depth;
    explicit Nesting(size_t& d) : depth(++d) {}
    ~Nesting() { --depth; }
    Nesting(const Nesting&) = delete;
    Nesting& operator=(const Nesting&) = delete;
  } nesting(depth);
  std::vector<Ray>& rays = buffers.rays;
  std::vector<std::optional<Hit>>& hits = buffers.hits;
  std::vector<int32_t>& ray_of_element = buffers.ray_of_element;
  rays.clear();
  ray_of_element.assign(elements.size(), -1);
  for (const uint32_t i : packet_order_) {
    if (dot(normal, elements[i].direction) <= 0) continue;
    ray_of_element[i] = static_cast<int32_t>(rays.size());
    rays.push_back(Ray{origin, elements[i].direction});
  }
  tracer_.intersect(rays, hits);
  std::vector<int32_t>& edge_ray_of_element = buffers.edge_ray_of_element;
  // (Not in a fog that lights the point: its light is the field's, by element centres.)
  const bool by_cells = !cells_.empty() && !in_fog;
  edge_ray_of_element.assign(by_cells ? elements.size() : 0, -1);
  buffers.edge_rays.clear();
  auto hidden_at = [&](size_t i) { return hits[static_cast<size_t>(ray_of_element[i])].has_value(); };
  // Whether an obstacle's outline passes element i: a neighbour's ray disagrees with its own.
  auto on_outline = [&](size_t i) {
    const bool hidden = hidden_at(i);
    for (const uint32_t j : cells_[i].neighbours)
      if (ray_of_element[j] >= 0 && hidden_at(j) != hidden) return true;
    return false;
  };
  // The obstacles' light at the hidden elements' centres, for those not traced apart.
  std::vector<ObstacleLight>& centre_lights = buffers.centre_lights;
  std::vector<int32_t>& centre_light_of_element = buffers.centre_light_of_element;
  std::vector<double>& centre_light_cd = buffers.centre_light_cd;
  centre_lights.clear();
  centre_light_cd.clear();
  centre_light_of_element.assign(elements.size(), -1);
  auto centre_light_index = [&](size_t i) {
    if (centre_light_of_element[i] < 0) {
      const size_t r = static_cast<size_t>(ray_of_element[i]);
      centre_light_of_element[i] = static_cast<int32_t>(centre_lights.size());
      centre_lights.push_back(obstacle_radiance_(rays[r], *hits[r], std::sqrt(elements[i].solid_angle)));
      centre_light_cd.push_back(-1);  // until asked for
    }
    return static_cast<size_t>(centre_light_of_element[i]);
  };
  auto centre_light = [&](size_t i) -> const ObstacleLight& { return centre_lights[centre_light_index(i)]; };
  auto centre_cd = [&](size_t i) {
    const size_t k = centre_light_index(i);
    if (centre_light_cd[k] < 0) centre_light_cd[k] = luminance(centre_lights[k].radiance);
    return centre_light_cd[k];
  };
  auto trace_apart = [&](size_t i) {
    edge_ray_of_element[i] = static_cast<int32_t>(buffers.edge_rays.size());
    for (int k = 0; k < cells_[i].traced_sub_cells(); ++k)
      buffers.edge_rays.push_back(Ray{origin, cells_[i].directions[k]});
  };
  if (by_cells) {
    // Where the sky's sub-cells differ (the aureole, the horizon), always; elsewhere,
    // with Cells::kMeans, the outlines whose elements counted whole could misjudge the
    // irradiance most (below).
    std::vector<std::pair<double, uint32_t>>& candidates = buffers.candidates;
    candidates.clear();
    for (size_t i = 0; i < elements.size(); ++i) {
      if (ray_of_element[i] < 0 || !on_outline(i)) continue;
      if (refined(cells_[i], normal))
        trace_apart(i);
      else if (cell_detail_ == Cells::kMeans && above_surface(cells_[i], normal))
        candidates.emplace_back(0.0, static_cast<uint32_t>(i));
    }
    if (!candidates.empty()) {
      // Counted whole, an element an outline crosses is off by its weight times the step
      // in radiance across the outline times the share of it on the other side (uniform
      // in [−½, ½]: RMS 0.29), independently from element to element. The steps: a hidden
      // element's obstacle against its sky; an open element's sky against its hidden
      // neighbours' obstacles.
      double total_cd = illuminance(Irradiance(irradiance));
      for (size_t i = 0; i < elements.size(); ++i)
        if (ray_of_element[i] >= 0 && hidden_at(i) && edge_ray_of_element[i] < 0)
          total_cd += dot(normal, elements[i].direction) * elements[i].solid_angle * (centre_cd(i) - element_cd_[i]);
      double error_squared = 0;
      for (auto& [error, i] : candidates) {
        double step = 0;
        if (hidden_at(i)) {
          step = centre_cd(i) - element_cd_[i];
        } else {
          int n = 0;
          for (const uint32_t j : cells_[i].neighbours)
            if (ray_of_element[j] >= 0 && hidden_at(j)) {
              step += centre_cd(j);
              ++n;
            }
          step = step / std::max(1, n) - element_cd_[i];
        }
        error = kShareErrorRms * dot(normal, elements[i].direction) * elements[i].solid_angle * std::abs(step);
        error_squared += error * error;
      }
      // The largest first, until what is left would misjudge the irradiance by less than
      // kOutlineTolerance (RMS).
      std::sort(candidates.begin(), candidates.end(), std::greater<>());
      const double allowed = kOutlineTolerance * std::max(total_cd, 0.0);
      for (const auto& [error, i] : candidates) {
        if (error_squared <= allowed * allowed) break;
        trace_apart(i);
        error_squared -= error * error;
      }
    }
    if (!buffers.edge_rays.empty()) tracer_.intersect(buffers.edge_rays, buffers.edge_hits);
  }
  // The sub-cell in `slot` of a traced element: its ray and hit (the middle one's the
  // element's own where the horizon does not cross it).
  auto sub_cell = [&](size_t i, int slot) -> std::pair<const Ray*, const std::optional<Hit>*> {
    const size_t ray_index = static_cast<size_t>(ray_of_element[i]);
    if (slot == kSubCells - 1 && !cells_[i].straddles_horizon) return {&rays[ray_index], &hits[ray_index]};
    const size_t edge = static_cast<size_t>(edge_ray_of_element[i]) + static_cast<size_t>(slot);
    return {&buffers.edge_rays[edge], &buffers.edge_hits[edge]};
  };
  // Where two rows of a traced element's column disagree, the outline between their
  // centres, by bisection (kOutlineBisections rounds, each round's rays traced together):
  // where the sky varies within the element. Elsewhere the sub-cells alone take the
  // error of an element counted whole down to a third, as the outlines' budget assumes.
  std::vector<OutlineCrossing>& crossings = buffers.crossings;
  crossings.clear();
  for (size_t i = 0; !buffers.edge_rays.empty() && i < elements.size(); ++i) {
    if (edge_ray_of_element[i] < 0 || !refined(cells_[i], normal)) continue;
    const CellGrid& c = cells_[i];
    for (size_t u = 0; u < 3; ++u)
      for (size_t r = 0; r < 2; ++r) {
        const bool lower_hidden = sub_cell(i, kSlot[u][r]).second->has_value();
        if (lower_hidden == sub_cell(i, kSlot[u][r + 1]).second->has_value()) continue;
        crossings.push_back({static_cast<uint32_t>(i), u, r, lower_hidden, c.centre(r), c.centre(r + 1)});
      }
  }
  const int bisections = cell_detail_ == Cells::kMeans ? kOutlineBisections : 0;
  for (int round = 0; round < bisections && !crossings.empty(); ++round) {
    buffers.bisection_rays.clear();
    for (const OutlineCrossing& x : crossings)
      buffers.bisection_rays.push_back(
          Ray{origin, cells_[x.element].toward(elements[x.element].direction, static_cast<double>(x.column) - 1,
                                               0.5 * (x.low + x.high))});
    tracer_.intersect(buffers.bisection_rays, buffers.bisection_hits);
    for (size_t k = 0; k < crossings.size(); ++k) {
      OutlineCrossing& x = crossings[k];
      const double mid = 0.5 * (x.low + x.high);
      (buffers.bisection_hits[k].has_value() == x.lower_hidden ? x.low : x.high) = mid;
    }
  }
  Spectrum reflected_back(0.0f);  // Σ_hidden w·T·ρ/π over the obstacles lit as the point
  bool lit_as_the_point = false;
  double weight_sum = 0, weight_over_distance = 0;  // Σ w, Σ_hidden w / t (when asked)
  // Element i's share w hidden by the obstacle `ray` meets (`light`), in place of `sky`.
  auto add_hidden = [&](size_t i, const Ray& ray, const Hit& hit, const ObstacleLight& light, double w,
                        const Radiance& sky) {
    const SkyElement& e = elements[i];
    if (obstacle_distance_m) weight_over_distance += w / std::max(hit.t, 1e-3);
    const float weight = static_cast<float>(w);
    const Radiance& obstacle = light.radiance;
    const Spectrum& albedo = light.lit_as_the_point.spectrum();
    lit_as_the_point = lit_as_the_point || !light.lit_as_the_point.is_black();
    if (in_fog) {
      const Spectrum hidden = fog_elements_->incoming(fog_elements_->at(point.z + e.direction.z * hit.t), i);
      const Spectrum through = fog_->transmittance(point, ray.direction, hit.t);
      for (int k = 0; k < kSpectralBins; ++k) {
        irradiance[k] = std::max(0.0f, irradiance[k] + weight * through[k] * (obstacle[k] - hidden[k]));
        reflected_back[k] += weight * through[k] * albedo[k] * static_cast<float>(1.0 / kPi);
      }
    } else {
      for (int k = 0; k < kSpectralBins; ++k) {
        irradiance[k] = std::max(0.0f, irradiance[k] + weight * (obstacle[k] - sky[k]));
        reflected_back[k] += weight * albedo[k] * static_cast<float>(1.0 / kPi);
      }
    }
  };
  size_t next_crossing = 0;  // crossings are in the elements' order
  for (size_t i = 0; i < elements.size(); ++i) {
    const SkyElement& e = elements[i];
    if (ray_of_element[i] < 0) continue;
    const double cosine = dot(normal, e.direction);
    const Ray& ray = rays[static_cast<size_t>(ray_of_element[i])];
    const std::optional<Hit>& hit = hits[static_cast<size_t>(ray_of_element[i])];
    const double w = cosine * e.solid_angle;
    if (obstacle_distance_m) weight_sum += w;
    if (!edge_ray_of_element.empty() && edge_ray_of_element[i] >= 0) {
      // Column by column, each hidden row's stretch of v: the row itself, but where a
      // neighbouring row disagrees, up to the outline found between their centres. Each
      // sub-cell a stretch covers takes out its own radiance over that part of it, its
      // share of the element being its height / 9 (as the open sky counts it); the
      // obstacle's light is the hidden row's own ray's. (A sub-cell below the surface's
      // own horizon meets the surface itself and counts as hidden by it: counting it as
      // open or with the centre's ray measured worse on Fig. 7, the cache's 99th
      // percentile against 16,384 directions 2.84 → 3.38 %.)
      const CellGrid& c = cells_[i];
      // Traced apart for its outline alone (the sky even across it), one obstacle light
      // stands for all its hidden sub-cells: the centre's where the centre is hidden, else
      // the first hidden sub-cell's, either over the element's whole footprint.
      const bool for_the_outline = !refined(c, normal);
      std::optional<ObstacleLight> shared_light;
      if (for_the_outline && hit) shared_light = centre_light(i);
      for (size_t u = 0; u < 3; ++u) {
        // The outlines of this column, by the lower of their two rows.
        std::array<std::optional<double>, 2> outline{};
        while (next_crossing < crossings.size() && crossings[next_crossing].element == i &&
               crossings[next_crossing].column == u) {
          const OutlineCrossing& x = crossings[next_crossing++];
          outline[x.lower_row] = 0.5 * (x.low + x.high);
        }
        for (size_t r = 0; r < 3; ++r) {
          const auto [own_ray, own_hit] = sub_cell(i, kSlot[u][r]);
          if (!own_hit->has_value()) continue;
          const double from = r > 0 && outline[r - 1] ? *outline[r - 1] : c.rows[r];
          const double to = r < 2 && outline[r] ? *outline[r] : c.rows[r + 1];
          if (for_the_outline && !shared_light)
            shared_light = obstacle_radiance_(*own_ray, **own_hit, std::sqrt(e.solid_angle));
          // (Its width a sub-cell's: a third of the element's.)
          const ObstacleLight light =
              for_the_outline ? *shared_light : obstacle_radiance_(*own_ray, **own_hit, std::sqrt(e.solid_angle) / 3);
          for (size_t row = 0; row < 3; ++row) {
            const double overlap = std::min(to, c.rows[row + 1]) - std::max(from, c.rows[row]);
            const size_t slot = static_cast<size_t>(kSlot[u][row]);
            if (overlap > 0) add_hidden(i, *own_ray, **own_hit, light, w * overlap / 9, c.radiance[slot]);
          }
        }
      }
      continue;
    }
    if (hit) add_hidden(i, ray, *hit, centre_light(i), w, element_radiance[i]);
  }
  assert(next_crossing == crossings.size());  // every outline found was counted
  // In a building's shadow the fog along many of the point's directions lies in the
  // shadow too and scatters no sunlight toward it (media/fog_shadowed_sunlight.h); given
  // to the points' own integrals only (the constructor).
  if (in_fog && shadowed_fog_sunlight_ && shadowed_fog_sunlight_->shaded(point, normal)) {
    const Spectrum missing = shadowed_fog_sunlight_->missing_irradiance(point, normal);
    for (int k = 0; k < kSpectralBins; ++k) irradiance[k] = std::max(0.0f, irradiance[k] - missing[k]);
  }
  // Σ w·ρ/π ≤ ρ times the hidden share of the hemisphere, below 1 for any albedo below 1;
  // the bound keeps a white room's geometric series finite.
  if (lit_as_the_point)
    for (int k = 0; k < kSpectralBins; ++k) irradiance[k] /= 1.0f - std::min(0.99f, reflected_back[k]);
  if (obstacle_distance_m)
    *obstacle_distance_m =
        weight_over_distance > 0 ? weight_sum / weight_over_distance : std::numeric_limits<double>::infinity();
  return Irradiance(irradiance);
}

double SkyLight::sky_view_factor(const Vec3& point, const Vec3& normal) const {
  const Vec3 origin = offset_from_surface(point, normal);
  double visible = 0;
  for (const SkyElement& e : elements_) {
    const double cosine = dot(normal, e.direction);
    if (cosine <= 0 || e.direction.z <= 0) continue;
    if (!tracer_.occluded(Ray{origin, e.direction})) visible += cosine * e.solid_angle;
  }
  return visible / kPi;
}

}  // namespace skylit
