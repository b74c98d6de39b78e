#include "skylit/render/fog_medium.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <tbb/parallel_for.h>

#include "skylit/geometry/intervals.h"
#include "skylit/media/fog_sun_integral.h"

namespace skylit {

namespace {
constexpr double kLongestRayM = 50e3;  // level rays inside the layer: far enough to be opaque
}

double FogMedium::row_elevation(int row) {
  const double u = 2.0 * row / (kElevationRows - 1) - 1.0;  // −1 … 1
  return 0.5 * kPi * u * std::abs(u);
}

FogMedium::FogMedium(const FogSettings& settings, const std::vector<const TriangleMesh*>& meshes,
                     const RayTracer& tracer, const SkyModel& sky, const Vec3& camera)
    : layer_(settings),
      to_sun_(sky.to_sun()),
      sun_above_fog_(sky.direct_sun(std::max(0.0, layer_.top_m())).spectrum()),
      shadows_(meshes, sky.to_sun()),
      sky_light_(layer_, sky),
      min_sigma_(*std::min_element(layer_.unit_density_extinction_bins().begin(),
                                   layer_.unit_density_extinction_bins().end())),
      camera_(camera),
      row_length_(kElevationRows),
      row_depth_(static_cast<size_t>(kElevationRows * (kDistanceSlices + 1))) {
  if (const FogDiffuseField* field = sky_light_.diffuse_field()) {
    shadowed_sunlight_ =
        std::make_unique<FogShadowedSunlight>(layer_, *field, shadows_, tracer, to_sun_, sun_above_fog_);
    surface_light_ = std::make_unique<FogSurfaceLight>(sky_light_);
    behind_ = std::make_unique<FogBehindSurfaces>(layer_, *field, -to_sun_);
  }
  // The multiple-scattering source has azimuthal terms: the table keeps each one.
  std::array<Spectrum, FogSkyLight::kMaxTerms> probe;
  terms_ = sky_light_.in_scattered_terms(camera_, Vec3{1, 0, 0}, 0.0, 0.0, probe.data());
  row_inscatter_.assign(row_depth_.size() * static_cast<size_t>(terms_), Spectrum(0.0f));
  // The sun-side light is kept only where a sun lights the fog (none at night, or with
  // the sun hidden by the earth's air at the layer's top), so a ray needs only ask
  // whether the table is there.
  const bool sun_side = sky_light_.has_sun_side() && !sun_above_fog_.is_black();
  if (sun_side) row_sun_side_.assign(row_inscatter_.size(), Spectrum(0.0f));
  const Spectrum& open = sky_light_.unattenuated();
  for (int i = 0; i < kShareAltitudes; ++i) {
    const double z = layer_.bottom_m() + (layer_.top_m() - layer_.bottom_m()) * i / (kShareAltitudes - 1);
    const Spectrum j = sky_light_.at(z);
    Spectrum share;
    for (int k = 0; k < kSpectralBins; ++k) share[k] = open[k] > 0 ? std::min(1.0f, j[k] / open[k]) : 1.0f;
    sky_share_.push_back(share);
  }
  tbb::parallel_for(0, kElevationRows, [&](int row) {
    const double e = row_elevation(row);
    const Vec3 dir{std::cos(e), 0.0, std::sin(e)};
    const RaySpan inside = layer_.clip(camera_.z, dir.z, 0.0, kLongestRayM);
    const double length = inside.empty() ? 0.0 : inside.hi;
    row_length_[static_cast<size_t>(row)] = length;
    std::array<Spectrum, FogSkyLight::kMaxTerms> sum, piece, sun_side_sum, sun_side_piece;
    sum.fill(Spectrum(0.0f));
    sun_side_sum.fill(Spectrum(0.0f));
    double previous = 0.0;
    for (int k = 0; k <= kDistanceSlices; ++k) {
      const double u = static_cast<double>(k) / kDistanceSlices;
      const double d = length * u * u;
      if (d > previous) {
        sky_light_.in_scattered_terms(camera_, dir, previous, d, piece.data(),
                                      sun_side ? sun_side_piece.data() : nullptr);
        for (int t = 0; t < terms_; ++t) sum[static_cast<size_t>(t)] += piece[static_cast<size_t>(t)];
        if (sun_side)
          for (int t = 0; t < terms_; ++t)
            sun_side_sum[static_cast<size_t>(t)] += sun_side_piece[static_cast<size_t>(t)];
      }
      previous = d;
      const size_t at = static_cast<size_t>(row * (kDistanceSlices + 1) + k);
      std::copy_n(sum.begin(), terms_, row_inscatter_.begin() + static_cast<std::ptrdiff_t>(at) * terms_);
      if (sun_side)
        std::copy_n(sun_side_sum.begin(), terms_, row_sun_side_.begin() + static_cast<std::ptrdiff_t>(at) * terms_);
      row_depth_[at] = clearest_depth(dir.z, d);
    }
  });
}

double FogMedium::clearest_depth(double z_v, double distance) const {
  return min_sigma_ * layer_.column(camera_.z, z_v, 0.0, distance);
}

FogMedium::CameraRay FogMedium::camera_ray(const Vec3& direction) const {
  CameraRay out{};
  out.azimuth_weights[0] = 1.0f;
  if (terms_ > 1) {
    const FogDiffuseField::AzimuthTerms cosines =
        FogDiffuseField::azimuth_terms(sky_light_.relative_azimuth(direction));
    std::copy_n(cosines.begin(), terms_, out.azimuth_weights.begin());
  }
  const double elevation = std::asin(std::clamp(direction.z, -1.0, 1.0));
  const double u = std::clamp(elevation / (0.5 * kPi), -1.0, 1.0);
  const double f = (std::copysign(std::sqrt(std::abs(u)), u) + 1.0) * 0.5 * (kElevationRows - 1);
  out.row = std::min(static_cast<int>(f), kElevationRows - 2);
  out.upper = static_cast<float>(f - out.row);
  return out;
}

Spectrum FogMedium::from_camera(const CameraRay& ray, double distance, double depth,
                                const std::vector<Spectrum>& table) const {
  // On row r: the slice at or before `distance` and the weight of the next one.
  struct Slices {
    size_t first;
    float next;
  };
  auto slices_on = [&](int r) -> Slices {
    const double length = row_length_[static_cast<size_t>(r)];
    const size_t first = static_cast<size_t>(r * (kDistanceSlices + 1));
    if (length <= 0) return {first, 0.0f};
    if (distance >= length) return {first + kDistanceSlices, 0.0f};
    const double s = std::sqrt(distance / length) * kDistanceSlices;
    const int k = std::min(static_cast<int>(s), kDistanceSlices - 1);
    const size_t at = first + static_cast<size_t>(k);
    // Linear in the fog's transmittance e^−τ between the two slices around it: the
    // light gathered grows as 1 − e^−τ, exactly so where the fog and its sources are
    // uniform (a level ray), so a dense fog that saturates within the first slices is
    // read right. Linear in distance where the slices hold no fog.
    const double depth0 = row_depth_[at], depth1 = row_depth_[at + 1];
    double t;
    if (depth1 - depth0 > 1e-9) {
      const double within = std::clamp(depth, depth0, depth1);
      t = std::expm1(-(within - depth0)) / std::expm1(-(depth1 - depth0));
    } else {
      const double d0 = length * k * k / (kDistanceSlices * kDistanceSlices);
      const double d1 = length * (k + 1) * (k + 1) / (kDistanceSlices * kDistanceSlices);
      t = (distance - d0) / (d1 - d0);
    }
    return {at, static_cast<float>(std::clamp(t, 0.0, 1.0))};
  };
  const Slices lower = slices_on(ray.row), upper = slices_on(ray.row + 1);
  // The four slices around the ray, their terms weighed by cos(mφ), summed bin by bin in
  // one pass over each slice's terms (this is read for every view ray).
  Spectrum v(0.0f);
  auto add = [&](size_t slice, float weight) {
    if (weight == 0.0f) return;
    add_azimuth_weighted(v, &table[slice * static_cast<size_t>(terms_)], terms_, ray.azimuth_weights.data(), weight);
  };
  add(lower.first, (1 - ray.upper) * (1 - lower.next));
  add(lower.first + 1, (1 - ray.upper) * lower.next);
  add(upper.first, ray.upper * (1 - upper.next));
  add(upper.first + 1, ray.upper * upper.next);
  for (int b = 0; b < kSpectralBins; ++b) v[b] = std::max(v[b], 0.0f);  // a truncated series may dip below 0
  return v;
}

FogMedium::Along FogMedium::along(const Ray& ray, double distance) const {
  // Only the part of the ray inside the layer matters; an infinite ray (the sky) leaves
  // the layer within a finite distance unless it runs level inside it.
  const double end = std::isfinite(distance) ? distance : std::numeric_limits<double>::max();
  const RaySpan inside = layer_.clip(ray.origin.z, ray.direction.z, 0.0, end);
  Along out;
  if (inside.empty()) return out;
  const double column = layer_.column(ray.origin.z, ray.direction.z, inside.lo, inside.hi);
  // Where the fog hides the rest: at kSeenDepth in the clearest bin, the column taken as
  // spread evenly along the piece (exact for a level ray; elsewhere only where the rest
  // is hidden anyway).
  const double clearest = column * min_sigma_;
  const double seen =
      clearest > kSeenDepth ? inside.lo + (inside.hi - inside.lo) * (kSeenDepth / clearest) : std::min(inside.hi, end);
  out.entry_distance = inside.lo;
  out.seen_distance = seen;
  if (seen < inside.hi) {
    out.near.transmittance =
        Transmittance(layer_.transmittance(layer_.column(ray.origin.z, ray.direction.z, inside.lo, seen)));
    out.beyond = Transmittance(layer_.transmittance(layer_.column(ray.origin.z, ray.direction.z, seen, inside.hi)));
  } else {
    out.near.transmittance = Transmittance(layer_.transmittance(column));
  }
  if (surface_light_ && std::isfinite(distance)) {
    const Transmittance through = out.near.transmittance * out.beyond;  // the fog's alone, so far
    const Transmittance gain = Transmittance(layer_.transmittance(sky_light_.sun_depth_scale() * column)) - through;
    if (gain.max_value() > 1e-4) {  // below, nothing visible changes: no look-up of the field
      out.forward_gain = gain;
      out.open_radiance = Radiance(sky_light_.diffuse_field()->radiance_without_sun(
          ray.origin.z + ray.direction.z * distance, -ray.direction.z, sky_light_.relative_azimuth(ray.direction)));
    }
  }
  Spectrum in_scattered(0.0f);
  const double inside_end = std::min(inside.hi, 1e12);  // where the light along it ends
  // Sunlight, only where the view ray is in sunlight: the beams between the shadows.
  std::vector<Interval> lit_parts;
  if (to_sun_.z > 0 && !sun_above_fog_.is_black()) {
    lit_parts = shadows_.sunlit_intervals(ray, inside.lo, inside_end);
    for (const Interval& lit : lit_parts) {
      in_scattered += fog_sun_inscatter(layer_, ray.origin, ray.direction, to_sun_, lit.begin, lit.end, sun_above_fog_,
                                        sky_light_.sun_depth_scale());
    }
  }
  // Sky light, everywhere along it (the paper's assumption: no shadows for sky light);
  // from the camera's table when the ray starts there.
  // With multiple scattering, less the field's light from the sun's side over the parts
  // in the buildings' shadows (nothing to read for a ray in sunlight throughout).
  std::optional<CameraRay> camera;
  if (ray.origin == camera_) {
    camera = camera_ray(ray.direction);
    in_scattered += from_camera(*camera, std::min(distance, kLongestRayM), min_sigma_ * column, row_inscatter_);
  } else {
    in_scattered += sky_light_.in_scattered(ray.origin, ray.direction, inside.lo, inside_end);
  }
  if (!row_sun_side_.empty()) {
    complement_of_union(inside.lo, inside_end, 0.0, lit_parts);  // now the parts in shadow
    if (!lit_parts.empty()) {
      in_scattered -= sun_side_light_in_shadow(ray, lit_parts, inside.lo, camera ? &*camera : nullptr);
      for (int b = 0; b < kSpectralBins; ++b) in_scattered[b] = std::max(in_scattered[b], 0.0f);
    }
  }
  out.near.in_scattered = Radiance(in_scattered);
  return out;
}

Spectrum FogMedium::sun_side_light_in_shadow(const Ray& ray, const std::vector<Interval>& shadowed, double begin,
                                             const CameraRay* camera) const {
  Spectrum out(0.0f);
  // The camera's table gathered from the camera to s: nothing before the layer.
  auto cumulative = [&](double s) {
    if (s <= begin) return Spectrum(0.0f);
    const double to = std::min(s, kLongestRayM);
    return from_camera(*camera, to, min_sigma_ * layer_.column(ray.origin.z, ray.direction.z, 0.0, to), row_sun_side_);
  };
  for (const Interval& part : shadowed) {
    if (camera)
      out += cumulative(part.end) - cumulative(part.begin);
    else
      out += sky_light_.sun_side_in_scattered(ray.origin, ray.direction, part.begin, part.end);
  }
  for (int b = 0; b < kSpectralBins; ++b) out[b] = std::max(out[b], 0.0f);
  return out;
}

FogHiddenBehind FogMedium::hidden_behind(const Ray& ray, double distance, const Vec3& normal, double extent_m) const {
  if (!behind_ || !std::isfinite(distance)) return {};
  const RaySpan inside = layer_.clip(ray.origin.z, ray.direction.z, 0.0, distance);
  if (inside.empty()) return {};
  return behind_->at(ray.origin + ray.direction * distance, normal, -ray.direction,
                     layer_.column(ray.origin.z, ray.direction.z, inside.lo, inside.hi), inside.hi - inside.lo,
                     extent_m);
}

Transmittance FogMedium::sun_transmittance(const Vec3& point) const {
  if (to_sun_.z <= 0) return Transmittance(0.0f);
  return Transmittance(layer_.transmittance(layer_.sun_column(point.z, to_sun_.z)));
}

Transmittance FogMedium::sun_beam_transmittance(const Vec3& point) const {
  if (to_sun_.z <= 0) return Transmittance(0.0f);
  return Transmittance(layer_.transmittance(sky_light_.sun_depth_scale() * layer_.sun_column(point.z, to_sun_.z)));
}

Transmittance FogMedium::sky_light_share(double z) const {
  if (z >= layer_.top_m()) return Transmittance(1.0f);
  const double f =
      std::clamp((z - layer_.bottom_m()) / (layer_.top_m() - layer_.bottom_m()), 0.0, 1.0) * (kShareAltitudes - 1);
  const int i = std::min(static_cast<int>(f), kShareAltitudes - 2);
  const float w = static_cast<float>(f - i);
  return Transmittance(sky_share_[static_cast<size_t>(i)] * (1 - w) + sky_share_[static_cast<size_t>(i + 1)] * w);
}

}  // namespace skylit
