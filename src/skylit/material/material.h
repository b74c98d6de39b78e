// Surface materials: what a scene's `materials` give (docs/materials.md).
//
// - DiffuseMaterial: Lambertian (the scene type `diffuse`).
// - CookTorranceMaterial: a rough interface with the Cook & Torrance (1982) specular
//   lobe and spectral Fresnel reflectance: a metal, or a dielectric coat over an
//   optional Lambertian base (scene types `cook_torrance` and `layered`).
// - GlassMaterial: a window pane with the dark room behind it (scene type `glass`).
// - RoadMaterial: a dry road by the CIE r-tables (scene type `road`; road_reflection.h).
//
// What the renderer needs from them is in reflection.h; the classes precompute
// their Fresnel tables once, so copies share them and shading stays cheap.
#pragma once

#include <memory>
#include <string>
#include <variant>

#include "skylit/material/angular_table.h"
#include "skylit/material/optical_constants.h"
#include "skylit/material/road_reflection.h"
#include "skylit/spectrum/spectrum.h"

namespace skylit {

// Below this rms slope a lobe is treated as a mirror: the renderer traces one
// reflected ray (reflection.h, mirror_reflectance). At m = 0.001 the lobe's radius
// (D down to 1e-3 of its peak) is 0.3°, about the sun's angular radius (0.27°), so
// nothing in a sky would look different through a narrower lobe.
inline constexpr double kMirrorRoughness = 0.001;

// A Lambertian reflector: radiance = reflectance / π × irradiance.
struct DiffuseMaterial {
  Spectrum reflectance;  // hemispherical reflectance per bin, in [0, 1]
};

// Specular: f_s = D G F(v·h) / (4 (n·l)(n·v)) (microfacet.h) with F from `ior`.
// Diffuse (only for a dielectric `ior`): a Lambertian body under the coat. Light
// crosses the coat twice and bounces between body and coat; with radiance scaling by
// 1/η² across the interface and the geometric series of inner bounces, a body of
// reflectance ρ gives
//   albedo(θ_v) = ρ (1 − F̄) (1 − F(θ_v)) / (η² (1 − ρ F̄_in)),
// F̄ = 2∫F(μ)μ dμ the coat's hemispherical reflectance from outside and
// F̄_in = 1 − (1 − F̄)/η² from inside (total internal reflection included). The same
// model as Mitsuba's `plastic` and `roughplastic` (W. Jakob, Mitsuba renderer
// documentation); for a rough coat the Fresnel factors are the smooth coat's, as
// there. Its angular shape is K (1 − F(θ_v)); ρ only sets K. So the material takes
// what can be measured, the diffuse reflectance A at normal view with the specular
// part excluded (a spectrophotometer's d:8° "specular excluded" reading), and uses
// K = A / (1 − F(0)). A body with ρ ≤ 1 gives A ≤ 1 − F(0) (ρ = 1: A = 1 − F(0),
// and then albedo(θ_v) = 1 − F(θ_v), exactly what the smooth coat does not reflect);
// larger A are taken as 1 − F(0). The light side uses F̄ (the mean over incidence)
// so that the renderer can multiply by irradiance.
class CookTorranceMaterial {
 public:
  // roughness: Beckmann rms slope m ≥ 0 (below kMirrorRoughness a mirror).
  // diffuse_reflectance: A above, per bin; must be black when ior is a conductor
  // (throws std::invalid_argument otherwise: light does not pass through a metal).
  CookTorranceMaterial(const ComplexIor& ior, double roughness, const Spectrum& diffuse_reflectance = Spectrum());

  const ComplexIor& ior() const { return ior_; }
  double roughness() const { return roughness_; }
  // A, as given (before limiting to 1 − F(0)).
  const Spectrum& diffuse_reflectance() const { return diffuse_reflectance_; }
  bool has_diffuse() const { return has_diffuse_; }
  bool is_mirror() const { return roughness_ < kMirrorRoughness; }

  // The same coat over a body of another colour (a texel's), sharing the Fresnel
  // table; a material without a body (a metal) is returned unchanged.
  CookTorranceMaterial with_diffuse_reflectance(const Spectrum& diffuse_reflectance) const;

  // F(cos θ) of the interface.
  const AngularTable& fresnel() const { return *fresnel_; }
  // K = min(A, 1 − F(0)) / (1 − F(0)): the diffuse albedo is K (1 − F(θ_v)).
  const Spectrum& diffuse_factor() const { return diffuse_factor_; }

 private:
  ComplexIor ior_;
  double roughness_;
  Spectrum diffuse_reflectance_;
  bool has_diffuse_;  // asked for every sample: kept rather than recomputed
  std::shared_ptr<const AngularTable> fresnel_;
  Spectrum diffuse_factor_;

  void set_diffuse_factor();
};

// A window pane of thickness d in air: reflectance R(θ) of its two surfaces with the
// light bouncing inside and the glass's absorption (fresnel.h, pane_optics); a mirror
// unless given a roughness. Behind it the room, seen as a Lambertian of reflectance
// ρ_room lit through the pane: albedo(θ_v) = ρ_room T̄ T(θ_v), T(θ) the pane's
// transmittance and T̄ = 2∫T(μ)μ dμ its mean over the hemisphere of incidence.
// ρ_room is the room's effective reflectance as a cavity (docs/materials.md).
class GlassMaterial {
 public:
  GlassMaterial(const ComplexIor& ior, double thickness_m, double roughness, const Spectrum& interior_reflectance);

  const ComplexIor& ior() const { return ior_; }
  double thickness_m() const { return thickness_m_; }
  double roughness() const { return roughness_; }
  const Spectrum& interior_reflectance() const { return interior_reflectance_; }
  bool is_mirror() const { return roughness_ < kMirrorRoughness; }

  const AngularTable& reflectance() const { return *reflectance_; }
  const AngularTable& transmittance() const { return *transmittance_; }
  // ρ_room T̄: the room's albedo before the factor T(θ_v).
  const Spectrum& interior_albedo_factor() const { return interior_albedo_factor_; }

 private:
  ComplexIor ior_;
  double thickness_m_;
  double roughness_;
  Spectrum interior_reflectance_;
  std::shared_ptr<const AngularTable> reflectance_;
  std::shared_ptr<const AngularTable> transmittance_;
  Spectrum interior_albedo_factor_;
};

using Material = std::variant<DiffuseMaterial, CookTorranceMaterial, GlassMaterial, RoadMaterial>;

struct SurfaceAppearance;  // surface_appearance.h

struct NamedMaterial {
  std::string name;
  Material material;
  // What varies over the surface or shines (textures, emission); null for neither.
  std::shared_ptr<const SurfaceAppearance> appearance{};
};

}  // namespace skylit
