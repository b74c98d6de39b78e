// A set of clouds (cloud.h): given explicitly, or generated from a coverage fraction and
// a seed. Generation is reproducible everywhere: std::mt19937_64's sequence is fixed by
// the C++ standard, and its integers are turned into uniform doubles here (not by
// std::uniform_real_distribution, whose algorithm each library chooses).
//
// Ray queries test each cloud's bounding volume (clouds are few: hundreds at most) and
// return the crossings in order along the ray.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "skylit/clouds/cloud.h"

namespace skylit {

struct CloudLayerSettings {
  double altitude = 1500;  // mid-plane, m
  double coverage = 0.3;   // fraction of the sky's area covered, in [0, 1]
  std::uint64_t seed = 1;
  double center_x = 0, center_y = 0;  // the square region covered, m
  double half_extent = 10000;
  double min_semi_axis = 300, max_semi_axis = 1500;  // m, of the larger semi-axis
  double min_aspect = 0.5;                           // smaller/larger semi-axis, up to 1
  double min_thickness = 200, max_thickness = 600;   // T_max range, m
  double extinction = kDefaultCloudExtinction;       // m⁻¹
  int waves = 4;                                     // sine waves per axis (Gardner's series)
  double first_amplitude = 0.3;                      // then ×1/√2 per wave
};

// A uniform double in [0, 1) from the top 53 bits of one draw.
double cloud_uniform(std::uint64_t draw);

// Gardner's (1985) series on both axes of a cloud: the first wave about one per
// semi-axis, each next at twice the frequency and 1/√2 the amplitude, random phases from
// `seed`. For clouds given one by one in a scene.
void add_gardner_waves(CloudShape& shape, std::uint64_t seed, int waves = 4, double first_amplitude = 0.3);

class CloudLayer {
 public:
  CloudLayer() = default;
  explicit CloudLayer(std::vector<Cloud> clouds) : clouds_(std::move(clouds)) {}

  // Clouds with centres uniform in the region widened by max_semi_axis, added until their
  // summed footprint reaches −ln(1 − coverage) times the widened area: for randomly
  // placed clouds (a Boolean model) the covered fraction is then ≈ coverage.
  static CloudLayer generate(const CloudLayerSettings& settings);

  const std::vector<Cloud>& clouds() const { return clouds_; }

  // Cloud::prepare_sun on every cloud (once per scene / sun direction); scatter() with
  // light.to_sun equal to to_sun then interpolates t' instead of marching toward the sun.
  void prepare_sun(const Vec3& to_sun);
  void clear_sun();
  bool empty() const { return clouds_.empty(); }

  struct Crossing {
    std::size_t index;       // into clouds()
    double t_enter, t_exit;  // the ray's part in the cloud's bounding volume
  };
  // Clouds whose bounding volume the ray o + t·d, t in [t_min, t_max], crosses, by t_enter.
  std::vector<Crossing> crossings(const Vec3& o, const Vec3& d, double t_min, double t_max) const;
  // The first cloud along the ray with non-zero optical depth.
  std::optional<Crossing> first_hit(const Vec3& o, const Vec3& d, double t_min, double t_max) const;

  double optical_depth(const Vec3& o, const Vec3& d, double t_min, double t_max) const;
  // e^{−t} from p toward the sun through every cloud: shadows on the ground and buildings.
  double sun_transmittance(const Vec3& p, const Vec3& to_sun) const;

  // Eq. 16 along a viewing ray through all the clouds it crosses, composited front to
  // back (each cloud lit through its own shape only; overlapping bounding volumes are
  // taken one after the other).
  CloudScattering scatter(const Vec3& o, const Vec3& d, double t_min, double t_max, const CloudLighting& light) const;

 private:
  std::vector<Cloud> clouds_;
};

}  // namespace skylit
