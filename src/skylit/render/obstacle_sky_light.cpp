#include "skylit/render/obstacle_sky_light.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <vector>

#include "skylit/core/angles.h"
#include "skylit/sky/sky_light.h"

namespace skylit {

ObstacleSkyLight::ObstacleSkyLight(const Scene& scene, const RayTracer& tracer,
                                   const std::vector<int>& lookup_directions, Integral integral, SeesSun sees_sun,
                                   ReflectedSunAt reflected_sun)
    : scene_(scene),
      tracer_(tracer),
      integral_(std::move(integral)),
      sees_sun_(std::move(sees_sun)),
      reflected_sun_(std::move(reflected_sun)),
      patches_(lookup_directions.size()) {
  // Never 0 (an empty entry of the threads' tables) and never reused.
  static std::atomic<uint64_t> constructed{0};
  serial_ = ++constructed;
  // An element of n directions over the sphere spans about √(4π/n) radians.
  for (const int n : lookup_directions) patch_per_distance_.push_back(std::sqrt(4 * kPi / n));
  // Without levels (the obstacles lit by the open sky) no patch is ever asked for.
  if (!lookup_directions.empty())
    for (const SceneObject& object : scene_.objects) planes_.emplace_back(object.mesh);
  // TBB's maps grow only when their buckets hold four entries on average, each a node a
  // look-up walks past (the walk was half of this function's own time); at one a bucket
  // Fig. 7's tile frame took 1278 ms against 1326 (aluminium 1283 against 1294), the
  // patches' values untouched.
  for (auto& level : patches_) level.max_load_factor(1.0f);
}

size_t ObstacleSkyLight::PatchKeyHash::operator()(const PatchKey& key) const {
  uint64_t h = 0x9e3779b97f4a7c15ULL;
  auto mix = [&h](uint64_t v) {
    h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    h *= 0xff51afd7ed558ccdULL;
  };
  mix(key.mesh);
  mix(static_cast<uint32_t>(key.plane));
  mix(static_cast<uint32_t>(key.a));
  mix(static_cast<uint32_t>(key.b));
  mix(static_cast<uint8_t>(key.exponent) | (key.back ? 0x100u : 0u));
  return static_cast<size_t>(h ^ (h >> 29));
}

ObstacleSkyLight::LatticeJitter::LatticeJitter(const PlaneGroups::Plane& plane, const PatchKey& key, int level) {
  // The plane by its rounded equation (as PlaneGroups tells planes apart), not its
  // object's index: a wall cut into strips, or given as an object of its own, has the
  // same points.
  uint64_t h = PatchKeyHash{}(PatchKey{0, 0, key.a, key.b, key.exponent, key.back});
  for (const long long part : rounded_plane(plane.normal, dot(plane.normal, plane.origin)))
    h = (h ^ static_cast<uint64_t>(part)) * 0x9e3779b97f4a7c15ULL;
  state_ = h + static_cast<uint64_t>(level) + 1;  // never 0, which xorshift keeps
}

double ObstacleSkyLight::LatticeJitter::next() {
  // xorshift64*: a patch's points need only differ from its neighbours', not be good
  // random numbers.
  state_ ^= state_ >> 12;
  state_ ^= state_ << 25;
  state_ ^= state_ >> 27;
  return static_cast<double>((state_ * 0x2545f4914f6cdd1dULL) >> 11) * 0x1.0p-53;
}

namespace {
// The sun map's lattice: 8 × 8 cells of a quarter patch over [−½, 1½)² of the patch;
// the patch itself is cells 2–5 each way.
constexpr int kMapCells = 8;
constexpr double kMapCellsPerPatch = 4;
constexpr double kMapStart = -0.5;                     // in patches
constexpr int kPatchCellsFrom = 2, kPatchCellsTo = 6;  // the patch's own cells, each way
bool inside_patch(int i, int j) {
  return i >= kPatchCellsFrom && i < kPatchCellsTo && j >= kPatchCellsFrom && j < kPatchCellsTo;
}
uint64_t map_bit(int i, int j) { return uint64_t{1} << (i * kMapCells + j); }
}  // namespace

float ObstacleSkyLight::footprint_sunlit(const Patch& patch, const PlaneGroups::Plane& plane, const PatchKey& key,
                                         double side, const Ray& ray, double element_width_rad) {
  const Vec3& d = ray.direction;
  const double facing = dot(d, plane.normal);
  const double t = dot(plane.origin - ray.origin, plane.normal) / facing;
  if (!(std::abs(facing) > 1e-6 && t > 0)) return patch.sunlit;
  // The footprint on the plane, to first order in the angles: the direction d + α·across
  // + β·up meets it at the hit + α·along_across + β·along_up, each the offset's
  // projection onto the plane along d, times t.
  const Vec3 across = normalize(cross(d, std::abs(d.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0}));
  const Vec3 up = cross(d, across);
  auto on_plane_along_d = [&](const Vec3& offset) { return t * (offset - (dot(offset, plane.normal) / facing) * d); };
  const Vec3 along_across = on_plane_along_d(across), along_up = on_plane_along_d(up);
  // In the map's cells: (coordinate / side − the patch's index − start) × cells per patch.
  const Vec3 hit = ray.origin + t * d - plane.origin;
  const double scale = kMapCellsPerPatch / side;
  const double u0 = (dot(hit, plane.e1) / side - key.a - kMapStart) * kMapCellsPerPatch;
  const double v0 = (dot(hit, plane.e2) / side - key.b - kMapStart) * kMapCellsPerPatch;
  const double du_a = dot(along_across, plane.e1) * scale, dv_a = dot(along_across, plane.e2) * scale;
  const double du_b = dot(along_up, plane.e1) * scale, dv_b = dot(along_up, plane.e2) * scale;
  constexpr int kAcross = 4;
  auto cell = [](double c) { return std::clamp(static_cast<int>(std::floor(c)), 0, kMapCells - 1); };
  int on = 0, lit = 0;
  for (int a = 0; a < kAcross; ++a)
    for (int b = 0; b < kAcross; ++b) {
      const double alpha = ((a + 0.5) / kAcross - 0.5) * element_width_rad;
      const double beta = ((b + 0.5) / kAcross - 0.5) * element_width_rad;
      const uint64_t bit = map_bit(cell(u0 + alpha * du_a + beta * du_b), cell(v0 + alpha * dv_a + beta * dv_b));
      if (!(patch.on_plane & bit)) continue;
      ++on;
      lit += (patch.sees_sun & bit) ? 1 : 0;
    }
  return on > 0 ? static_cast<float>(lit) / static_cast<float>(on) : patch.sunlit;
}

std::optional<Vec3> ObstacleSkyLight::on_plane(uint32_t mesh, int32_t plane, const Vec3& point,
                                               const Vec3& normal) const {
  // A probe from just in front of the point back through it: the plane's own triangle
  // there, if any (seen as the rays see it, cut-outs and all).
  const Vec3 front = offset_from_surface(point, normal);
  const double reach = 2 * length(front - point);
  const std::optional<Hit> hit = tracer_.intersect(Ray{front, -normal, 0.0, reach});
  if (!hit || hit->mesh_id != mesh || planes_[mesh].of(hit->triangle) != plane) return std::nullopt;
  const TriangleMesh& triangles = scene_.objects[mesh].mesh;
  const auto& corners = triangles.triangles[hit->triangle];
  const Vec3 middle =
      (triangles.vertices[corners[0]] + triangles.vertices[corners[1]] + triangles.vertices[corners[2]]) / 3.0;
  const Vec3 inward = middle - point;
  const double distance = length(inward);
  return distance > 0 ? point + std::min(1e-3, distance) / distance * inward : point;
}

std::optional<ObstacleSkyLight::Patch> ObstacleSkyLight::at(int level, const Ray& ray, const Hit& hit,
                                                            double min_side_m, double element_width_rad) const {
  if (level >= levels()) return std::nullopt;
  const int32_t plane_index = planes_[hit.mesh_id].of(hit.triangle);
  if (plane_index < 0) return std::nullopt;  // a degenerate triangle (never met)
  const PlaneGroups::Plane& plane = planes_[hit.mesh_id].plane(plane_index);
  // The patch: a square of 2^exponent m, about an element's width at the hit's distance,
  // in the plane's own frame; none on a plane too small. The frame comes from the
  // plane's triangles, not the hit's normal, which Embree finds in single precision
  // (its last bits differ between the paths that meet a triangle: a packet's lane, a
  // single ray), so that a patch's points and its value do not depend on which ray met
  // it first.
  const double width = std::max({kMinPatchM, min_side_m, patch_per_distance_[static_cast<size_t>(level)] * hit.t});
  // ⌈log₂ width⌉ from the binary exponent (width = m·2^e, m in [½, 1)): std::log2 took a
  // sixth of this function's time.
  int binary_exponent = 0;
  const double mantissa = std::frexp(width, &binary_exponent);
  const int exponent = std::clamp(mantissa == 0.5 ? binary_exponent - 1 : binary_exponent, -8, 40);
  const double side = std::ldexp(1.0, exponent);
  if (plane.area_m2 < kMinAreaInPatches * side * side) return std::nullopt;
  const Vec3 offset = ray.origin + hit.t * ray.direction - plane.origin;
  // A hit lies on its plane, so its coordinates fit; the clamp only guards the cast.
  auto cell = [side](double coordinate) {
    return static_cast<int32_t>(std::clamp(std::floor(coordinate / side), -2e9, 2e9));
  };
  const bool back = dot(plane.normal, ray.direction) > 0;
  const PatchKey key{
      hit.mesh_id, plane_index, cell(dot(offset, plane.e1)), cell(dot(offset, plane.e2)), static_cast<int8_t>(exponent),
      back};
  // Near a shadow edge, the share of the element's own footprint.
  auto for_the_element = [&](const std::optional<Patch>& patch) -> std::optional<Patch> {
    if (!patch || patch->on_plane == 0 || element_width_rad <= 0) return patch;
    Patch own = *patch;
    own.sunlit = footprint_sunlit(own, plane, key, side, ray, element_width_rad);
    return own;
  };
  // Neighbouring points' integrals meet the same patches: a small table per thread of
  // the patches it met last finds most of them without walking the shared map's lists
  // (whose nodes, scattered in memory, took a third of this function's time).
  Recent& recent = recent_patches()[(PatchKeyHash{}(key) ^ static_cast<size_t>(level)) % kRecentPatches];
  if (recent.owner == serial_ && recent.level == level && recent.key == key) return for_the_element(*recent.value);
  auto& patches = patches_[static_cast<size_t>(level)];
  if (const auto found = patches.find(key); found != patches.end())
    return for_the_element(remember(recent, level, key, found->second));
  // The point at (u, v) of the patch's side in the plane.
  auto in_plane = [&](double u, double v) {
    return plane.origin + ((key.a + u) * side) * plane.e1 + ((key.b + v) * side) * plane.e2;
  };
  const Vec3 normal = back ? -plane.normal : plane.normal;
  // The points of the sun map's jittered lattice (8 × 8 cells of a quarter patch over
  // the patch and half a patch around it, a point in each at a place drawn from its
  // plane and square, LatticeJitter); those of the patch's own 4 × 4 cells that lie on
  // the plane's triangles (what the hits meet) give its sunlit share and the point the
  // value is found at (one of them, drawn below). (A 2 × 2 lattice placed a
  // sunlit wall's shadow edge only to half a patch: with the squares' edges on a
  // canyon's round coordinates, its shaded wall read 0.93 and 0.91 of the path tracer
  // at h/w 2 and 4, where 4 × 4 reads 0.99 and 0.97.)
  LatticeJitter jitter(plane, key, level);
  std::array<Vec3, kMapCells * kMapCells> map_points;
  for (int i = 0; i < kMapCells; ++i)
    for (int j = 0; j < kMapCells; ++j) {
      const double u = kMapStart + (i + jitter.next()) / kMapCellsPerPatch;
      const double v = kMapStart + (j + jitter.next()) / kMapCellsPerPatch;
      map_points[static_cast<size_t>(i * kMapCells + j)] = in_plane(u, v);
    }
  auto map_point = [&map_points](int i, int j) { return map_points[static_cast<size_t>(i * kMapCells + j)]; };
  std::vector<Vec3> lattice;
  uint64_t on_plane_bits = 0;
  for (int i = kPatchCellsFrom; i < kPatchCellsTo; ++i)
    for (int j = kPatchCellsFrom; j < kPatchCellsTo; ++j)
      if (const std::optional<Vec3> p = on_plane(hit.mesh_id, plane_index, map_point(i, j), normal)) {
        lattice.push_back(*p);
        on_plane_bits |= map_bit(i, j);
      }
  // The value's point: one of the lattice's, drawn from the patch. At its centre the patch
  // stood for its whole square with a biased value wherever the sky light bends across it
  // (a courtyard's floor and walls near their corners: the light the walls of a 20 m
  // courtyard sent each other from their own sky was 1.5–6 % short); drawn, each patch
  // errs its own way and the integrals meeting many average it out (docs/sky-light.md).
  std::optional<Vec3> point;
  if (!lattice.empty())
    point =
        lattice[std::min(lattice.size() - 1, static_cast<size_t>(jitter.next() * static_cast<double>(lattice.size())))];
  else
    point = on_plane(hit.mesh_id, plane_index, in_plane(0.5, 0.5), normal);
  if (point && lattice.empty()) lattice.push_back(*point);  // a strip across the centre alone
  // Two threads may compute the same patch at once: both get the same value (it depends
  // on the key alone), and the first to insert it keeps it.
  if (!point) return remember(recent, level, key, patches.insert({key, std::nullopt}).first->second);
  // The integral's turn (SkyLight::Turning) from the patch's square, whatever its
  // triangles: every 8 × 8 block of a plane's squares takes each of the 64 turns once, so
  // that the integrals meeting a wall average over all of them (drawn at random instead,
  // a deep canyon's foot read 0.960 or 1.032 of the path tracer by the draw,
  // docs/sky-light.md).
  static_assert(SkyLight::kTurns == 64);
  const uint64_t turn = static_cast<uint64_t>(key.a & 7) + 8 * static_cast<uint64_t>(key.b & 7);
  Patch value{integral_(level, *point, normal, turn)};
  if (sees_sun_) {
    // Over the part of the patch on the plane's triangles.
    int sunlit = 0;
    uint64_t sun_bits = 0;
    size_t k = 0;
    for (int i = kPatchCellsFrom; i < kPatchCellsTo; ++i)
      for (int j = kPatchCellsFrom; j < kPatchCellsTo; ++j)
        if (on_plane_bits & map_bit(i, j)) {
          const bool lit = sees_sun_(lattice[k++], normal);
          sunlit += lit ? 1 : 0;
          sun_bits |= lit ? map_bit(i, j) : 0;
        }
    if (k == 0) sunlit = sees_sun_(lattice.front(), normal) ? 1 : 0;  // the strip's centre
    value.sunlit = static_cast<float>(sunlit) / static_cast<float>(lattice.size());
    // A shadow edge within half a patch: one of the ring's points (on the plane beyond
    // its triangles too: the sun from there only decides whether to look closer) sees
    // the sun otherwise than the patch, or the patch is part lit. Then the map whole.
    // The ring's points are asked one in each 2 × 2 block of its cells (12 of its 48):
    // all 48 cost Fig. 7's frame about a tenth more, for the same canyon to 0.1 %.
    bool edge_near = value.sunlit > 0 && value.sunlit < 1;
    for (int i = 0; i < kMapCells && !edge_near; i += 2)
      for (int j = 0; j < kMapCells && !edge_near; j += 2)
        if (!inside_patch(i, j)) {
          const int ii = i + static_cast<int>(jitter.next() * 2), jj = j + static_cast<int>(jitter.next() * 2);
          edge_near = sees_sun_(map_point(ii, jj), normal) != (value.sunlit > 0);
        }
    if (edge_near && k > 0) {
      for (int i = 0; i < kMapCells; ++i)
        for (int j = 0; j < kMapCells; ++j) {
          if (inside_patch(i, j)) continue;
          const std::optional<Vec3> p = on_plane(hit.mesh_id, plane_index, map_point(i, j), normal);
          if (!p) continue;
          on_plane_bits |= map_bit(i, j);
          if (sees_sun_(*p, normal)) sun_bits |= map_bit(i, j);
        }
      value.on_plane = on_plane_bits;
      value.sees_sun = sun_bits;
    }
  }
  // At the first level only: the street sees the wall the facade lights; what that wall
  // sees of such walls is a bounce further and costs a patch's nodes again.
  if (reflected_sun_ && level == 0) value.reflected_sun = reflected_sun_(*point, normal);
  return for_the_element(remember(recent, level, key, patches.insert({key, value}).first->second));
}

const std::optional<ObstacleSkyLight::Patch>& ObstacleSkyLight::remember(Recent& recent, int level, const PatchKey& key,
                                                                         const std::optional<Patch>& value) const {
  recent = {serial_, level, key, &value};
  return value;
}

std::array<ObstacleSkyLight::Recent, ObstacleSkyLight::kRecentPatches>& ObstacleSkyLight::recent_patches() {
  thread_local std::array<Recent, kRecentPatches> recent{};
  return recent;
}

std::vector<size_t> ObstacleSkyLight::patch_counts() const {
  std::vector<size_t> counts;
  for (const auto& level : patches_) counts.push_back(level.size());
  return counts;
}

}  // namespace skylit
