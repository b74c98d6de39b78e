// The fog's light that a surface hides from the fog in front of it (issue 13, docs/fog.md
// "The fog in front of a surface").
//
// The multiply scattered field (media/fog_diffuse_field.h) is that of an open, level
// layer: at a point of a view ray, light arrives from every direction. In front of a
// surface, the light that would travel toward the point from behind the surface's plane
// is not the open layer's: it is the surface's own. For a point at height h above the
// plane, light travelling along ω (ω·n > 0, n the surface's normal) left the plane
// h/(ω·n) back, so the surface changes it by
//     e^(−σ_tr·h/(ω·n))·(L_surface − L_field(ω)).
// σ_tr = (1 − ωg)·σ, the similarity relation's extinction (van de Hulst), not the δ-M
// one (1 − ωf)·σ: the difference is itself scattered, mostly forward by p', so it
// spreads in angle but persists over a transport length, not a δ-M mean free path (in
// front of a black wall under a sunlit droplet fog the δ-M length left the fog 2.3 times
// the reference at 40 m, the transport length 1.6 times; docs/fog.md). Scattered toward
// the viewer by (1 − f)·p' (the spike's f is FogMedium::Along::forward_gain) and gathered
// along the view, with h = s·(u·n) at a distance s before the surface (u toward the
// viewer):
//     ΔL = Σ_ω (1 − f)·p'(ω·u)·dω·W(ω)·(L_surface − L_field(ω)),
//     W(ω) = ωσ·∫_0^S T(viewer, s)·e^(−σ_tr·s·(u·n)/(ω·n)) ds
// in closed form with the fog's density at the surface: T(viewer, s) = T(viewer,
// surface)·e^(σs) for s up to the optical depth to the viewer, T(viewer, surface) left to
// the caller. The surface is a disc of the radius R it extends to about the point
// (measured by the caller): along ω, the plane point the light leaves from lies
// s·|u_t − (u·n)/(ω·n)·ω_t| from the point (t: the parts along the plane), so s stops
// where that reaches R. A small target hides little more than the light along the view
// itself (the spike's). The field at the surface's altitude stands for the field where
// the light leaves the plane. The surface's own light toward ω is what it leaves alike
// toward every direction (the caller's: not the sun's highlight nor a mirror's view).
//
// In a building's shadow FogMedium has already taken the field's light from the sun's
// side out of the view (FogDiffuseField::sun_side_terms); there only the surface's own
// light comes back from those directions.
#pragma once

#include <array>
#include <vector>

#include "skylit/core/vec3.h"
#include "skylit/media/fog_diffuse_field.h"
#include "skylit/media/fog_layer.h"
#include "skylit/spectrum/radiometry.h"

namespace skylit {

// How deep in the fog (optical depth from the viewer) the hidden light is held without
// the fog's transmittance T to the viewer; deeper, with T's part beyond this depth.
// Within a few optical depths of the viewer, what a surface hides lies mostly just in
// front of it and is seen through T, so values held without T interpolate between
// points at different depths. Deeper, most of it lies far in front of the surface, nearer
// the viewer (the surface's mark on the field fades over a transport length, about seven
// extinction lengths in droplet fog), so it falls with depth far more slowly than T:
// held without T, it was T(viewer, surface)⁻¹ times too large, up to e^30, and a pixel
// nearer than the cache corners it took this from (a ground plane near the horizon seen
// from beside a small building) multiplied that by its own larger T: saturated red and
// green blotches of 30–75 kcd/m² along a foggy horizon. A point's own value is the same
// either way: T' = max(T, e^(−kHiddenHeldDepth)) undoes exactly what `at` holds back.
inline constexpr double kHiddenHeldDepth = 2.0;

// What the caller multiplies FogHiddenBehind by: the fog's transmittance T from the
// surface to the viewer, per bin no less than e^(−kHiddenHeldDepth).
Transmittance hidden_light_transmittance(const Transmittance& fog_to_viewer);

// What the camera sees more of a surface leaving radiance L through the fog in front of
// it: (L·gain − field)·T', field the open field's light from behind the surface's plane:
// all of it, or where the fog in front of the surface lies in a shadow of the sun, the
// part from outside the sun's side (the view has lost the rest already). T' =
// hidden_light_transmittance(T), T the fog's transmittance from the surface to the viewer
// (the caller's: held without it, these interpolate across a surface seen over a range
// of depths; see kHiddenHeldDepth).
struct FogHiddenBehind {
  Transmittance gain{0.0f};
  Radiance field{0.0f};
  Radiance field_in_shadow{0.0f};
  const Radiance& field_for(bool fog_in_shadow) const { return fog_in_shadow ? field_in_shadow : field; }
};

class FogBehindSurfaces {
 public:
  // `sunbeam`: the sun's direction of travel (toward the ground); its horizontal part is
  // the field's azimuth 0.
  // Both referred to, not copied.
  FogBehindSurfaces(const FogLayer& layer, const FogDiffuseField& field, const Vec3& sunbeam);

  // At a surface `point` with `normal`, seen from `toward_viewer` (unit, u·n > 0) through
  // a fog column `column_to_viewer_m` (∫ρ ds from the viewer) of which `length_in_fog_m`
  // lies in the layer; `extent_m`: how far the surface reaches about the point.
  FogHiddenBehind at(const Vec3& point, const Vec3& normal, const Vec3& toward_viewer, double column_to_viewer_m,
                     double length_in_fog_m, double extent_m) const;

  // Quadrature about the view: rings in the angle from u, directions around each ring.
  static constexpr int kRings = 16, kAround = 16;
  // The field's radiance tabulated at each level by elevation and azimuth.
  static constexpr int kElevations = 46, kAzimuths = 37;

 private:
  Spectrum field_radiance(FogDiffuseField::LevelWeight level, const Vec3& direction) const;

  const FogLayer& layer_;
  const FogDiffuseField& field_;
  double albedo_;           // ω
  double transport_scale_;  // 1 − ωg: σ_tr/σ
  Vec3 sunbeam_, sun_horizontal_;
  int reference_bin_;  // σ's bin for the shape of W (the fog is nearly grey)
  struct Ring {
    double cos_angle, sin_angle, weight;  // weight: (1 − f)·p'·dω of one direction
  };
  std::array<Ring, kRings> rings_{};
  std::array<double, kAround> around_cos_{}, around_sin_{};
  std::vector<Spectrum> radiance_;  // [level][elevation][azimuth]
};

}  // namespace skylit
