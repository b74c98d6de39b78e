// One cloud (§6, Eq. 16): an ellipse in the sky at a mid-plane altitude, given a
// thickness that varies across it, filled with water droplets of uniform density.
//
// Shape. Kaneda et al. map "a thickness function [Fourier series composed of a
// polynomial of sine waves (Gardner 1985)] onto an ellipse". From Gardner, G. Y. (1985),
// "Visual simulation of clouds", SIGGRAPH '85, Computer Graphics 19(3):297–303, we take
// his texture function: a product of two sums of sine waves, one along each horizontal
// axis, T(x, y) ∝ (1 + Σ a_i sin(ω_i x + φ_i)) · (1 + Σ b_i sin(ν_i y + ψ_i)), with (in
// the generated layers, cloud_layer.h) his spectral rule that each wave has twice the
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
// Optics. Droplets (diameters ~ 5–50 µm) are much larger than visible wavelengths:
// extinction and phase function are taken as wavelength-independent (grey), as the
// paper says (§6). The extinction coefficient σ is uniform inside the cloud; the
// default 0.05 m⁻¹ is that of a cumulus with liquid water content ~0.35 g m⁻³ and
// effective radius ~10 µm (σ ≈ 3·LWC/(2 ρ_w r_e)), an in-cloud visibility of ~60–80 m,
// and gives a 400 m thick cloud an optical depth of 20 (cumulus: 10–50). The phase
// function is the droplet fit of Jendersie & d'Eon (2023) (media/fog_phase.h) at a
// droplet diameter of 20 µm: strongly forward-peaked (mean cosine ~0.87), with a
// diffraction spike within a few degrees of the sun. Single-scattering albedo 1.
//
// Light (Eq. 16). Along a viewing ray, the radiance leaving the cloud toward the viewer:
//
//   I_c = I_behind e^{−t_total} + ∫ σ (ω F(θ) E_sun e^{−t'(s)} + I_a e^{−(1−g) t'(s)}) e^{−t(s)} ds,
//
// with E_sun the sun's irradiance at the cloud (Eq. 15, supplied by the caller), t'(s)
// the optical depth from the point toward the sun through this cloud's 3-D shape, t(s)
// the optical depth from the point back toward the viewer, and I_a a uniform ambient
// radiance standing for multiple scattering (iii). Unlike the paper's printed Eq. 16,
// I_a is attenuated by the similarity-scaled depth e^{−(1−g) t'} (g = cloud_mean_cosine(),
// 0.879; van de Hulst's similarity relation: in a forward-scattering medium multiply
// scattered light diffuses with transport coefficient σ(1−g)), not by e^{−t'}: it still
// fades into the cloud away from the sun's side (so the sunlit side stays brighter with
// the sun behind the viewer), but thick centres no longer go black. The single-scattered
// sun keeps e^{−t'} (docs/clouds.md).
//
// Speed. prepare_sun(to_sun) tabulates t' on a kSunGridU × kSunGridV × kSunGridZ grid of
// nodes over the bounding volume in the cloud's frame (u, v, z − z_mid); scatter() with
// the same sun direction then interpolates it trilinearly instead of marching toward the
// sun at every step (docs/clouds.md gives the measured error and speed-up). The march
// itself (view rays, shadows, the grid's build) skips the evaluation of T wherever a
// bound on the margin g = T/2 − |z − z_mid| over a run of its steps (margin_bounds)
// proves that g keeps its sign there: its steps are those of the plain fixed-step march
// and the stretches it finds inside are the same, it only evaluates T less often.
#pragma once

#include <limits>
#include <type_traits>
#include <vector>

#include "skylit/core/vec3.h"
#include "skylit/spectrum/spectrum.h"

