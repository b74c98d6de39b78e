// An indexed triangle mesh in world (or object) coordinates: the form every
// geometry source (primitives, OBJ, glTF) is turned into before ray tracing.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include "skylit/core/vec3.h"

namespace skylit {

// An axis-aligned box; empty (lo > hi) until a point is added.
struct BoundingBox {
  Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity()};
  Vec3 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity()};

  bool empty() const { return lo.x > hi.x; }
  void add(const Vec3& p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  void add(const BoundingBox& b) {
    if (!b.empty()) add(b.lo), add(b.hi);
  }
  Vec3 center() const { return 0.5 * (lo + hi); }
  Vec3 size() const { return hi - lo; }
};

// Texture coordinates (u, v) at a triangle's three corners: u to the right, v down from
// the image's top row (glTF's convention; OBJ's v is turned over when read).
using CornerUvs = std::array<std::array<float, 2>, 3>;

struct TriangleMesh {
  std::vector<Vec3> vertices;
  // Indices into `vertices`; counter-clockwise seen from the outside (the side the
  // geometric normal cross(v1 - v0, v2 - v0) points to).
  std::vector<std::array<uint32_t, 3>> triangles;

  bool empty() const { return triangles.empty(); }

  // The box around the vertices that triangles use.
  BoundingBox bounds() const {
    BoundingBox box;
    for (const auto& t : triangles)
      for (uint32_t i : t) box.add(vertices[i]);
    return box;
  }

  // Adds `other`'s vertices and triangles, re-indexing its triangles.
  void append(const TriangleMesh& other) {
    // Indices are 32-bit because Embree takes 32-bit indices; refuse to wrap.
    if (vertices.size() + other.vertices.size() > std::numeric_limits<uint32_t>::max())
      throw std::length_error("TriangleMesh::append: more than 2^32-1 vertices");
    const auto offset = static_cast<uint32_t>(vertices.size());
    vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
    // No exact reserve here: called once per object of a city model (83,000 times for a
    // PLATEAU tile), it would reallocate every time and copy quadratically (42 s).
    for (const auto& t : other.triangles) triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
};

}  // namespace skylit
