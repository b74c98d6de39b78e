// The fog layer's density (Eq. 2), extinction (Eq. 9) and, in closed form, its columns
// along a view ray (Eq. 10) and toward the sun (Eq. 19, bounded by the layer's top).
//
// Every column is that of a straight piece inside the layer, of length L, starting at
// altitude z and rising by Δz = z_v·L. With η = 1/h0 the density at distance s along it
// is ρ(z)·e^(−η·z_v·s), so with x = −η·Δz, the log of the density ratio end/start,
//     N = ∫₀ᴸ ρ(z)·e^(x·s/L) ds = ρ(z)·L·(e^x − 1)/x = ρ_dense·L·g(|x|),
// where ρ_dense is the density at the denser end and g(y) = (1 − e^(−y))/y ∈ (0, 1].
// g(0) = 1: the homogeneous limit h0 → ±∞ and the level ray z_v → 0 are the same
// formula, no special case. Nothing cancels; the only hazard is overflow of e^(−η·z) for
// extreme inputs, which is why N is formed as the exponential of a sum of logarithms,
// each clamped to a finite value, and capped at kOpaqueColumnM.
#include "skylit/media/fog_layer.h"

#include "skylit/spectrum/spectral_math.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "skylit/core/error.h"

namespace skylit {
namespace {

constexpr double kHuge = 1e300;  // bounds exponents and coefficients: no Inf, no Inf − Inf

const double kLogOpaque = std::log(kOpaqueColumnM);

double clamp_huge(double x) { return std::clamp(x, -kHuge, kHuge); }

// log g(y) = log((1 − e^(−y))/y) for y ≥ 0, accurate to rounding: the series below 1e-5
// (its next term is y³/24), expm1 above.
double log_g(double y) {
  if (y < 1e-5) return std::log1p(y * (-0.5 + y / 6.0));
  return std::log(-std::expm1(-y)) - std::log(y);
}

double spectral_factor(double wavelength_nm, double lambda0_nm, double b) {
  return std::pow(wavelength_nm / lambda0_nm, -b);  // (λ/λ0)^−b of Eq. 9
}

void require(bool ok, const std::string& message) {
  if (!ok) throw InputError(message);
}

}  // namespace

double fog_density_from_visibility(double visibility_m, const FogSettings& s) {
  const double sigma550 =
      s.unit_density_extinction_per_m * spectral_factor(550.0, s.reference_wavelength_nm, s.wavelength_exponent);
  return kKoschmiederConstant / (visibility_m * sigma550);
}

double fog_visibility_from_density(double density, const FogSettings& s) {
  const double sigma550 =
      s.unit_density_extinction_per_m * spectral_factor(550.0, s.reference_wavelength_nm, s.wavelength_exponent);
  return kKoschmiederConstant / (density * sigma550);
}

FogLayer::FogLayer(const FogSettings& s)
    : z_bottom_(s.bottom_altitude_m),
      z_top_(s.top_altitude_m),
      albedo_(s.single_scattering_albedo),
      sigma0_(s.unit_density_extinction_per_m),
      lambda0_(s.reference_wavelength_nm),
      b_(s.wavelength_exponent),
      phase_kind_(s.phase),
      asymmetry_(s.asymmetry),
      multiple_scattering_(s.multiple_scattering) {
  require(std::isfinite(z_bottom_) && std::isfinite(z_top_) && z_bottom_ < z_top_,
          "fog: bottom_altitude_m must be below top_altitude_m (both finite)");
  require(!std::isnan(s.scale_height_m) && s.scale_height_m != 0.0,
          "fog.scale_height_m must not be 0 (negative: denser upward; very large: homogeneous)");
  require(std::isfinite(sigma0_) && sigma0_ >= 0.0, "fog.unit_density_extinction_per_m must be finite and ≥ 0");
  require(std::isfinite(lambda0_) && lambda0_ > 0.0, "fog.reference_wavelength_nm must be > 0");
  require(std::isfinite(b_), "fog.wavelength_exponent must be finite");
  require(albedo_ >= 0.0 && albedo_ <= 1.0, "fog.single_scattering_albedo must be in [0, 1]");
  if (s.phase == FogPhase::droplet_fit) {
    require(s.droplet_diameter_um >= 5.0 && s.droplet_diameter_um <= 50.0,
            "fog.droplet_diameter_um must be in [5, 50] µm, where the phase function's fit holds");
  } else {
    require(s.asymmetry > -1.0 && s.asymmetry < 1.0, "fog.asymmetry must be in (−1, 1)");
  }
  droplet_ = DropletPhaseParameters::for_diameter(std::clamp(s.droplet_diameter_um, 5.0, 50.0));
  if (s.ground_visibility_m) {
    const double v = *s.ground_visibility_m;
    require(std::isfinite(v) && v > 0.0, "fog.ground_visibility_m must be finite and > 0");
    require(sigma0_ > 0.0, "fog.ground_visibility_m needs fog.unit_density_extinction_per_m > 0");
    rho0_ = std::min(fog_density_from_visibility(v, s), kHuge);
  } else {
    rho0_ = s.density_at_ground;
    require(std::isfinite(rho0_) && rho0_ >= 0.0, "fog.density_at_ground must be finite and ≥ 0");
  }
  log_rho0_ = std::log(rho0_);                // −∞ for no fog, handled by the callers
  eta_ = clamp_huge(1.0 / s.scale_height_m);  // 0 for h0 = ±∞
  for (int i = 0; i < kSpectralBins; ++i) {
    sigma_bins_[static_cast<size_t>(i)] = unit_density_extinction_per_m(kGrid.center_nm(i));
    grey_ = grey_ && sigma_bins_[static_cast<size_t>(i)] == sigma_bins_[0];
  }
}

double FogLayer::density(double z) const {
  if (z < z_bottom_ || z > z_top_) return 0.0;
  return std::exp(std::min(log_rho0_ + clamp_huge(-eta_ * z), kLogOpaque));  // Eq. 2
}

double FogLayer::unit_density_extinction_per_m(double wavelength_nm) const {
  return std::min(sigma0_ * spectral_factor(wavelength_nm, lambda0_, b_), kHuge);  // Eq. 9 / ρ
}

RaySpan FogLayer::clip(double z_p, double z_v, double s1, double s2) const {
  if (z_v == 0.0) {
    if (z_p < z_bottom_ || z_p > z_top_) return {};
    return {s1, s2};
  }
  // Where the ray meets the bottom and the top (±∞ for a nearly level ray is fine).
  const double s_bottom = (z_bottom_ - z_p) / z_v, s_top = (z_top_ - z_p) / z_v;
  return {std::max(s1, std::min(s_bottom, s_top)), std::min(s2, std::max(s_bottom, s_top))};
}

double FogLayer::log_piece_column(double z_start, double rise, double log_length) const {
  // x = ln(ρ_end/ρ_start); the denser end's log density is that of the start plus max(0, x).
  // Each term is finite or −∞ (ρ0 > 0 is checked by the callers), so the sum is never NaN.
  const double x = clamp_huge(-eta_ * rise);
  const double log_dense = log_rho0_ + clamp_huge(-eta_ * z_start) + std::max(0.0, x);
  return log_dense + log_length + log_g(std::abs(x));
}

double FogLayer::piece_column(double z_start, double rise, double length) const {
  if (!(length > 0.0) || !(rho0_ > 0.0)) return 0.0;
  // Ordinary pieces directly: ρ(z_start)·length·(e^x − 1)/x with x = ln(ρ_end/ρ_start),
  // two exponentials; the logarithmic form below keeps extreme ones (huge lengths,
  // densities or rises) finite.
  const double x = -eta_ * rise, log_start = log_rho0_ - eta_ * z_start;
  if (std::abs(x) < 50 && std::abs(log_start) < 500 && length < 1e100) {
    const double mean = std::abs(x) < 1e-8 ? 1 + 0.5 * x : std::expm1(x) / x;
    return std::min(std::exp(log_start) * length * mean, kOpaqueColumnM);
  }
  return std::exp(std::min(log_piece_column(z_start, rise, std::log(length)), kLogOpaque));
}

double FogLayer::column(double z_p, double z_v, double s1, double s2) const {
  const RaySpan span = clip(z_p, z_v, s1, s2);
  if (span.empty()) return 0.0;
  const double length = span.hi - span.lo;
  const double z_start = std::clamp(z_p + z_v * span.lo, z_bottom_, z_top_);
  // Only a level ray stays in the layer for ever: with any fog it is opaque (and 0·∞
  // would make its rise NaN).
  if (!std::isfinite(length)) return rho0_ > 0.0 ? kOpaqueColumnM : 0.0;
  return piece_column(z_start, z_v * length, length);  // Eq. 10 / σ, i.e. Eq. 22's α·h0/z_v·(1 − u) / σ
}

double FogLayer::column_between(const Vec3& a, const Vec3& b) const {
  const double d = length(b - a);
  if (!(d > 0.0)) return 0.0;
  return column(a.z, (b.z - a.z) / d, 0.0, d);
}

double FogLayer::sun_column(double z, double z_sun) const {
  if (!(z_sun > 0.0)) return kOpaqueColumnM;
  if (z >= z_top_ || !(rho0_ > 0.0)) return 0.0;
  // From where the path is in the layer (z, or the bottom for a point below it) up to the
  // top: ρ(z)·(1 − e^(−η(z_t − z)))/(η·z_L) = ρ0·h0/z_L·(e^(−z/h0) − e^(−z_t/h0)), Eq. 19
  // with the top's term that the unbounded layer lacks. The length (z_t − z)/z_L is
  // passed as its logarithm so that a grazing sun (z_L → 0) gives a huge column, not Inf.
  const double z_from = std::max(z, z_bottom_), rise = z_top_ - z_from;
  return std::exp(std::min(log_piece_column(z_from, rise, std::log(rise) - std::log(z_sun)), kLogOpaque));
}

Spectrum FogLayer::transmittance(double column_m) const {
  // The optical depth in double (columns reach 1e250), then the vectorised single-
  // precision exponential: the renderer asks for this for every sample, and the sky
  // light in fog for each direction an obstacle hides. Grey fog (the default, b = 0):
  // one exponential for all bins, the same value the loop below gives each of them.
  if (grey_) {
    const float depth = static_cast<float>(std::min(sigma_bins_[0] * column_m, 1e4));
    return Spectrum(depth >= 87.0f ? 0.0f : exp_nonpositive(-depth));
  }
  Spectrum depth;
  for (int i = 0; i < kSpectralBins; ++i)
    depth[i] = static_cast<float>(std::min(sigma_bins_[static_cast<size_t>(i)] * column_m, 1e4));
  Spectrum t = transmittance_of(depth);
  // Below e^−87 single precision has nothing left: opaque is exactly 0.
  for (int i = 0; i < kSpectralBins; ++i) t[i] = depth[i] >= 87.0f ? 0.0f : t[i];
  return t;
}

double FogLayer::phase(double cos_theta) const {
  cos_theta = std::clamp(cos_theta, -1.0, 1.0);
  return phase_kind_ == FogPhase::droplet_fit ? droplet_phase(cos_theta, droplet_)
                                              : henyey_greenstein_phase(cos_theta, asymmetry_);
}

}  // namespace skylit
