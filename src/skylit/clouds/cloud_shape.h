// The solid of one cloud (§6): an ellipse in the sky at a mid-plane altitude, given a
// thickness that varies across it. Only geometry lives here (where the cloud is); the
// march through it is cloud_march.h, its light cloud_scattering.h, the whole cloud cloud.h.
//
// Kaneda et al. map "a thickness function [Fourier series composed of a polynomial of
// sine waves (Gardner 1985)] onto an ellipse". From Gardner, G. Y. (1985), "Visual
// simulation of clouds", SIGGRAPH '85, Computer Graphics 19(3):297–303, we take his
// texture function: a product of two sums of sine waves, one along each horizontal axis,
// T(x, y) ∝ (1 + Σ a_i sin(ω_i x + φ_i)) · (1 + Σ b_i sin(ν_i y + ψ_i)), with (in the
// generated layers, cloud_layer.h) his spectral rule that each wave has twice the
// frequency and 1/√2 the amplitude of the one before. We do not take his ellipsoids,
// his translucency threshold or his cross-coupled phase shifts: here the texture
// modulates a thickness, and the cloud is the solid
//
//   { (x, y, z) : r(x, y) < 1, |z − z_mid| ≤ T(x, y)/2 },
//   T = T_max · (1 − r²)^p · f_u(u) · f_v(v),
//   f(u) = max(0, 1 + Σ a_i sin(ω_i u + φ_i)) / (1 + Σ |a_i|)   (so 0 ≤ f ≤ 1),
//
// where (u, v) are the horizontal coordinates along the ellipse's axes measured from
// its centre and r² = (u/A)² + (v/B)² for the semi-axes A, B. T ≤ T_max everywhere;
// with Σ|a_i| < 1 the texture never reaches 0 and the footprint is the whole ellipse.
// p = 1/2 (the default) is the thickness of an ellipsoid: thin toward the rim.
//
// The textures are tabulated across the ellipse (the sine sums were most of the time of
// every march), and the tables' slope and curvature bounds are kept for the march's
// margin bounds (cloud_march.h).
#pragma once

#include <vector>

#include "skylit/core/vec3.h"

namespace skylit {

// σ of a cumulus with liquid water content ~0.35 g m⁻³ and effective radius ~10 µm
// (σ ≈ 3·LWC/(2 ρ_w r_e)), an in-cloud visibility of ~60–80 m; a 400 m thick cloud then
// has an optical depth of 20 (cumulus: 10–50).
inline constexpr double kDefaultCloudExtinction = 0.05;  // m⁻¹

// One sine wave of the thickness texture: amplitude (dimensionless), angular frequency
// (rad/m along the axis), phase (rad).
struct CloudWave {
  double amplitude = 0;
  double frequency = 0;
  double phase = 0;
};

struct CloudShape {
  double center_x = 0, center_y = 0;            // m
  double altitude = 1500;                       // z of the mid-plane, m
  double semi_axis_a = 1000;                    // m, along the u axis
  double semi_axis_b = 600;                     // m, along the v axis
  double rotation = 0;                          // rad: angle of the u axis counter-clockwise from east (+x)
  double max_thickness = 400;                   // T_max, m
  double falloff_exponent = 0.5;                // p in (1 − r²)^p
  std::vector<CloudWave> waves_u;               // texture along u (Gardner's x series)
  std::vector<CloudWave> waves_v;               // texture along v (Gardner's y series)
  double extinction = kDefaultCloudExtinction;  // σ, m⁻¹, grey
  double albedo = 1.0;                          // ω, single-scattering albedo
};

class CloudGeometry {
 public:
  // Samples over [−a, a] and [−b, b] of the texture tables (kTextureSamples + 1 values).
  // The finest wave has at most kStepsPerWavelength·(2a / horizontal_scale) … samples:
  // 2048 over a diameter is over 100 per wavelength of Gardner's fourth wave.
  static constexpr int kTextureSamples = 2048;

  // Negative or non-finite sizes are taken as 0 (an empty cloud).
  explicit CloudGeometry(const CloudShape& shape);

  const CloudShape& shape() const { return shape_; }
  // No volume: a zero semi-axis or thickness.
  bool empty() const { return empty_; }

  // T(x, y) in metres at a world position (0 outside the ellipse).
  double thickness(double x, double y) const;
  bool contains(const Vec3& p) const;
  // Half-width of the axis-aligned box around the footprint, along x and y.
  double extent_x() const { return extent_x_; }
  double extent_y() const { return extent_y_; }

  // The part [t0, t1] of the ray o + t·d, t in [t_min, t_max], inside the cloud's bounding
  // volume (elliptic cylinder ∩ slab |z − z_mid| ≤ T_max/2); false if empty. d need not
  // be unit; t_max may be infinite.
  bool clip(const Vec3& o, const Vec3& d, double t_min, double t_max, double& t0, double& t1) const;

  // The cloud's horizontal frame: a horizontal vector (dx, dy) (from the centre, for a
  // position) along the ellipse's axes u and v, and the world point at (u, v) and z.
  double along_u(double dx, double dy) const { return dx * cos_r_ + dy * sin_r_; }
  double along_v(double dx, double dy) const { return -dx * sin_r_ + dy * cos_r_; }
  Vec3 world_point(double u, double v, double z) const {
    return {shape_.center_x + u * cos_r_ - v * sin_r_, shape_.center_y + u * sin_r_ + v * cos_r_, z};
  }
  // f_u(u) and f_v(v) from the tables (u, v in metres from the centre, clamped to the
  // ellipse's box), and (1 − r²)^p as a function of q = 1 − r²: 0 for q ≤ 0,
  // non-decreasing in q.
  double texture_u(double u) const { return table_lookup(texture_u_, u, shape_.semi_axis_a); }
  double texture_v(double v) const { return table_lookup(texture_v_, v, shape_.semi_axis_b); }
  double envelope(double q) const;
  // Largest |slope| of the tabulated (piecewise-linear) textures, per metre along u, v.
  double texture_slope_u() const { return texture_slope_u_; }
  double texture_slope_v() const { return texture_slope_v_; }
  // Bounds on |f''| of the textures' sine sums (infinite where max(0, ·) may clip them).
  double texture_curvature_u() const { return texture_curvature_u_; }
  double texture_curvature_v() const { return texture_curvature_v_; }
  // Step length wanted along the horizontal to resolve the ellipse and its waves, m.
  double horizontal_scale() const { return horizontal_scale_; }

 private:
  static double texture(double w, const std::vector<CloudWave>& waves, double norm);
  static double table_lookup(const std::vector<double>& table, double w, double half_width);
  double local_thickness(double u, double v) const;

  CloudShape shape_;
  double cos_r_ = 1, sin_r_ = 0;
  double norm_u_ = 1, norm_v_ = 1;
  std::vector<double> texture_u_, texture_v_;
  double texture_slope_u_ = 0, texture_slope_v_ = 0;
  double texture_curvature_u_ = 0, texture_curvature_v_ = 0;
  double horizontal_scale_ = 0;
  double extent_x_ = 0, extent_y_ = 0;
  bool empty_ = true;
};

}  // namespace skylit
