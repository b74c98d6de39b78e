// daylight_glare_probability and Guth's position index (glare.h).
#include "skylit/assess/glare.h"

#include <algorithm>
#include <cmath>

#include "skylit/core/angles.h"

namespace skylit {

double guth_position_index(double sigma, double tau) {
  const double p = std::exp((35.2 - 0.31889 * tau - 1.22 * std::exp(-2 * tau / 9)) * 1e-3 * sigma +
                            (21 + 0.26667 * tau - 0.002963 * tau * tau) * 1e-5 * sigma * sigma);
  return std::min(p, 16.0);
}

GlareResult daylight_glare_probability(const XyzImage& image, const ImageCamera& camera) {
  const Ray axis = camera.ray_through(image.width / 2.0, image.height / 2.0);
  const Vec3 forward = axis.direction;
  // The image's up and right, from the rays just above and right of the centre.
  const Vec3 up = normalize(camera.ray_through(image.width / 2.0, image.height / 2.0 - 1).direction - forward);
  const Vec3 right = normalize(cross(forward, up));

  struct Pixel {
    double luminance, solid_angle, cos_theta;
    Vec3 direction;
  };
  std::vector<Pixel> pixels;
  double luminous_sum = 0, solid_angle_sum = 0, e_v = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      if (!camera.sees(x + 0.5, y + 0.5)) continue;
      const Vec3 d = camera.ray_through(x + 0.5, y + 0.5).direction;
      const double cos_theta = dot(d, forward);
      const double l = image.at(x, y).y;
      if (!(cos_theta > 0) || !std::isfinite(l)) continue;
      const double omega = camera.pixel_solid_angle(x + 0.5, y + 0.5);
      pixels.push_back({std::max(0.0, l), omega, cos_theta, d});
      luminous_sum += std::max(0.0, l) * omega;
      solid_angle_sum += omega;
      e_v += std::max(0.0, l) * omega * cos_theta;
    }
  GlareResult r;
  r.vertical_illuminance_lx = e_v;
  r.mean_luminance = solid_angle_sum > 0 ? luminous_sum / solid_angle_sum : 0;
  const double threshold = kGlareSourceFactor * r.mean_luminance;
  double sum = 0, source_luminous = 0;
  for (const Pixel& p : pixels) {
    if (!(p.luminance > threshold) || !(e_v > 0)) continue;
    const double sigma = degrees(std::acos(std::clamp(p.cos_theta, -1.0, 1.0)));
    const double tau = degrees(std::atan2(std::abs(dot(p.direction, right)), std::abs(dot(p.direction, up))));
    const double position = guth_position_index(sigma, tau);
    sum += p.luminance * p.luminance * p.solid_angle / (std::pow(e_v, 1.87) * position * position);
    r.source_solid_angle_sr += p.solid_angle;
    source_luminous += p.luminance * p.solid_angle;
  }
  r.source_mean_luminance = r.source_solid_angle_sr > 0 ? source_luminous / r.source_solid_angle_sr : 0;
  r.dgp = std::min(1.0, 5.87e-5 * e_v + 9.18e-2 * std::log10(1 + sum) + 0.16);
  return r;
}

}  // namespace skylit
