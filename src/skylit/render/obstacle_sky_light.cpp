#include "skylit/render/obstacle_sky_light.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <vector>

#include "skylit/core/angles.h"

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
                                                            double min_side_m) const {
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
  // Neighbouring points' integrals meet the same patches: a small table per thread of
  // the patches it met last finds most of them without walking the shared map's lists
  // (whose nodes, scattered in memory, took a third of this function's time).
  Recent& recent = recent_patches()[(PatchKeyHash{}(key) ^ static_cast<size_t>(level)) % kRecentPatches];
  if (recent.owner == serial_ && recent.level == level && recent.key == key) return *recent.value;
  auto& patches = patches_[static_cast<size_t>(level)];
  if (const auto found = patches.find(key); found != patches.end()) return remember(recent, level, key, found->second);
  // The point at (u, v) of the patch's side in the plane.
  auto in_plane = [&](double u, double v) {
    return plane.origin + ((key.a + u) * side) * plane.e1 + ((key.b + v) * side) * plane.e2;
  };
  const Vec3 normal = back ? -plane.normal : plane.normal;
  // The points of a 4 × 4 lattice over the patch that lie on the plane's triangles (what
  // the hits meet); the point the value is found at: the centre, or else the first of
  // them. (A 2 × 2 lattice placed a sunlit wall's shadow edge only to half a patch: with
  // the squares' edges on a canyon's round coordinates, its shaded wall read 0.93 and
  // 0.91 of the path tracer at h/w 2 and 4, where 4 × 4 reads 0.99 and 0.97.)
  constexpr int kLattice = 4;
  std::vector<Vec3> lattice;
  for (int i = 0; i < kLattice; ++i)
    for (int j = 0; j < kLattice; ++j)
      if (const std::optional<Vec3> p =
              on_plane(hit.mesh_id, plane_index, in_plane((i + 0.5) / kLattice, (j + 0.5) / kLattice), normal))
        lattice.push_back(*p);
  std::optional<Vec3> point = on_plane(hit.mesh_id, plane_index, in_plane(0.5, 0.5), normal);
  if (!point && !lattice.empty()) point = lattice.front();
  if (point && lattice.empty()) lattice.push_back(*point);  // a strip across the centre alone
  // Two threads may compute the same patch at once: both get the same value (it depends
  // on the key alone), and the first to insert it keeps it.
  if (!point) return remember(recent, level, key, patches.insert({key, std::nullopt}).first->second);
  Patch value{integral_(level, *point, normal)};
  if (sees_sun_) {
    // Over the part of the patch on the plane's triangles.
    int sunlit = 0;
    for (const Vec3& p : lattice) sunlit += sees_sun_(p, normal) ? 1 : 0;
    value.sunlit = static_cast<float>(sunlit) / static_cast<float>(lattice.size());
  }
  // At the first level only: the street sees the wall the facade lights; what that wall
  // sees of such walls is a bounce further and costs a patch's nodes again.
  if (reflected_sun_ && level == 0) value.reflected_sun = reflected_sun_(*point, normal);
  return remember(recent, level, key, patches.insert({key, value}).first->second);
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