namespace skylit {

inline constexpr double kDefaultCloudExtinction = 0.05;       // m⁻¹ (see above)
inline constexpr double kCloudDropletDiameterUm = 20.0;       // for the phase function
inline constexpr double kDefaultCloudAmbientFraction = 0.25;  // see default_cloud_ambient
// Nodes of the sun optical-depth grid (prepare_sun): along u, v (the ellipse's axes, over
// [−A, A] × [−B, B]) and z (over the slab |z − z_mid| ≤ T_max/2).
inline constexpr int kSunGridU = 64;
inline constexpr int kSunGridV = 64;
inline constexpr int kSunGridZ = 24;

// The cloud phase function F(θ) (sr⁻¹, normalised over the sphere): the droplet fit of
// media/fog_phase.h at kCloudDropletDiameterUm. cos θ = V·L for the viewing direction V
// (from the viewer into the cloud) and the direction L toward the sun.
double cloud_phase(double cos_theta);
// g = ∫ cos θ F(θ) dΩ of cloud_phase (computed once, numerically): 0.879.
double cloud_mean_cosine();

// One sine wave of the thickness texture: amplitude (dimensionless), angular frequency
// (rad/m along the axis), phase (rad).
struct CloudWave {
  double amplitude = 0;
  double frequency = 0;
  double phase = 0;
};

struct CloudShape {
  double center_x = 0, center_y = 0;  // m
  double altitude = 1500;             // z of the mid-plane, m
  double semi_axis_a = 1000;          // m, along the u axis
  double semi_axis_b = 600;           // m, along the v axis
  double rotation = 0;                // rad: angle of the u axis counter-clockwise from east (+x)
  double max_thickness = 400;         // T_max, m
  double falloff_exponent = 0.5;      // p in (1 − r²)^p
  std::vector<CloudWave> waves_u;     // texture along u (Gardner's x series)
  std::vector<CloudWave> waves_v;     // texture along v (Gardner's y series)
  double extinction = kDefaultCloudExtinction;  // σ, m⁻¹, grey
  double albedo = 1.0;                          // ω, single-scattering albedo
};

// Lighting of a cloud, from the caller's atmosphere model.
struct CloudLighting {
  Vec3 to_sun{0, 0, 1};  // unit vector toward the sun
  Spectrum sun;          // E_sun at the cloud's altitude (Eq. 15), W m⁻² nm⁻¹, normal to the beam
  Spectrum ambient;      // I_a, W m⁻² sr⁻¹ nm⁻¹
};

// A default for I_a: kDefaultCloudAmbientFraction · E_sun · max(sin h, 0) / π for the
// sun's altitude h — the radiance of a Lambertian surface of albedo 0.25 under the sun,
// about what a thick cloud's base transmits diffusely (a two-stream estimate for optical
// depth ~20 and g ~0.85 gives 0.2–0.3). The renderer may add a share of the sky's mean
// radiance for when the sun is down.
Spectrum default_cloud_ambient(const Spectrum& sun_at_cloud, const Vec3& to_sun);

// What a segment of a ray through a cloud does to light: radiance leaving = behind ·
// transmittance + in_scattered (Eq. 16).
struct CloudScattering {
  Spectrum in_scattered;
  double transmittance = 1.0;
  // Where the ray enters the first cloud it meets (m along it; infinite if none): what
  // the air between the viewer and the clouds starts from.
  double distance = std::numeric_limits<double>::infinity();
};

class Cloud {
 public:
  // Negative or non-finite sizes are taken as 0 (an empty cloud).
  explicit Cloud(const CloudShape& shape);

  const CloudShape& shape() const { return shape_; }

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

  // Optical depth (grey) along o + t·d, t in [t_min, t_max], d a unit vector.
  double optical_depth(const Vec3& o, const Vec3& d, double t_min, double t_max) const;
  double transmittance(const Vec3& o, const Vec3& d, double t_min, double t_max) const;
  // e^{−t'} from p toward the sun through this cloud (always marched).
  double sun_transmittance(const Vec3& p, const Vec3& to_sun) const;

  // Tabulates t' toward to_sun (normalised here) on the sun grid (kSunGrid*), in parallel
  // with TBB. Call once per scene / sun direction; not thread-safe against concurrent
  // scatter() calls. A zero or non-finite direction clears the grid.
  void prepare_sun(const Vec3& to_sun);
  void clear_sun() { sun_grid_.clear(); }
  // Whether scatter() with this (unit or not) sun direction will use the grid.
  bool sun_prepared_for(const Vec3& to_sun) const;
  // t' at p toward the prepared sun by trilinear interpolation of the grid (p inside the
  // bounding volume or clamped onto it). Only meaningful when a grid is prepared.
  double interpolated_sun_depth(const Vec3& p) const;

  // In-scattered radiance and transmittance of the segment of the viewing ray o + t·d
  // (d unit, from the viewer), t in [t_min, t_max] (Eq. 16 without I_behind). With the
  // sun below the horizon or E_sun black, only I_a remains (still through e^{−(1−g)t'}).
  // t' comes from the grid if prepare_sun was called with light.to_sun, else is marched.
  CloudScattering scatter(const Vec3& o, const Vec3& d, double t_min, double t_max,
                          const CloudLighting& light) const;
  // Eq. 16 in full: I_behind · e^{−t_total} + in-scattered.
  Spectrum radiance(const Vec3& o, const Vec3& d, double t_min, double t_max, const Spectrum& behind,
                    const CloudLighting& light) const;

