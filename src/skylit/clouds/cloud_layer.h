// A set of clouds (cloud.h): given explicitly, or generated from a coverage fraction and
// a seed. Generation is reproducible everywhere: std::mt19937_64's sequence is fixed by
// the C++ standard, and its integers are turned into uniform doubles here (not by
// std::uniform_real_distribution, whose algorithm each library chooses).
//
// Ray queries test the bounding volumes of the clouds a uniform grid over their
// footprints lists along the ray (cloud_grid.h) and return the crossings in order
// along the ray.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "skylit/clouds/cloud.h"
#include "skylit/clouds/cloud_grid.h"

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
  // The share of the sun's and the sky's light that reaches the clouds: 1 lights each
  // cloud as if it were alone.
  double light_share = 1.0;
  // When given (weather hours: the file's diffuse horizontal illuminance, lx), light_share
  // is instead fitted, when the clouds are placed under the scene's sky (CloudsInSky), so
  // that the clouded sky gives the open ground this illuminance on average
  // (docs/weather.md, "Clouds").
  std::optional<double> diffuse_horizontal_lux;
};

// The bounds of a fitted light share: clouds get no more light than the sun and the sky
// send, and at least what a cloud deep in a layer of 95 % cover, under two or three
// others, might (docs/weather.md).
inline constexpr double kLeastCloudLightShare = 0.25, kMostCloudLightShare = 1.0;

// The most clouds a generated layer may hold. Each cloud a view meets builds a sun grid
// (0.4 MB, about 0.1–0.4 s on one core here), so a layer of many more can take many
// minutes at any image size (issue 19, item 11): a scene reader refuses settings whose
// expected count exceeds it, and generate() stops at twice it (the count is random).
inline constexpr std::size_t kMaxGeneratedClouds = 500;

// CloudLayer::scatter takes no cloud behind one that lets less than this through.
inline constexpr double kOpaqueTransmittance = 1e-6;

// How many clouds generate() makes for these settings, on average: the target footprint
// −ln(1 − coverage)·(2·(half_extent + max_semi_axis))² over the mean footprint
// π·E[a²]·E[b/a] of the size distribution.
double expected_generated_cloud_count(const CloudLayerSettings& settings);

// A uniform double in [0, 1) from the top 53 bits of one draw.
double cloud_uniform(std::uint64_t draw);

// Gardner's (1985) series on both axes of a cloud: the first wave about one per
// semi-axis, each next at twice the frequency and 1/√2 the amplitude, random phases from
// `seed`. For clouds given one by one in a scene.
void add_gardner_waves(CloudShape& shape, std::uint64_t seed, int waves = 4, double first_amplitude = 0.3);

class CloudLayer {
 public:
  CloudLayer() = default;
  explicit CloudLayer(std::vector<Cloud> clouds) : clouds_(std::move(clouds)), grid_(clouds_) {}

  // Clouds with centres uniform in the region widened by max_semi_axis, added until their
  // summed footprint reaches −ln(1 − coverage) times the widened area: for randomly
  // placed clouds (a Boolean model) the covered fraction is then ≈ coverage.
  static CloudLayer generate(const CloudLayerSettings& settings);

  const std::vector<Cloud>& clouds() const { return clouds_; }

  // From now on scatter() with light.to_sun equal to to_sun interpolates t' in each
  // cloud's sun grid instead of marching toward the sun. A cloud's grid is made
  // (Cloud::prepare_sun) when the first ray meets it, once, whichever thread asks first,
  // and its nodes marched as look-ups need them (sun_depth_grid.h): a grid costs about
  // 0.4 MB and up to 10^5 marches, and a layer of thousands of clouds of which a view
  // meets a few must not pay for all (issue 19, item 11). The values do not depend on
  // when a node is marched, so neither does the image.
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
  // taken one after the other), up to the first where less than kOpaqueTransmittance of
  // what lies behind shows through.
  CloudScattering scatter(const Vec3& o, const Vec3& d, double t_min, double t_max, const CloudLighting& light) const;

 private:
  // Makes cloud `index`'s sun grid if prepare_sun asked for grids and it has none yet.
  void ensure_sun_grid(std::size_t index) const;

  // Mutable only for the sun grids made on demand, each under its own once_flag.
  mutable std::vector<Cloud> clouds_;
  CloudGrid grid_;
  std::optional<Vec3> grid_sun_;                  // the direction prepare_sun asked for
  std::unique_ptr<std::once_flag[]> grid_built_;  // one per cloud
};

}  // namespace skylit
