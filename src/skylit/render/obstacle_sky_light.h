// The sky light on the obstacles that a surface's sky-light integral meets (issue 14,
// item 1). Where a building hides part of a point's sky, the building's own light
// comes instead (sky/sky_light.h); that light was the obstacle lit by the whole
// unobstructed sky, which credits a facade across a narrow street with the sky it
// cannot see (+17–20 % on a wall facing an 8 m gap against the path tracer). Here each
// obstacle point is lit by its own occluded sky instead, itself computed by a sky-light
// integral whose obstacles are looked up one level further on; the last level's
// integral lights its obstacles as itself (sky/sky_light.h, ObstacleLight::lit_as_the_point), which
// sums the remaining bounces as a geometric series.
//
// An integral's element stands for a patch of the obstacle as wide as the element
// seen at the hit's distance, and the sky light changes slowly along a surface, so the
// value is kept per patch and shared by every ray that meets it: a square of a power of
// two metres (at least kMinPatchM, about the element's width at the hit's distance, and
// no finer than what the image resolves where the looking integral sits) in the plane
// met (geometry/plane_groups.h: the object's triangles in that plane, however the model
// cut the surface into triangles), on the side met, evaluated at the patch's centre if
// that lies on one of the plane's triangles, else at the first point of a 4 × 4
// lattice over the patch that does (found by a short probe ray). Kept per triangle, a
// street canyon's sunlit wall cut into strips of 1 m lit the shaded wall across 7 %
// brighter, in strips of 0.1 m 18 % dimmer, than the same wall of two triangles. It
// depends on the patch alone, not on which ray met it first, so the image is the same
// whatever the threads and their order.
//
// A plane smaller than a quarter of its patch (a window frame, a reveal, a facet of a
// detailed model seen from afar) has none, nor a patch neither whose centre nor any of
// whose lattice points lies on the plane's triangles (a corner of it over a wall's
// window): one of many small parts, and a patch for each would cost a quadrature per
// part; the integral that meets it lights it as itself, as past the last level
// (sky/sky_light.h, ObstacleLight::lit_as_the_point).
//
// The sun's visibility is kept per patch too, as the share of the lattice's points on
// the plane's triangles that see the sun (what the hits meet; points clamped onto a
// triangle's edges instead made a street canyon's shaded wall 2 % brighter against the
// path tracer; a shadow ray per hit was 9 % of Fig. 7's frame). The lattice is jittered
// (each point at a place in its cell drawn from the patch's plane and square): at its
// cells' centres it missed a shadow edge within an eighth of a patch of its side on
// every patch along a straight edge alike, and a 5 m wide canyon's shaded wall read 3.8 %
// brighter than the path tracer where a 12 m one held. Where a shadow edge passes within
// half a patch (found on a ring of 12 points around it), the sun is kept as a map of 8 × 8 points over the patch and
// half a patch around it, and an element that meets the patch takes the share of its own footprint on the plane in that
// map (`at`'s element width): the patch's mean stood for every element that met it wherever on it, and a thin sunlit
// band at the top of a deep canyon's wall, a fraction of an element high, was met by a few element centres or none
// (docs/sky-light.md, "At other widths"). The sunlight's strength (the air, fog and cloud shadows above the point, all
// smooth) stays the hit's own.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <tbb/concurrent_unordered_map.h>

#include "skylit/geometry/plane_groups.h"
#include "skylit/geometry/ray_tracer.h"
#include "skylit/scene/scene.h"
#include "skylit/spectrum/radiometry.h"

namespace skylit {

class ObstacleSkyLight {
 public:
  // The diffuse sky irradiance (W m⁻² nm⁻¹) at `point` on a surface facing `normal`,
  // from the sky-light integral of `level`, whose obstacles are lit through level + 1;
  // with its directions turned by `turn`, chosen by the patch (SkyLight::Turning).
  using Integral = std::function<Irradiance(int level, const Vec3& point, const Vec3& normal, uint64_t turn)>;
  // Whether the sun shines on `point`, on a surface facing `normal` (nothing in the way).
  using SeesSun = std::function<bool(const Vec3& point, const Vec3& normal)>;

  // The sunlight that glass and metal facades reflect onto `point` (render/reflected_sun.h).
  using ReflectedSunAt = std::function<Irradiance(const Vec3& point, const Vec3& normal)>;

  // A patch's light: its sky irradiance, the share of it the sun reaches, and the
  // sunlight facades reflect onto it (level 0 only: a wall across a street from an
  // aluminium facade, lit by its reflection, lights the street in turn).
  struct Patch {
    Irradiance sky;
    float sunlit = 1;
    Irradiance reflected_sun{0.0f};
    // Near a shadow edge: bit 8i + j for the point of cell (i, j) of the 8 × 8 lattice
    // over the patch and half a patch around it (cells of a quarter patch, i along e1),
    // whether it lies on the plane's triangles, and whether it sees the sun. None
    // elsewhere (on_plane 0).
    uint64_t on_plane = 0, sees_sun = 0;
  };

