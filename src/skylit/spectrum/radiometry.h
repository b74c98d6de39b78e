// Spectral radiometric quantities as distinct types, so that a radiance cannot be added
// to an irradiance, nor a transmittance passed where a radiance is meant, without the
// compiler saying so (after Bruneton's dimension-typed atmosphere, 2017).
//
//   Radiance       W m⁻² sr⁻¹ nm⁻¹  light along a ray
//   Irradiance     W m⁻² nm⁻¹       light arriving on a surface (or normal to a beam)
//   Reflectance    1                a surface's share (albedo, Fresnel reflectance)
//   Transmittance  1                a medium's share along a path
//
// Only the products with a physical meaning exist: a radiance or irradiance times a
// transmittance or reflectance keeps its unit; irradiance becomes radiance only through
// a named conversion (lambertian_radiance, CosineWeightedBrdf). Each type holds a Spectrum, read
// with spectrum() where generic code (colour, tables) needs the numbers.
#pragma once

#include "skylit/core/angles.h"
#include "skylit/spectrum/spectrum.h"

namespace skylit {

template <typename Unit>
class SpectralQuantity {
 public:
  constexpr SpectralQuantity() = default;
  constexpr explicit SpectralQuantity(const Spectrum& values) : values_(values) {}
  constexpr explicit SpectralQuantity(float constant) : values_(constant) {}

  constexpr const Spectrum& spectrum() const { return values_; }
  constexpr float operator[](int bin) const { return values_[bin]; }
  float max_value() const { return values_.max_value(); }
  double mean_value() const { return values_.mean_value(); }
  bool is_black() const { return values_.is_black(); }

  SpectralQuantity& operator+=(const SpectralQuantity& o) {
    values_ += o.values_;
    return *this;
  }
  SpectralQuantity& operator-=(const SpectralQuantity& o) {
    values_ -= o.values_;
    return *this;
  }
  SpectralQuantity& operator*=(float scale) {
    values_ *= scale;
    return *this;
  }

  friend SpectralQuantity operator+(SpectralQuantity a, const SpectralQuantity& b) { return a += b; }
  friend SpectralQuantity operator-(SpectralQuantity a, const SpectralQuantity& b) { return a -= b; }
  friend SpectralQuantity operator*(SpectralQuantity a, float scale) { return a *= scale; }
  friend SpectralQuantity operator*(float scale, SpectralQuantity a) { return a *= scale; }

 private:
  Spectrum values_;
};

namespace units {
struct Radiance;
struct Irradiance;
struct Reflectance;
struct Transmittance;
}  // namespace units

using Radiance = SpectralQuantity<units::Radiance>;
using Irradiance = SpectralQuantity<units::Irradiance>;
using Reflectance = SpectralQuantity<units::Reflectance>;
using Transmittance = SpectralQuantity<units::Transmittance>;

// A dimensionless share applied to light keeps the light's unit.
template <typename Unit>
concept LightUnit = std::same_as<Unit, units::Radiance> || std::same_as<Unit, units::Irradiance>;
template <typename Unit>
concept ShareUnit = std::same_as<Unit, units::Reflectance> || std::same_as<Unit, units::Transmittance>;

template <LightUnit Light, ShareUnit Share>
SpectralQuantity<Light> operator*(const SpectralQuantity<Light>& light, const SpectralQuantity<Share>& share) {
  return SpectralQuantity<Light>(light.spectrum() * share.spectrum());
}
template <LightUnit Light, ShareUnit Share>
SpectralQuantity<Light> operator*(const SpectralQuantity<Share>& share, const SpectralQuantity<Light>& light) {
  return light * share;
}
template <ShareUnit Share>
SpectralQuantity<Share> operator*(const SpectralQuantity<Share>& a, const SpectralQuantity<Share>& b) {
  return SpectralQuantity<Share>(a.spectrum() * b.spectrum());
}
template <LightUnit Light, ShareUnit Share>
SpectralQuantity<Light>& operator*=(SpectralQuantity<Light>& light, const SpectralQuantity<Share>& share) {
  return light = light * share;
}
template <ShareUnit Share>
SpectralQuantity<Share>& operator*=(SpectralQuantity<Share>& a, const SpectralQuantity<Share>& b) {
  return a = a * b;
}

// A BRDF times the incidence cosine, f(l, v) (n·l) (sr⁻¹), for one pair of directions:
// what turns light arriving from l into radiance leaving toward v. From a beam's
// irradiance measured normal to it (the sun, a lamp): f cos θ_l E; from radiance L
// arriving within a small solid angle dω: f cos θ_l L dω.
struct CosineWeightedBrdf {
  Spectrum per_sr;
  Radiance reflect(const Irradiance& normal_irradiance) const {
    return Radiance(per_sr * normal_irradiance.spectrum());
  }
  Radiance reflect(const Radiance& incoming, double solid_angle) const {
    return Radiance(per_sr * incoming.spectrum() * static_cast<float>(solid_angle));
  }
};

// The radiance a Lambertian surface of this albedo sends back under irradiance E: ρE/π.
inline Radiance lambertian_radiance(const Reflectance& albedo, const Irradiance& irradiance) {
  return Radiance(albedo.spectrum() * irradiance.spectrum() * static_cast<float>(1.0 / kPi));
}

}  // namespace skylit
