// Parameter sweeps (io/sweep.h): `--vary` parsing and its errors, the Cartesian
// product in row-major order, the labels of rows and columns, the overrides of each
// combination and the cell file names.
#include "skylit/figures/sweep.h"

#include <gtest/gtest.h>

#include "../test_support.h"

#include <string>
#include <vector>

#include "skylit/core/error.h"

namespace skylit {
namespace {

using Values = std::vector<std::string>;

std::string error_of(const std::string& argument) {
  return testing::input_error_of([&] { parse_sweep_parameter(argument); });
}

TEST(SweepParameter, SplitsOnCommasAndTrims) {
  const SweepParameter p = parse_sweep_parameter("sun.altitude_deg=17, 60 ,4");
  EXPECT_EQ(p.path, "sun.altitude_deg");
  EXPECT_EQ(p.values, (Values{"17", "60", "4"}));
  EXPECT_EQ(parse_sweep_parameter("materials.walls=tile").values, (Values{"tile"}));
}

TEST(SweepParameter, SplitsOnSemicolonsWhenGiven) {
  const SweepParameter p = parse_sweep_parameter("camera.position=[0,-20,2];[0,-40,2]");
  EXPECT_EQ(p.values, (Values{"[0,-20,2]", "[0,-40,2]"}));
}

TEST(SweepParameter, RejectsMalformedArguments) {
  EXPECT_NE(error_of("sun.altitude_deg").find("--vary sun.altitude_deg: expected PATH=V1,V2"), std::string::npos);
  EXPECT_NE(error_of("sun.altitude_deg=").find("no values"), std::string::npos);
  EXPECT_NE(error_of("=1,2").find("no path"), std::string::npos);
  EXPECT_NE(error_of("a=1,,2").find("an empty value"), std::string::npos);
  EXPECT_NE(error_of("a=1,2,").find("an empty value"), std::string::npos);
}

TEST(SweepPlan, TwoParametersGiveRowsAndColumnsInRowMajorOrder) {
  const SweepPlan plan =
      plan_sweep({{"sun.altitude_deg", {"17", "60", "4"}}, {"materials.walls", {"tile", "aluminium"}}});
  EXPECT_EQ(plan.rows, 3u);
  EXPECT_EQ(plan.columns, 2u);
  EXPECT_EQ(plan.row_labels, (Values{"sun.altitude_deg = 17", "sun.altitude_deg = 60", "sun.altitude_deg = 4"}));
  EXPECT_EQ(plan.column_labels, (Values{"materials.walls = tile", "materials.walls = aluminium"}));
  ASSERT_EQ(plan.combinations.size(), 6u);
  const SweepCombination& c = plan.combinations[3];
  EXPECT_EQ(c.index, 3u);
  EXPECT_EQ(c.row, 1u);
  EXPECT_EQ(c.column, 1u);
  EXPECT_EQ(c.values, (Values{"60", "aluminium"}));
  EXPECT_EQ(sweep_overrides(plan, c), (Values{"sun.altitude_deg=60", "materials.walls=aluminium"}));
  EXPECT_EQ(combination_label(plan, c), "sun.altitude_deg = 60, materials.walls = aluminium");
  for (size_t i = 0; i < plan.combinations.size(); ++i) {
    EXPECT_EQ(plan.combinations[i].index, i);
    EXPECT_EQ(plan.combinations[i].row * plan.columns + plan.combinations[i].column, i);
  }
}

TEST(SweepPlan, OneParameterIsOneUnlabelledRow) {
  const SweepPlan plan = plan_sweep({{"sun.altitude_deg", {"17", "60"}}});
  EXPECT_EQ(plan.rows, 1u);
  EXPECT_EQ(plan.columns, 2u);
  EXPECT_TRUE(plan.row_labels.empty());
  EXPECT_EQ(plan.column_labels, (Values{"sun.altitude_deg = 17", "sun.altitude_deg = 60"}));
  EXPECT_EQ(plan.combinations[1].values, (Values{"60"}));
}

TEST(SweepPlan, MoreParametersJoinTheRowLabels) {
  const SweepPlan plan = plan_sweep({{"a", {"1", "2"}}, {"b", {"x", "y", "z"}}, {"c", {"p", "q"}}});
  EXPECT_EQ(plan.rows, 6u);
  EXPECT_EQ(plan.columns, 2u);
  EXPECT_EQ(plan.row_labels.front(), "a = 1 / b = x");
  EXPECT_EQ(plan.row_labels[1], "a = 1 / b = y");  // the first parameter varies slowest
  EXPECT_EQ(plan.row_labels.back(), "a = 2 / b = z");
  ASSERT_EQ(plan.combinations.size(), 12u);
  EXPECT_EQ(plan.combinations[5].values, (Values{"1", "z", "q"}));
  EXPECT_EQ(plan.combinations[11].values, (Values{"2", "z", "q"}));
}

TEST(SweepPlan, RejectsNoParametersAndRepeatedPaths) {
  EXPECT_THROW(plan_sweep({}), InputError);
  EXPECT_THROW(plan_sweep({{"a", {"1"}}, {"a", {"2"}}}), InputError);
}

TEST(SweepFiles, ValuesBecomeSafeFileNameParts) {
  EXPECT_EQ(file_name_part("17"), "17");
  EXPECT_EQ(file_name_part("-4.5"), "-4.5");
  EXPECT_EQ(file_name_part("aluminium"), "aluminium");
  EXPECT_EQ(file_name_part("[0, -20, 2]"), "0_-20_2");
  EXPECT_EQ(file_name_part("\"a/b\\c\""), "a_b_c");
  EXPECT_EQ(file_name_part("{}"), "v");
  EXPECT_EQ(file_name_part(std::string(50, 'x')).size(), 32u);
}

TEST(SweepFiles, CellsAreNumberedNextToTheSheet) {
  const SweepPlan plan =
      plan_sweep({{"sun.altitude_deg", {"17", "60", "4"}}, {"materials.walls", {"tile", "aluminium"}}});
  EXPECT_EQ(sweep_cell_path("out/fig7.png", plan, plan.combinations[0], ".png"),
            std::filesystem::path("out/fig7_1_17_tile.png"));
  EXPECT_EQ(sweep_cell_path("fig7.png", plan, plan.combinations[5], ".exr"),
            std::filesystem::path("fig7_6_4_aluminium.exr"));
  // Zero-padded to the width of the count, so that names sort in order.
  const SweepPlan big = plan_sweep({{"a", {"1", "2", "3", "4"}}, {"b", {"1", "2", "3"}}});
  EXPECT_EQ(sweep_cell_path("s.png", big, big.combinations[0], ".png"), std::filesystem::path("s_01_1_1.png"));
  EXPECT_EQ(sweep_cell_path("s.png", big, big.combinations[11], ".png"), std::filesystem::path("s_12_4_3.png"));
}

}  // namespace
}  // namespace skylit
