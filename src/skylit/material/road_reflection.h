// Dry road surfaces as road-lighting design describes them: the CIE standard
// reduced-luminance-coefficient tables r(β, tan γ) (CIE 144:2001, CIE 030.2-1982;
// data/road_r_tables.csv and data/SOURCES.md), scaled by the surface's average
// luminance coefficient Q0. docs/road-lighting.md gives the definitions and limits.
//
// The angles, at a point P of the road with normal n, lamp direction l and view v:
//   γ: the light's angle of incidence (cos γ = n·l), tan γ = horizontal distance
//      from the lamp's foot to P over the lamp's height;
//   β: the angle between the vertical plane through the lamp and P and the one
//      through the observer and P, 0 when the lamp stands beyond P as the observer
//      looks (cos β = −l⊥·v⊥, ⊥ the parts parallel to the road);
//   α: the view's elevation above the road (sin α = n·v).
// The luminance coefficient q = L/E (sr⁻¹, E the illuminance on the road) is
// q = r / cos³ γ, so under one lamp of intensity I at height h, L = I r / h²
// (EN 13201-3). q is the road's BRDF for that view.
//
// The tables describe a view at α = 1° (CIE 144 holds them valid for 0.5°–1.5°).
// For steeper views the surface is taken as turning diffuse: the BRDF is
//   f = w(α) q_table + (1 − w(α)) Q0,  w = 1 up to α = 1.5°, linear to 0 at 20°,
// a stated assumption (measurements at 1°–10°, Muzet et al., show S1 and Q0 falling
// with α), not a measured model; see docs/road-lighting.md.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "skylit/core/vec3.h"

namespace skylit {

class RoadReflectionTable {
 public:
  // The standard table of a class: R1, R2, R3, R4, C1 or C2; nullptr for other names.
  static std::shared_ptr<const RoadReflectionTable> standard(std::string_view name);
  // The class names known, for messages: "R1, R2, …".
  static std::string standard_names();

  const std::string& name() const { return name_; }
  // The class's nominal average luminance coefficient (CIE 144 Table 2), sr⁻¹.
  double nominal_q0() const { return nominal_q0_; }
  // The specular factor S1 = r(0, 2) / r(0, 0).
  double specular_factor() const { return at(0, 2) / at(0, 0); }

  // r(β, tan γ), sr⁻¹ (the table's values × 10⁻⁴), bilinear between the tabulated
  // points; β is folded into [0°, 180°] (the tables are symmetric about β = 0). Cells
  // the standard leaves empty (steep β at grazing incidence) and tan γ beyond 12
  // count as 0: light from there lies outside the domain over which the tables were
  // measured and Q0 is defined.
  double at(double beta_deg, double tan_gamma) const;

  // The tabulated axes, for tests and quadratures.
  const std::vector<double>& tan_gammas() const { return tan_gammas_; }
  const std::vector<double>& betas_deg() const { return betas_deg_; }

  RoadReflectionTable(std::string name, double nominal_q0, std::vector<double> tan_gammas,
                      std::vector<double> betas_deg, std::vector<double> r_values);

 private:
  std::string name_;
  double nominal_q0_;
  std::vector<double> tan_gammas_, betas_deg_;
  std::vector<double> r_;  // row-major [tan γ][β], sr⁻¹, 0 where empty
};

// The scene type `road`: a standard table scaled to the surface's Q0.
class RoadMaterial {
 public:
  // q0 > 0, sr⁻¹ (typically 0.05–0.10).
  RoadMaterial(std::shared_ptr<const RoadReflectionTable> table, double q0);

  const RoadReflectionTable& table() const { return *table_; }
  double q0() const { return q0_; }

  // The BRDF f(l, v), sr⁻¹, as described above; 0 when l or v is below the surface.
  double brdf(const Vec3& n, const Vec3& to_light, const Vec3& to_viewer) const;
  // The table's q scaled to this Q0, exactly as at α = 1° (no blend): q0/Q0_table · r/cos³γ.
  double table_luminance_coefficient(const Vec3& n, const Vec3& to_light, const Vec3& to_viewer) const;
  // w(α) of the blend, from sin α = n·v.
  static double table_weight(double sin_elevation);

 private:
  std::shared_ptr<const RoadReflectionTable> table_;
  double q0_;
};

// The angles of the r-table for a lamp direction and a view at a road point.
struct RoadAngles {
  double beta_deg;
  double tan_gamma;
  double cos_gamma;
};
RoadAngles road_angles(const Vec3& n, const Vec3& to_light, const Vec3& to_viewer);

}  // namespace skylit