  // `lookup_directions[level]`: the number of directions of the integrals that look up
  // that level (the patch is about as wide as one of their elements); `integral` computes
  // a patch's value, `sees_sun` its sunlit share (all of it if not given); `tracer`
  // holds the scene's objects (mesh ids = object indices) for the probes. Holds
  // references to `scene` and `tracer`.
  ObstacleSkyLight(const Scene& scene, const RayTracer& tracer, const std::vector<int>& lookup_directions,
                   Integral integral, SeesSun sees_sun = {}, ReflectedSunAt reflected_sun = {});

  int levels() const { return static_cast<int>(patch_per_distance_.size()); }

  // The sky irradiance on the obstacle that `ray` meets at `hit`, on the side facing the
  // ray's origin, from `level`'s integral; none past the last level or on a plane too
  // small for a patch of its own.
  // `min_side_m`: no patch smaller than this (what the image resolves where the ray
  // starts).
  // `element_width_rad`: the width of the element `ray` stands for; near a shadow edge
  // the patch's `sunlit` is then the share of the element's footprint (0: the patch's).
  std::optional<Patch> at(int level, const Ray& ray, const Hit& hit, double min_side_m = 0,
                          double element_width_rad = 0) const;

  // The smallest patch's side, m: finer than the sky light on a facade changes near its
  // foot, where a street's floor and walls meet.
  static constexpr double kMinPatchM = 0.5;
  // A plane has patches of its own if its triangles' area is at least this many patches'.
  static constexpr double kMinAreaInPatches = 0.25;

  // How many patches have been computed, at each level (for tests and benchmarks).
  std::vector<size_t> patch_counts() const;

 private:
  struct PatchKey {
    uint32_t mesh;
    int32_t plane;    // PlaneGroups' index
    int32_t a, b;     // the patch's square in the plane's frame (e1, e2)
    int8_t exponent;  // its side is 2^exponent m
    bool back;        // met on the side the geometric normal points away from
    bool operator==(const PatchKey&) const = default;
  };
  struct PatchKeyHash {
    size_t operator()(const PatchKey& key) const;
  };

  // Where the plane's triangles are at `point` (in the plane), seen from the side
  // `normal` faces: the point drawn 1 mm toward the middle of the triangle found there
  // (off the edges it shares), or none if no triangle of the plane is there.
  std::optional<Vec3> on_plane(uint32_t mesh, int32_t plane, const Vec3& point, const Vec3& normal) const;

  // The places of a patch's lattice points within their cells, drawn from its plane,
  // square and level alone, so that the patch does not depend on which ray met it first,
  // nor on which object the plane belongs to.
  class LatticeJitter {
   public:
    LatticeJitter(const PlaneGroups::Plane& plane, const PatchKey& key, int level);
    double next();  // in [0, 1)

   private:
    uint64_t state_;
  };

  // The share of the sun map of `patch` (found near a shadow edge) over the footprint of
  // an element `element_width_rad` wide about `ray` on the plane: 4 × 4 directions
  // across the element, met with the plane, each taking the map's cell it falls in
  // (clamped to the map); those on no triangle of the plane left out.
  static float footprint_sunlit(const Patch& patch, const PlaneGroups::Plane& plane, const PatchKey& key, double side,
                                const Ray& ray, double element_width_rad);

  // A thread's table of the patches it met last (`at`): where a key's value is in
  // patches_ (whose elements never move).
  struct Recent {
    uint64_t owner = 0;  // the ObstacleSkyLight's serial_ (0: empty)
    int level = 0;
    PatchKey key{};
    const std::optional<Patch>* value = nullptr;
  };
  static constexpr size_t kRecentPatches = 4096;
  static std::array<Recent, kRecentPatches>& recent_patches();
  const std::optional<Patch>& remember(Recent& recent, int level, const PatchKey& key,
                                       const std::optional<Patch>& value) const;

  const Scene& scene_;
  const RayTracer& tracer_;
  uint64_t serial_ = 0;                     // this object's, unique: the threads' tables tell objects apart by it
  std::vector<PlaneGroups> planes_;         // per object
  std::vector<double> patch_per_distance_;  // per level: an element's width, radians
  Integral integral_;
  SeesSun sees_sun_;
  ReflectedSunAt reflected_sun_;
  // None for a patch none of whose points lies on its plane's triangles.
  mutable std::vector<tbb::concurrent_unordered_map<PatchKey, std::optional<Patch>, PatchKeyHash>> patches_;
};

}  // namespace skylit
