#include "skylit/render/obstacle_sky_light.h"

#include <algorithm>
#include <cmath>

#include "skylit/core/angles.h"

namespace skylit {

Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& v0, const Vec3& v1, const Vec3& v2) {
  // Which of the triangle's seven Voronoi regions (three corners, three edges, the face)
  // holds p, from the signs of the edge projections.
  const Vec3 ab = v1 - v0, ac = v2 - v0, ap = p - v0;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return v0;
  const Vec3 bp = p - v1;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return v1;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return v0 + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - v2;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return v2;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return v0 + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return v1 + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (v2 - v1);
  const double denominator = va + vb + vc;
  if (!(denominator > 0)) return v0;  // a degenerate triangle
  return v0 + (vb / denominator) * ab + (vc / denominator) * ac;
}

ObstacleSkyLight::ObstacleSkyLight(const Scene& scene, const std::vector<int>& lookup_directions, Integral integral,
                                   SeesSun sees_sun)
    : scene_(scene),
      integral_(std::move(integral)),
      sees_sun_(std::move(sees_sun)),
      patches_(lookup_directions.size()) {
  // An element of n directions over the sphere spans about √(4π/n) radians.
  for (const int n : lookup_directions) patch_per_distance_.push_back(std::sqrt(4 * kPi / n));
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
  mix(key.triangle);
  mix(static_cast<uint32_t>(key.a));
  mix(static_cast<uint32_t>(key.b));
  mix(static_cast<uint8_t>(key.exponent) | (key.back ? 0x100u : 0u));
  return static_cast<size_t>(h ^ (h >> 29));
}

std::optional<ObstacleSkyLight::Patch> ObstacleSkyLight::at(int level, const Ray& ray, const Hit& hit,
                                                            double min_side_m) const {
  if (level >= levels()) return std::nullopt;
  // The patch: a square of 2^exponent m, about an element's width at the hit's distance,
  // in the triangle's own frame (e1 along its first edge); none on a triangle too small.
  const double width = std::max({kMinPatchM, min_side_m, patch_per_distance_[static_cast<size_t>(level)] * hit.t});
  const int exponent = std::clamp(static_cast<int>(std::ceil(std::log2(width))), -8, 40);
  const double side = std::ldexp(1.0, exponent);
  const TriangleMesh& mesh = scene_.objects[hit.mesh_id].mesh;
  const auto& corners = mesh.triangles[hit.triangle];
  const Vec3 &v0 = mesh.vertices[corners[0]], &v1 = mesh.vertices[corners[1]], &v2 = mesh.vertices[corners[2]];
  const Vec3 area_vector = cross(v1 - v0, v2 - v0);
  const double twice_area = length(area_vector);
  if (0.5 * twice_area < kMinAreaInPatches * side * side) return std::nullopt;
  // The triangle's frame from its corners, not from the hit's normal: Embree finds that
  // normal in single precision, and its last bits differ between the paths that meet a
  // triangle (a packet's lane, a single ray), so a patch's point and normal, and so its
  // value, depended on which ray met it first (images differed in the last bits with the
  // threads' timing). The same direction as the hit's (Embree's Ng is this cross product).
  const Vec3 face = area_vector / twice_area;
  const Vec3 e1 = normalize(v1 - v0);
  const Vec3 e2 = cross(face, e1);
  const Vec3 offset = ray.origin + hit.t * ray.direction - v0;
  // A hit lies on its triangle, so its coordinates fit; the clamp only guards the cast.
  auto cell = [side](double coordinate) {
    return static_cast<int32_t>(std::clamp(std::floor(coordinate / side), -2e9, 2e9));
  };
  const bool back = dot(face, ray.direction) > 0;
  const PatchKey key{
      hit.mesh_id, hit.triangle, cell(dot(offset, e1)), cell(dot(offset, e2)), static_cast<int8_t>(exponent), back};
  auto& patches = patches_[static_cast<size_t>(level)];
  if (const auto found = patches.find(key); found != patches.end()) return found->second;
  // The point at (u, v) of the patch's side in the triangle's plane; a point of the
  // triangle drawn 1 mm toward its inside, so that it lies within the face rather than on
  // an edge shared with another.
  auto in_plane = [&](double u, double v) { return v0 + ((key.a + u) * side) * e1 + ((key.b + v) * side) * e2; };
  auto drawn_inward = [&](const Vec3& on_triangle) {
    const Vec3 inward = (v0 + v1 + v2) / 3.0 - on_triangle;
    const double distance = length(inward);
    return distance > 0 ? on_triangle + std::min(1e-3, distance) / distance * inward : on_triangle;
  };
  const Vec3 normal = back ? -face : face;
  // Two threads may compute the same patch at once: both get the same value (it depends
  // on the key alone), and the first to insert it keeps it.
  const Vec3 centre = drawn_inward(closest_point_on_triangle(in_plane(0.5, 0.5), v0, v1, v2));
  Patch value{integral_(level, centre, normal)};
  if (sees_sun_) {
    // Over the part of the patch that lies on the triangle (what the hits meet); the
    // centre where none of the lattice does.
    int sunlit = 0, on_triangle = 0;
    for (const double u : {0.25, 0.75})
      for (const double v : {0.25, 0.75}) {
        const Vec3 point = in_plane(u, v), nearest = closest_point_on_triangle(point, v0, v1, v2);
        if (length(nearest - point) > 1e-6 * side) continue;
        ++on_triangle;
        sunlit += sees_sun_(drawn_inward(nearest), normal) ? 1 : 0;
      }
    if (on_triangle == 0) {
      on_triangle = 1;
      sunlit = sees_sun_(centre, normal) ? 1 : 0;
    }
    value.sunlit = static_cast<float>(sunlit) / static_cast<float>(on_triangle);
  }
  return patches.insert({key, value}).first->second;
}

std::vector<size_t> ObstacleSkyLight::patch_counts() const {
  std::vector<size_t> counts;
  for (const auto& level : patches_) counts.push_back(level.size());
  return counts;
}

}  // namespace skylit