  // Bounds lo ≤ g(t) ≤ hi on the margin g = T/2 − |z − z_mid| (≥ 0 inside) at every
  // point o + t·d with t in [t0, t1], from samples at the two ends (up to rounding; d need not be
  // unit). Rigorous, not an estimate: the envelope (1 − r²)^p is non-decreasing in 1 − r²,
  // an exact quadratic along the ray (so the unbounded slope of p < 1 at the rim does not
  // matter); each texture factor moves no faster than its table's largest slope and,
  // where its sine sum is never clipped at 0, stays within |f''|·length²/8 of its chord;
  // z is linear (cloud.cpp, margin_bound). The march uses them to skip runs of steps
  // where g cannot change sign.
  void margin_bounds(const Vec3& o, const Vec3& d, double t0, double t1, double& lo, double& hi) const;

  // Calls inside(s0, s1) for each stretch of [t0, t1] (already clipped) found inside the
  // solid (the inside part of each step of the march, docs/clouds.md), in order;
  // resolution scales the number of steps. every_step evaluates T at every step's end
  // instead of skipping where margin_bounds proves the sign of g: the same stretches,
  // slower (for tests of the skipping).
  template <typename F>
  void for_each_inside(const Vec3& o, const Vec3& d, double t0, double t1, double resolution, F&& inside,
                       bool every_step = false) const;

 private:
  double texture(double w, const std::vector<CloudWave>& waves, double norm) const;
  // The textures along u and v tabulated across the ellipse (the sine sums were most of
  // the time of every march): kTextureSamples + 1 values over [−a, a] and [−b, b].
  static constexpr int kTextureSamples = 2048;
  static double table_lookup(const std::vector<double>& table, double w, double half_width);
  // (1 − r²)^p as a function of q = 1 − r²: 0 for q ≤ 0, non-decreasing in q.
  double envelope(double q) const;
  double local_thickness(double u, double v) const;
  // The margin g = T/2 − |z − z_mid| at o + t·d (≥ 0 inside), with the two texture
  // factors f_u, f_v there (the march bounds g near t from them).
  struct MarginSample {
    double g, fu, fv;
  };
  MarginSample margin_sample(const Vec3& o, const Vec3& d, double t) const;
  // A ray in the cloud's frame, for margin_bound: u(t)/a = u0 + du·t, v(t)/b likewise,
  // z(t) − z_mid = w0 + dw·t; bounds on |df_u/dt|, |df_v/dt| along it, and on f_u's
  // deviation from its chord over a stretch of length s (bend_u·s² + bend0_u; infinite
  // where the texture has no curvature bound), f_v likewise; the margins for the
  // rounding of g and q in samples up to t_far.
  struct RayFrame {
    double u0, v0, du, dv, inv_speed2, w0, dw;
    double slope_u, slope_v, bend_u, bend0_u, bend_v, bend0_v;
    double eps, q_slack;
  };
  RayFrame ray_frame(const Vec3& o, const Vec3& d, double t_far) const;
  // The upper (or lower) bound of margin_bounds over [ta, tb] from the samples at both ends.
  double margin_bound(const RayFrame& r, double ta, const MarginSample& a, double tb, const MarginSample& b,
                      bool upper) const;
  // One part of a march (march, cloud.cpp), and a run of its steps from end i to end j,
  // both sampled.
  struct MarchPart;
  void march_span(const MarchPart& m, int i, const MarginSample& si, int j, const MarginSample& sj) const;
  int step_count(const Vec3& d, double length, double resolution) const;
  // The sink gets the inside part of each step, in order; with whole_runs, a run of steps
  // proven inside comes as one stretch (for sums of lengths). every_step: no skipping.
  void march(const Vec3& o, const Vec3& d, double t0, double t1, double resolution, bool whole_runs,
             bool every_step, void (*sink)(void*, double, double), void* ctx) const;

  CloudShape shape_;
  double cos_r_ = 1, sin_r_ = 0;
  double norm_u_ = 1, norm_v_ = 1;
  std::vector<double> texture_u_, texture_v_;
  // Largest |slope| of the tabulated (piecewise-linear) textures, per metre along u, v.
  double texture_slope_u_ = 0, texture_slope_v_ = 0;
  // Bounds on |f''| of the textures' sine sums (infinite where max(0, ·) may clip them).
  double texture_curvature_u_ = 0, texture_curvature_v_ = 0;
  double horizontal_scale_ = 0;  // step length wanted along the horizontal, m
  double extent_x_ = 0, extent_y_ = 0;
  bool empty_ = true;
  // Sun grid: t' at node (i, j, k), index (k·V + j)·U + i; empty when not prepared.
  std::vector<float> sun_grid_;
  Vec3 sun_dir_{0, 0, 0};
};

template <typename F>
void Cloud::for_each_inside(const Vec3& o, const Vec3& d, double t0, double t1, double resolution,
                            F&& inside, bool every_step) const {
  march(o, d, t0, t1, resolution, false, every_step,
        [](void* ctx, double s0, double s1) { (*static_cast<std::remove_reference_t<F>*>(ctx))(s0, s1); },
        const_cast<void*>(static_cast<const void*>(&inside)));
}

}  // namespace skylit
