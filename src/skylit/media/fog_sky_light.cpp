// Sky light in fog: the table J(z) of Eq. 13 and the trapezoidal integration along a view
// ray with the adaptive pitch of Eq. 14. docs/fog.md, "Sky light in fog".
//
// J(z). For a flat layer the column from z toward a direction of vertical cosine w is
// V(z)/|w|, V the vertical column from z to the top (w > 0) or to the bottom (w < 0); so
//   J(z) = ∫ A(w)·e^(−σ·V(z)/|w|) dw,   A(w) = ∫ L(w, φ) dφ,
// and the sky is read only to form A at the quadrature's nodes in w, once. The nodes are
// Gauss–Legendre in bands whose edges are at |w| = (k/16)² (finer near the horizon, where
// the sky and the transmittance change fastest, and never at w = 0 itself, where the
// column is infinite); A is a midpoint sum over azimuths on one side of the sun's
// vertical plane, doubled.
#include "skylit/media/fog_sky_light.h"

#include <algorithm>
#include <cmath>

#include "skylit/core/error.h"

namespace skylit {
namespace {

// Gauss–Legendre nodes and weights on [−1, 1] for kNodesPerBand = 3.
constexpr std::array<double, 3> kGaussX{-0.7745966692414834, 0.0, 0.7745966692414834};
constexpr std::array<double, 3> kGaussW{5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
static_assert(FogSkyLight::kNodesPerBand == 3);

// The vertical column from z up to the top (up) or down to the bottom.
double vertical_column(const FogLayer& fog, double z, bool up) {
  z = std::clamp(z, fog.bottom_m(), fog.top_m());
  return up ? fog.column(z, 1.0, 0.0, fog.top_m() - z) : fog.column(z, -1.0, 0.0, z - fog.bottom_m());
}

}  // namespace

FogSkyLight::FogSkyLight(const FogLayer& fog, const SkyModel& sky, int altitudes) : fog_(fog) {
  if (altitudes < 2) throw InputError("fog sky light: at least 2 altitudes");

  // A(w) at the nodes, both hemispheres: node n has cosine w_[n] (signed) and weight dw_[n].
  const Vec3 up{0, 0, 1};
  Vec3 e1{sky.to_sun().x, sky.to_sun().y, 0.0};
  e1 = length(e1) > 1e-9 ? normalize(e1) : Vec3{1, 0, 0};
  const Vec3 e2 = cross(up, e1);
  sun_horizontal_ = e1;
  sun_horizontal_side_ = e2;
  std::vector<double> w, dw;
  std::vector<Spectrum> a;
  const double dphi = kPi / kHalfAzimuths;
  for (int hemisphere = 0; hemisphere < 2; ++hemisphere) {
    const double sign = hemisphere == 0 ? 1.0 : -1.0;
    for (int k = 0; k < kBandsPerHemisphere; ++k) {
      const double lo = std::pow(double(k) / kBandsPerHemisphere, 2),
                   hi = std::pow(double(k + 1) / kBandsPerHemisphere, 2);
      for (int g = 0; g < kNodesPerBand; ++g) {
        const double wn = 0.5 * (lo + hi) + 0.5 * (hi - lo) * kGaussX[static_cast<size_t>(g)];
        const double sin_zenith = std::sqrt(std::max(0.0, 1.0 - wn * wn));
        Spectrum sum;
        for (int j = 0; j < kHalfAzimuths; ++j) {
          const double phi = (j + 0.5) * dphi;
          const Vec3 d = sin_zenith * (std::cos(phi) * e1 + std::sin(phi) * e2) + sign * wn * up;
          sum += sky.sky_radiance_near_ground(d).spectrum();
        }
        w.push_back(sign * wn);
        dw.push_back(0.5 * (hi - lo) * kGaussW[static_cast<size_t>(g)]);
        a.push_back(sum * static_cast<float>(2.0 * dphi));
      }
    }
  }
  for (size_t n = 0; n < w.size(); ++n) unattenuated_ += a[n] * static_cast<float>(dw[n]);

  // Altitudes: equal steps of a blend of the altitude and of the vertical column from the
  // bottom, so that they crowd where the density is large (J changes fastest there).
  const double bottom = fog_.bottom_m(), top = fog_.top_m(), thickness = top - bottom;
  const double total = vertical_column(fog_, bottom, true);
  auto measure = [&](double z) {
    const double geometric = (z - bottom) / thickness;
    if (!(total > 0.0)) return geometric;
    return 0.5 * geometric + 0.5 * (total - vertical_column(fog_, z, true)) / total;
  };
  z_.resize(static_cast<size_t>(altitudes));
  for (int i = 0; i < altitudes; ++i) {
    const double target = double(i) / (altitudes - 1);
    double lo = bottom, hi = top;
    for (int it = 0; it < 80; ++it) {
      const double mid = 0.5 * (lo + hi);
      (measure(mid) < target ? lo : hi) = mid;
    }
    z_[static_cast<size_t>(i)] = i == 0 ? bottom : (i == altitudes - 1 ? top : 0.5 * (lo + hi));
  }

  // J at each altitude (Eq. 13).
  const auto& sigma = fog_.unit_density_extinction_bins();
  j_.resize(z_.size());
  for (size_t i = 0; i < z_.size(); ++i) {
    const double v_up = vertical_column(fog_, z_[i], true), v_down = vertical_column(fog_, z_[i], false);
    std::array<double, kSpectralBins> sum{};
    for (size_t n = 0; n < w.size(); ++n) {
      const double column = std::min((w[n] > 0 ? v_up : v_down) / std::abs(w[n]), kOpaqueColumnM);
      for (int b = 0; b < kSpectralBins; ++b)
        sum[static_cast<size_t>(b)] +=
            dw[n] * a[n][b] * std::exp(-std::min(sigma[static_cast<size_t>(b)] * column, 800.0));
    }
    for (int b = 0; b < kSpectralBins; ++b) {
      j_[i][b] = static_cast<float>(sum[static_cast<size_t>(b)]);
      j_max_[static_cast<size_t>(b)] = std::max(j_max_[static_cast<size_t>(b)], sum[static_cast<size_t>(b)]);
    }
  }
  if (fog_.multiple_scattering()) {
    FogLayerLighting light;
    // The sky's mean over azimuth at the top, toward each cosine (symmetric about the
    // sun's vertical plane, so one half circle counted twice).
    // The sky at the top: light travelling down at azimuth φ from the sunbeam comes from
    // the sky seen at azimuth φ from the sun.
    light.sky = [&](double mu, double phi) {
      const double sin_zenith = std::sqrt(std::max(0.0, 1.0 - mu * mu));
      return sky.sky_radiance_near_ground(sin_zenith * (std::cos(phi) * e1 + std::sin(phi) * e2) + mu * up).spectrum();
    };
    light.sun_cosine = sky.to_sun().z;
    light.sun_irradiance = sky.direct_sun(std::max(0.0, fog_.top_m())).spectrum();
    light.ground_albedo = sky.atmosphere().settings().ground_albedo;
    diffuse_.emplace(fog_, light);
    j_max_ = diffuse_->largest();
  } else {
    for (double& v : j_max_) v /= 4 * kPi;  // per steradian, as `source` gives it
  }
  double mean = 0;
  for (double v : j_max_) mean += v;
  j_max_mean_ = mean / kSpectralBins;
}

Spectrum FogSkyLight::at(double z) const {
  if (std::isnan(z)) return Spectrum(0.0f);
  if (z > z_.back()) return unattenuated_;
  if (z <= z_.front()) return j_.front();
  const size_t hi = static_cast<size_t>(std::upper_bound(z_.begin(), z_.end(), z) - z_.begin());
  if (hi >= z_.size()) return j_.back();
  const size_t lo = hi - 1;
  const double span = z_[hi] - z_[lo];
  const float f = span > 0 ? static_cast<float>((z - z_[lo]) / span) : 0.0f;
  Spectrum out;
  for (int b = 0; b < kSpectralBins; ++b) out[b] = (1 - f) * j_[lo][b] + f * j_[hi][b];
  return out;
}

Spectrum FogSkyLight::source(double z, double up, double relative_azimuth) const {
  if (diffuse_) return diffuse_->scattered(z, up, relative_azimuth);
  return at(z) * static_cast<float>(1.0 / (4.0 * kPi));
}

void FogSkyLight::integrate(const Vec3& viewpoint, const Vec3& dir_in, double s_begin, double s_end, int terms,
                            int paced, const TermSource& source_terms, Spectrum* out, int* steps) const {
  if (steps) *steps = 0;
  for (int t = 0; t < terms; ++t) out[t] = Spectrum(0.0f);
  const double albedo = fog_.single_scattering_albedo();
  const double len = length(dir_in);
  if (!(len > 0.0) || !std::isfinite(len) || !std::isfinite(viewpoint.z) || std::isnan(s_begin) || std::isnan(s_end) ||
      !(albedo > 0.0) || !(fog_.density_at_ground() > 0.0) || !(j_max_mean_ > 0.0))
    return;
  const double w = dir_in.z / len, z_p = viewpoint.z;
  const RaySpan span = fog_.clip(z_p, w, std::max(s_begin, 0.0), s_end);
  if (span.empty()) return;
  const double a = span.lo, b = span.hi;

  const auto& sigma = fog_.unit_density_extinction_bins();
  double sigma_mean = 0;
  for (double s : sigma) sigma_mean += s;
  sigma_mean /= kSpectralBins;
  if (!(sigma_mean > 0.0)) return;

  // Largest altitude step per trapezoid: a tenth of the scale height or of the layer.
  const double thickness = fog_.top_m() - fog_.bottom_m();
  const double eta = std::abs(fog_.inverse_scale_height_per_m());
  const double vertical_scale = eta > 0.0 ? std::min(thickness, 1.0 / eta) : thickness;
  const double geometric_max = std::abs(w) > 0.0 ? kGeometricPitch * vertical_scale / std::abs(w) : HUGE_VAL;

  // The integrand τ·source·e^(−(t − t(a))) per bin at s, given the column from a to s;
  // the factor ω0·e^(−t(a)) is applied at the end.
  // With several terms (the Fourier terms of the multiple-scattering source), `mean` is
  // that of Σ_t |term|, which bounds the light of any azimuth, and so paces the steps.
  struct Sample {
    std::array<std::array<double, kSpectralBins>, kMaxIntegrated> f{};
    double mean = 0, tau_mean = 0;
  };
  std::array<Spectrum, kMaxIntegrated> j;
  auto sample = [&](double s, double column_from_a) {
    Sample out;
    const double z = std::clamp(z_p + w * s, fog_.bottom_m(), fog_.top_m());
    const double rho = fog_.density(z);
    source_terms(z, -w, j.data());  // the light travels toward the viewpoint
    for (int i = 0; i < kSpectralBins; ++i) {
      const double sg = sigma[static_cast<size_t>(i)];
      const double tau = std::min(sg * rho, 1e30);  // no Inf·0 for absurd densities
      const double along = tau * std::exp(-std::min(sg * column_from_a, 800.0));
      for (int t = 0; t < terms; ++t) {
        const double v = along * j[static_cast<size_t>(t)][i];
        out.f[static_cast<size_t>(t)][static_cast<size_t>(i)] = v;
        if (t < paced) out.mean += std::abs(v);
      }
    }
    out.mean /= kSpectralBins;
    out.tau_mean = std::min(sigma_mean * rho, 1e30);
    return out;
  };

  std::array<std::array<double, kSpectralBins>, kMaxIntegrated> sum{};
  double s = a;
  Sample f0 = sample(a, 0.0);
  int n = 0;
  while (n < kMaxSteps) {
    // Eq. 14: ds = ds0/(τ J e^(−t)), ds0 = kPitchScale·max J, within [ds_min, ds_max].
    double ds = f0.mean > 0.0 ? kPitchScale * j_max_mean_ / f0.mean : HUGE_VAL;
    if (f0.tau_mean > 0.0) ds = std::min(ds, kAttenuationPitch / f0.tau_mean);
    ds = std::max(std::min(ds, geometric_max), kMinPitchM);
    if (!std::isfinite(ds)) {
      if (!std::isfinite(b)) break;  // no fog on an endless level ray: nothing more to add
      ds = b - s;
    }
    const double s1 = std::min(s + ds, b);
    const double column = fog_.column(z_p, w, a, s1);
    const Sample f1 = sample(s1, column);
    for (size_t t = 0; t < static_cast<size_t>(terms); ++t)
      for (size_t i = 0; i < kSpectralBins; ++i) sum[t][i] += 0.5 * (s1 - s) * (f0.f[t][i] + f1.f[t][i]);
    ++n;
    s = s1;
    f0 = f1;
    if (!(s < b)) break;
    // Termination (Eq. 14's test made safe): what the rest of the span can still add,
    // ∫_s^b τ J e^(−t) ≤ J_max·e^(−(t(s) − t(a)))·(1 − e^(−(t(b) − t(s)))), is below
    // kTailTolerance of what is summed, in every bin.
    // (FogLayer::column of a level ray to s = +∞ is NaN, 0·∞ in its rise: an endless rest
    // is taken as opaque.)
    double rest_column = std::isfinite(b) ? fog_.column(z_p, w, s, b) : kOpaqueColumnM;
    if (std::isnan(rest_column)) rest_column = kOpaqueColumnM;
    bool done = true;
    for (size_t i = 0; i < kSpectralBins && done; ++i) {
      const double sg = sigma[i];
      const double rest =
          j_max_[i] * std::exp(-std::min(sg * column, 800.0)) * -std::expm1(-std::min(sg * rest_column, 800.0));
      double summed = 0;
      for (size_t t = 0; t < static_cast<size_t>(paced); ++t) summed += std::abs(sum[t][i]);
      done = rest <= kTailTolerance * summed;
    }
    if (done) break;
  }
  if (steps) *steps = n;

  const double viewer_column = fog_.column(z_p, w, 0.0, a);
  for (int i = 0; i < kSpectralBins; ++i) {
    const double sg = sigma[static_cast<size_t>(i)];
    const double factor = albedo * std::exp(-std::min(sg * viewer_column, 800.0));
    for (size_t t = 0; t < static_cast<size_t>(terms); ++t) {
      const double v = factor * sum[t][static_cast<size_t>(i)];
      out[t][i] = static_cast<float>(std::isfinite(v) ? v : 0.0);
    }
  }
}

double FogSkyLight::relative_azimuth(const Vec3& dir) const {
  const double x = dot(dir, sun_horizontal_), y = dot(dir, sun_horizontal_side_);
  return x == 0 && y == 0 ? 0.0 : std::atan2(y, x);
}

Spectrum FogSkyLight::in_scattered(const Vec3& viewpoint, const Vec3& dir, double s_begin, double s_end,
                                   int* steps) const {
  Spectrum out;
  if (!diffuse_) {
    integrate(
        viewpoint, dir, s_begin, s_end, 1, 1, [this](double z, double up, Spectrum* j) { *j = source(z, up, 0.0); },
        &out, steps);
    return out;
  }
  return weighed_for_azimuth(viewpoint, dir, s_begin, s_end, &FogDiffuseField::scattered_terms, steps);
}

Spectrum FogSkyLight::weighed_for_azimuth(const Vec3& viewpoint, const Vec3& dir, double s_begin, double s_end,
                                          FieldTerms field_terms, int* steps) const {
  // A straight ray keeps its azimuth: the terms are weighed once for it.
  const FogDiffuseField::AzimuthTerms weights = FogDiffuseField::azimuth_terms(relative_azimuth(dir));
  std::array<Spectrum, FogDiffuseField::kModes> terms;
  Spectrum out(0.0f);
  integrate(
      viewpoint, dir, s_begin, s_end, 1, 1,
      [&](double z, double up, Spectrum* j) {
        ((*diffuse_).*field_terms)(z, up, terms);
        Spectrum sum(0.0f);
        add_azimuth_weighted(sum, terms.data(), FogDiffuseField::kModes, weights.data(), 1.0f);
        for (int b = 0; b < kSpectralBins; ++b) sum[b] = std::max(sum[b], 0.0f);
        *j = sum;
      },
      &out, steps);
  return out;
}

int FogSkyLight::in_scattered_terms(const Vec3& viewpoint, const Vec3& dir, double s_begin, double s_end,
                                    Spectrum* terms, Spectrum* sun_side) const {
  if (!diffuse_) {
    integrate(
        viewpoint, dir, s_begin, s_end, 1, 1, [this](double z, double up, Spectrum* j) { *j = source(z, up, 0.0); },
        terms, nullptr);
    return 1;
  }
  constexpr int kModes = FogDiffuseField::kModes;
  // The sun-side terms ride along in the same steps, which the source's terms alone pace
  // (so that the source's integral is the same with or without them).
  const bool both = sun_side != nullptr && has_sun_side();
  std::array<Spectrum, kModes> field_terms;
  std::array<Spectrum, 2 * kModes> out;
  integrate(
      viewpoint, dir, s_begin, s_end, both ? 2 * kModes : kModes, kModes,
      [&](double z, double up, Spectrum* j) {
        diffuse_->scattered_terms(z, up, field_terms);
        std::copy(field_terms.begin(), field_terms.end(), j);
        if (!both) return;
        diffuse_->sun_side_terms(z, up, field_terms);
        std::copy(field_terms.begin(), field_terms.end(), j + kModes);
      },
      out.data(), nullptr);
  std::copy_n(out.begin(), kModes, terms);
  if (both) std::copy_n(out.begin() + kModes, kModes, sun_side);
  return kModes;
}

Spectrum FogSkyLight::sun_side_in_scattered(const Vec3& viewpoint, const Vec3& dir, double s_begin,
                                            double s_end) const {
  if (!has_sun_side()) return Spectrum(0.0f);
  return weighed_for_azimuth(viewpoint, dir, s_begin, s_end, &FogDiffuseField::sun_side_terms, nullptr);
}

}  // namespace skylit
