// Luminous intensity distributions in Type C photometry (IES LM-63-02 §4 and CIE 121:
// the polar axis is the luminaire's nadir; γ is the angle from the nadir, 0–180°; C is
// the azimuth about the nadir, 0–360°). A distribution is either a table read from a
// photometric file (IES LM-63, EULUMDAT) or one of the simple shapes a scene may ask
// for (isotropic, cosine, spot). Values are absolute candela.
#pragma once

#include <vector>

namespace skylit {

// Which part of the C range a table covers; the rest follows by mirroring. These are
// the symmetries both LM-63 (from the first and last horizontal angle) and EULUMDAT
// (Isym 0–4) can express.
enum class CSymmetry {
  kAxial,            // one C plane stands for all (rotationally symmetric)
  kQuadrant,         // C 0–90; mirror about the C0–C180 and C90–C270 planes
  kBilateral0_180,   // C 0–180; mirror about the C0–C180 plane: I(C) = I(360 − C)
  kBilateral90_270,  // C −90…90 (the half through C0); mirror about C90–C270: I(C) = I(180 − C)
  kNone,             // C 0…<=360, wrapping from the last plane back to C0 = C360
};

// Multiplier of lamp output as a function of the luminaire's tilt from its
// photometric position (LM-63 TILT=INCLUDE). Empty = 1 at every tilt. Linear
// interpolation, clamped at the ends (the file covers the tilts it allows).
struct TiltTable {
  int lamp_to_luminaire_geometry = 0;  // LM-63 code 1–3, kept for reference only
  std::vector<double> angles_deg;
  std::vector<double> multipliers;
  double multiplier(double tilt_deg) const;
};

// The most intense luminaire a scene may hold, candela, from a shape, a file or a scaling
// to lumens: a searchlight's beam is of order 1e9 cd, a stadium floodlight 1e6. Beyond
// it the lamp's light, squared distances and glow overflow single precision (issue 19,
// item 5: an IES value of 1e308 gave Inf pixels).
inline constexpr double kMaxLuminousIntensityCd = 1e9;

class IntensityDistribution {
 public:
  enum class Kind { kIsotropic, kCosine, kSpot, kTable };

  // I(C, γ) = candela in every direction.
  static IntensityDistribution isotropic(double candela);
  // A Lambertian emitter facing the nadir: I = peak·cos γ below the horizon, 0 above.
  static IntensityDistribution cosine(double peak_candela);
  // A spot: peak inside γ ≤ inner, 0 beyond γ ≥ outer, and a smoothstep in γ between
  // (so a render shows no hard ring unless inner == outer).
  // Throws std::invalid_argument unless 0 ≤ inner ≤ outer ≤ 180.
  static IntensityDistribution spot(double peak_candela, double inner_deg, double outer_deg);
  // A measured table: candela[ic * gamma_deg.size() + ig] at (c_deg[ic], gamma_deg[ig]).
  // c_deg must cover exactly the canonical range of `symmetry` (see CSymmetry), both
  // angle lists strictly ascending, γ within [0, 180] with at least two angles, values
  // finite and ≥ 0. Throws std::invalid_argument (with a plain message the readers
  // put behind file:line) otherwise.
  static IntensityDistribution table(CSymmetry symmetry, std::vector<double> c_deg, std::vector<double> gamma_deg,
                                     std::vector<double> candela);

  // Candela toward (C, γ) in degrees; any C (wrapped), γ in [0, 180]. Tables are
  // interpolated bilinearly in (C, γ) and are 0 outside the measured γ range.
  double candela(double c_deg, double gamma_deg) const;
  // Total luminous flux in lumens: ∫∫ I sin γ dγ dC by the midpoint rule on a
  // 0.125° γ grid (and a 0.5° C grid when I depends on C). Relative error below 1e-5
  // for smooth distributions; for tables, well under 0.1 % (the bilinear surface is
  // integrated almost exactly: C knots on multiples of 0.5° are cell edges).
  double luminous_flux() const;
  // The largest candela value anywhere (the table's maximum or the shape's peak).
  double peak_candela() const;
  // The largest γ (degrees) toward which any light goes: beyond it the intensity is 0
  // at every C (180 if light may go everywhere).
  double max_gamma_deg() const;
  // The angle (degrees) over which the intensity may change its slope: for a table
  // three of its finest γ steps, for a soft-edged spot half its edge's width, for
  // smooth shapes 30°. A quadrature over directions should not take larger steps.
  double angular_detail_deg() const;
  // The same distribution with every value multiplied by factor (≥ 0).
  IntensityDistribution scaled(double factor) const;

  Kind kind() const { return kind_; }
  CSymmetry symmetry() const { return symmetry_; }
  const std::vector<double>& c_angles() const { return c_; }
  const std::vector<double>& gamma_angles() const { return gamma_; }

 private:
  IntensityDistribution() = default;
  double table_candela(double c_deg, double gamma_deg) const;
  double column_candela(std::size_t ic, double gamma_deg) const;

  Kind kind_ = Kind::kIsotropic;
  CSymmetry symmetry_ = CSymmetry::kAxial;
  double peak_ = 0;                       // shapes: the peak candela
  double inner_deg_ = 0, outer_deg_ = 0;  // spot
  std::vector<double> c_, gamma_, values_;
};

}  // namespace skylit
