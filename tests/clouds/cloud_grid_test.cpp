// The clouds' uniform grid (issue 19, item 11): a ray's crossings found through the grid
// are exactly those of testing every cloud, for every kind of ray (steep, level, inside
// the layer, from above, vertical, along the grid's lines), so images do not change.
#include <gtest/gtest.h>

#include <random>

#include "skylit/clouds/cloud_layer.h"

namespace skylit {
namespace {

std::vector<CloudLayer::Crossing> every_cloud(const CloudLayer& layer, const Vec3& o, const Vec3& d, double t_min,
                                              double t_max) {
  std::vector<CloudLayer::Crossing> out;
  for (std::size_t i = 0; i < layer.clouds().size(); ++i) {
    double t0, t1;
    if (layer.clouds()[i].clip(o, d, t_min, t_max, t0, t1)) out.push_back({i, t0, t1});
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
    return a.t_enter < b.t_enter || (a.t_enter == b.t_enter && a.index < b.index);
  });
  return out;
}

TEST(CloudGrid, CrossingsAreThoseOfTestingEveryCloud) {
  CloudLayerSettings settings;
  settings.coverage = 0.6;
  settings.half_extent = 3000;
  settings.min_semi_axis = 100;
  settings.max_semi_axis = 600;
  const CloudLayer layer = CloudLayer::generate(settings);
  ASSERT_GT(layer.clouds().size(), 50u);
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> u(-1, 1);
  std::size_t found = 0;
  for (int k = 0; k < 4000; ++k) {
    const int kind = k % 5;
    Vec3 o{4000 * u(random), 4000 * u(random), kind == 2 ? 1500 + 200 * u(random) : (kind == 3 ? 5000 : 1.6)};
    Vec3 d{u(random), u(random), kind == 1 ? 0.05 * u(random) : (kind == 3 ? -1 : std::abs(u(random)))};
    if (kind == 4) d = k % 2 ? Vec3{0, 0, 1} : Vec3{1, 0, 0.2};  // vertical; along a grid line
    d = d / length(d);
    const auto expected = every_cloud(layer, o, d, 0.0, 1e7);
    const auto got = layer.crossings(o, d, 0.0, 1e7);
    ASSERT_EQ(got.size(), expected.size()) << k;
    for (std::size_t i = 0; i < got.size(); ++i) {
      EXPECT_EQ(got[i].index, expected[i].index) << k;
      EXPECT_EQ(got[i].t_enter, expected[i].t_enter) << k;
      EXPECT_EQ(got[i].t_exit, expected[i].t_exit) << k;
    }
    found += got.size();
  }
  EXPECT_GT(found, 1000u);  // the rays do meet clouds: the comparison is not of empty lists
}

}  // namespace
}  // namespace skylit
