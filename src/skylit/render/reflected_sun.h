// Sunlight that glass and metal facades reflect onto other surfaces, without noise
// (docs/reflected-sun.md).
//
// The scene's specular triangles are merged into facet groups: the triangles of one
// material that lie in one plane. The sun reflected by a group comes from its side that
// faces the sun, in the directions its lobe sends the sun's direction s to. For a
// mirror (glass, a polished metal) that is one direction: the image sun, s mirrored in
// the plane, a second sun seen through the facet. A point P receives it when the ray
// from P toward the image sun meets the group (exact visibility, triangle by triangle)
// at a point Q that the sun reaches, and then gets
//   E = R(θ_s) E_sun(Q) cos θ_P,
// R the facet's spectral Fresnel reflectance at the sun's incidence. For a rough lobe
// (Cook–Torrance, Beckmann slope m) the image sun is widened into the lobe: a fixed
// set of nodes, stratified in the Beckmann distribution of half vectors (the midpoint
// of equal shares of its cumulative distribution), each a direction ω_k with the weight
// f_s(s, −ω_k)(n·s) / (N p(ω_k)), p the density those half vectors give the reflected
// direction; P then sums the nodes whose rays meet the group where the sun reaches it:
//   E = Σ_k w_k E_sun(Q_k) max(0, n_P·ω_k).
// The directions depend only on the plane's orientation and material, so the groups that
// share both (the windows of one facade, or of a whole street's facades facing one way)
// form one orientation class: a point sends one ray per node of each class, whichever of
// the class's groups it meets, instead of one per group (a city of a thousand windows
// in four orientations costs four rays a pixel, not a thousand).
// The nodes are the same for every point, so the result is deterministic and smooth.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "skylit/geometry/ray_tracer.h"
#include "skylit/material/material.h"
#include "skylit/render/cone_tree.h"
#include "skylit/render/surface_point.h"
#include "skylit/scene/scene.h"
#include "skylit/spectrum/radiometry.h"

namespace skylit {

// Rough lobes' quadrature: rings in the cumulative distribution of the half vector's
// tilt times azimuths. docs/reflected-sun.md gives its error against a dense grid.
inline constexpr int kLobeRings = 6, kLobeAzimuths = 12;

// Lobes at least this rough (Beckmann m; glTF's roughness 0.71) are left to the sky-light
// integral, whose rays meeting such a surface take the sun it reflects toward them
// (BandsIntegrator::obstacle_radiance): a lobe this wide (its half vectors spread over
// some 30°, its reflection over 60° and more) is smooth over the integral's elements
// (6° with 1,024 directions), and the node rays grew with the orientation classes: a
// curved glTF model of default roughness 1 had one class per triangle, 72 rays each
// (docs/reflected-sun.md, "Broad lobes").
inline constexpr double kBroadLobeRoughness = 0.5;
// Whether a material's glossy lobe (metal, coat or frosted glass) is that broad: its
// reflected sun is the sky-light integral's, not ReflectedSun's.
bool is_broad_lobe(const Material& material);

class ReflectedSun {
 public:
  // The sun's direct normal irradiance at a point of a facet with this normal, 0 where
  // the facet is in shadow (the renderer's own sun test).
  using SunAt = std::function<Irradiance(const Vec3& position, const Vec3& normal)>;

  // Finds the facet groups of `scene`'s objects (mesh ids = object indices in `tracer`)
  // lit by the sun from direction `to_sun`.
  ReflectedSun(const Scene& scene, const RayTracer& tracer, const Vec3& to_sun, SunAt sun_at);

  // The reflected sun's irradiance on a surface point, on the side of its normal: from
  // the mirror groups, or from the rough ones.
  Irradiance from_mirrors(const Vec3& position, const Vec3& normal) const { return from(position, normal, true); }
  Irradiance from_rough(const Vec3& position, const Vec3& normal) const { return from(position, normal, false); }

  bool has_mirrors() const { return has_mirrors_; }
  bool has_rough() const { return has_rough_; }
  int group_count() const { return static_cast<int>(groups_.size()); }

 private:
  struct Node {
    Vec3 toward;      // from the lit point toward the facet (unit)
    Spectrum weight;  // what multiplies E_sun(Q) cos θ_P
  };
  struct Group {
    Vec3 normal;        // on the side the sun lights
    double offset = 0;  // normal · x on the plane
  };
  // The groups of one material and orientation: the same nodes, one box around them all.
  struct OrientationClass {
    Vec3 normal;  // on the side the sun lights
    BoundingBox box;
    bool mirror = false;
    std::vector<Node> nodes;
  };

  Irradiance from(const Vec3& position, const Vec3& normal, bool mirrors) const;
  void add_nodes(OrientationClass& orientation, const Material& material) const;

  const RayTracer& tracer_;
  Vec3 to_sun_;
  SunAt sun_at_;
  std::vector<Group> groups_;
  std::vector<OrientationClass> classes_;
  // The classes with nodes, mirrors and rough apart, and their trees of boxes and the
  // cones that hold their nodes' directions (items by the same indices): a class whose
  // box lies outside its cone, seen from a point, is passed over with one test instead
  // of one per node, and neighbouring classes of a curved model together
  // (render/cone_tree.h).
  std::vector<int32_t> mirror_classes_, rough_classes_;
  ConeTree mirror_tree_, rough_tree_;
  std::vector<int32_t> class_of_group_;
  // Per object, the group of each triangle (−1: none); empty for objects without any.
  std::vector<std::vector<int32_t>> triangle_group_;
  bool has_mirrors_ = false, has_rough_ = false;
};

}  // namespace skylit
