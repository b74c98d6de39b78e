// The cone tree (render/cone_tree.h): box_in_cone never refuses a box one of whose
// points lies within the cone (checked by sampling the boxes), and the tree visits
// exactly the items the one-by-one test accepts, in a fixed order.
#include "skylit/render/cone_tree.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <vector>

namespace skylit {
namespace {

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  return normalize(Vec3{g(rng), g(rng), g(rng)});
}

BoxCone random_item(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  BoxCone item;
  const Vec3 lo{u(rng) * 100 - 50, u(rng) * 100 - 50, u(rng) * 30};
  // Flat boxes too (a facet's), up to a few metres across.
  const Vec3 size{u(rng) * 4, u(rng) < 0.3 ? 0.0 : u(rng) * 4, u(rng) * 4};
  item.box.add(lo);
  item.box.add(lo + size);
  item.axis = random_unit(rng);
  item.cos_spread = std::cos(u(rng) < 0.2 ? 0.0 : u(rng) * 1.2);  // mirrors' 0 to 69°
  return item;
}

TEST(ConeTree, BoxInConeNeverRefusesAPointInTheCone) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  int sampled_inside = 0, refused = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const BoxCone item = random_item(rng);
    const Vec3 origin{u(rng) * 140 - 70, u(rng) * 140 - 70, u(rng) * 40};
    if (box_in_cone(origin, item, 0)) continue;
    ++refused;
    // Refused: no point of the box may lie within the cone.
    const Vec3 size = item.box.size();
    for (int k = 0; k < 200; ++k) {
      const Vec3 p = item.box.lo + Vec3{u(rng) * size.x, u(rng) * size.y, u(rng) * size.z};
      const Vec3 d = p - origin;
      const bool inside = dot(d, item.axis) >= item.cos_spread * length(d) - 1e-12;
      sampled_inside += inside ? 1 : 0;
      ASSERT_FALSE(inside) << "trial " << trial;
    }
  }
  EXPECT_EQ(sampled_inside, 0);
  EXPECT_GT(refused, 1500);  // the test refuses most (the cones are narrow): it is exercised
}

TEST(ConeTree, VisitsExactlyTheItemsTheOneByOneTestAccepts) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<BoxCone> items;
  for (int i = 0; i < 5000; ++i) items.push_back(random_item(rng));
  const ConeTree tree(items, 1e-3);
  size_t visited_total = 0;
  for (int q = 0; q < 200; ++q) {
    const Vec3 origin{u(rng) * 140 - 70, u(rng) * 140 - 70, u(rng) * 40};
    std::vector<size_t> visited;
    tree.visit(origin, [&](size_t i) { visited.push_back(i); });
    std::set<size_t> expected;
    for (size_t i = 0; i < items.size(); ++i)
      if (box_in_cone(origin, items[i], 1e-3)) expected.insert(i);
    EXPECT_EQ(std::set<size_t>(visited.begin(), visited.end()), expected) << "query " << q;
    EXPECT_EQ(visited.size(), expected.size()) << "each item once";
    visited_total += visited.size();
    std::vector<size_t> again;
    tree.visit(origin, [&](size_t i) { again.push_back(i); });
    EXPECT_EQ(again, visited);  // a fixed order
  }
  EXPECT_GT(visited_total, 0u);
}

}  // namespace
}  // namespace skylit
