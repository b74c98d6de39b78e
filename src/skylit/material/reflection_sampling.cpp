#include "skylit/material/reflection_sampling.h"

#include <algorithm>
#include <cmath>

#include "skylit/material/microfacet.h"
#include "skylit/material/reflection.h"

namespace skylit {

namespace {

// The glossy lobe's mean Fresnel reflectance at a cosine: about its directional albedo
// where the lobe's half vectors lie near the normal.
double glossy_fresnel_mean(const Material& material, double cos_theta) {
  if (const auto* ct = std::get_if<CookTorranceMaterial>(&material)) return ct->fresnel().mean_at(cos_theta);
  if (const auto* glass = std::get_if<GlassMaterial>(&material)) return glass->reflectance().mean_at(cos_theta);
  return 0;
}

// How likely each lobe is chosen for this view: in proportion to its reflectance,
// estimated from quantities that cost no integration (the glossy lobe by its Fresnel
// factor at normal view of the half vector, which its energy is near for moderate
// roughness). Any positive choice gives an unbiased estimate; a good one, less noise.
struct LobeChoice {
  double diffuse = 0, glossy = 0, mirror = 0;
};

LobeChoice lobe_choice(const Material& material, const Vec3& n, const Vec3& to_viewer) {
  const double cos_view = dot(n, to_viewer);
  LobeChoice c;
  if (cos_view <= 0) return c;
  c.diffuse = diffuse_albedo(material, cos_view).mean_value();
  if (const std::optional<Reflectance> m = mirror_reflectance(material, n, to_viewer)) c.mirror = m->mean_value();
  if (has_specular(material)) c.glossy = std::max(1e-3, glossy_fresnel_mean(material, cos_view));
  const double total = c.diffuse + c.glossy + c.mirror;
  if (total <= 0) return {};
  return {c.diffuse / total, c.glossy / total, c.mirror / total};
}

double beckmann_pdf(const Vec3& n, const Vec3& to_light, const Vec3& to_viewer, double m) {
  Vec3 h = to_light + to_viewer;
  const double len = length(h);
  if (!(len > 0)) return 0;
  h = h / len;
  const double cos_h = dot(n, h), v_dot_h = std::abs(dot(to_viewer, h));
  if (cos_h <= 0 || v_dot_h <= 0) return 0;
  return beckmann_distribution(cos_h, m) * cos_h / (4 * v_dot_h);
}

}  // namespace

void orthonormal_frame(const Vec3& n, Vec3& t, Vec3& b) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z), c = n.x * n.y * a;
  t = {1 + sign * n.x * n.x * a, sign * c, -sign * n.x};
  b = {c, sign + n.y * n.y * a, -n.y};
}

CosineWeightedBrdf reflection_cos(const Material& material, const Vec3& n, const Vec3& to_light,
                                  const Vec3& to_viewer) {
  const double cos_light = dot(n, to_light), cos_view = dot(n, to_viewer);
  if (cos_light <= 0 || cos_view <= 0) return {Spectrum(0.0f)};
  Spectrum out = diffuse_albedo(material, cos_view).spectrum() * static_cast<float>(cos_light / kPi);
  if (has_point_light_lobe(material)) out += point_light_reflection(material, n, to_light, to_viewer).per_sr;
  return {out};
}

namespace {

// The density of to_light through the non-mirror lobes, for the lobes' chances `c`
// (found once per sample, used for the drawing and the density alike).
double mixture_pdf(const LobeChoice& c, const Material& material, const Vec3& n, const Vec3& to_light,
                   const Vec3& to_viewer) {
  const double cos_light = dot(n, to_light);
  if (cos_light <= 0) return 0;
  double pdf = c.diffuse * cos_light / kPi;
  if (c.glossy > 0) pdf += c.glossy * beckmann_pdf(n, to_light, to_viewer, specular_roughness(material));
  return pdf;
}

}  // namespace

double reflection_pdf(const Material& material, const Vec3& n, const Vec3& to_light, const Vec3& to_viewer) {
  return mixture_pdf(lobe_choice(material, n, to_viewer), material, n, to_light, to_viewer);
}

std::optional<ReflectionSample> sample_reflection(const Material& material, const Vec3& n, const Vec3& to_viewer,
                                                  double u_lobe, double u1, double u2) {
  const LobeChoice c = lobe_choice(material, n, to_viewer);
  if (c.diffuse + c.glossy + c.mirror <= 0) return std::nullopt;
  if (u_lobe >= c.diffuse + c.glossy) {
    // The mirror: its reflectance over the chance of choosing it.
    const std::optional<Reflectance> r = mirror_reflectance(material, n, to_viewer);
    if (!r) return std::nullopt;
    return ReflectionSample{mirror_direction(n, to_viewer), r->spectrum() * static_cast<float>(1.0 / c.mirror), 0.0,
                            true};
  }
  Vec3 t, b;
  orthonormal_frame(n, t, b);
  Vec3 to_light;
  if (u_lobe < c.diffuse) {
    // Cosine-weighted (Malley's method).
    const double r = std::sqrt(u1), phi = 2 * kPi * u2;
    to_light = r * std::cos(phi) * t + r * std::sin(phi) * b + std::sqrt(std::max(0.0, 1 - u1)) * n;
  } else {
    const double m = specular_roughness(material);
    const double tan2 = -m * m * std::log(1 - u1), cos_h = 1 / std::sqrt(1 + tan2);
    const double sin_h = std::sqrt(std::max(0.0, 1 - cos_h * cos_h)), phi = 2 * kPi * u2;
    const Vec3 h = sin_h * std::cos(phi) * t + sin_h * std::sin(phi) * b + cos_h * n;
    to_light = 2 * dot(to_viewer, h) * h - to_viewer;
  }
  to_light = normalize(to_light);
  const double pdf = mixture_pdf(c, material, n, to_light, to_viewer);
  if (!(pdf > 0)) return ReflectionSample{to_light, Spectrum(0.0f), 0.0, false};
  return ReflectionSample{
      to_light, reflection_cos(material, n, to_light, to_viewer).per_sr * static_cast<float>(1.0 / pdf), pdf, false};
}

}  // namespace skylit
