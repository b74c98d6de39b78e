// Work spread over MPI ranks and over array-job shards writes the same bytes as one
// process (docs/cluster.md): a sweep, an animation and a tiled render, at 40 × 24 or
// smaller with one sample per pixel so that the mpirun start-up (about a second per run
// on the CI machine) is most of the cost. The MPI tests need skylit built with MPI and
// mpirun on PATH; the shard tests always run.
#include <gtest/gtest.h>

#include <cstdlib>
#include <set>

#include "../test_support.h"

namespace skylit {
namespace {

using testing::quoted;
using testing::run_skylit;
using testing::run_skylit_with_env;
using testing::TempDir;

// Runs as root in containers and CI need Open MPI's consent.
constexpr const char* kMpirun = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun -n 2 --oversubscribe";

const char* kSmall = " --set render.width=40 --set render.height=24 --set render.samples_per_axis=2 -q ";

std::string sited_scene() {
  std::string scene = testing::small_scene_json(40, 24);
  const std::string sun = R"("sun": {"altitude_deg": 40, "azimuth_deg": 135},)";
  scene.replace(scene.find(sun), sun.size(),
                R"("site": {"latitude_deg": 52.5, "longitude_deg": 13.4}, "time": "2026-06-21T12:00Z",)");
  return scene;
}

// Every file of `a` is in `b` with the same bytes (b may hold more: the shards' .xyz).
void expect_same_files(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::size_t count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(a)) {
    ++count;
    EXPECT_EQ(testing::read_file(entry.path()), testing::read_file(b / entry.path().filename()))
        << entry.path().filename();
  }
  EXPECT_GT(count, 0u);
}

// Not under AddressSanitizer: LeakSanitizer reports Open MPI's own allocations that it
// keeps until exit, and the ranks would fail for them.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

bool mpi_available() {
#ifdef SKYLIT_TEST_WITH_MPI
  return !kAddressSanitizer && std::system("mpirun --version > /dev/null 2>&1") == 0;
#else
  return false;
#endif
}

TEST(SplitRuns, ShardsMergeIntoTheSameSweepAndAnimation) {
  TempDir dir;
  const auto scene = dir.write("scene.json", sited_scene());
  const std::string sweep =
      "sweep " + quoted(scene) + kSmall + " --vary time=2026-06-21T08:00Z,2026-06-21T12:00Z," + "2026-06-21T16:00Z -o ";
  ASSERT_EQ(run_skylit(sweep + quoted(dir.path() / "one" / "s.png")).exit_status, 0);
  for (const char* shard : {"1/2", "2/2"})
    ASSERT_EQ(run_skylit(sweep + quoted(dir.path() / "sharded" / "s.png") + " --shard " + shard).exit_status, 0);
  const auto merged = run_skylit(sweep + quoted(dir.path() / "sharded" / "s.png") + " --merge");
  ASSERT_EQ(merged.exit_status, 0) << merged.output;
  expect_same_files(dir.path() / "one", dir.path() / "sharded");

  const std::string animate = "animate " + quoted(scene) + kSmall + " --dates 03-21,06-21,12-21 --at 12:00 -o ";
  ASSERT_EQ(run_skylit(animate + quoted(dir.path() / "a1")).exit_status, 0);
  for (const char* shard : {"1/2", "2/2"})
    ASSERT_EQ(run_skylit(animate + quoted(dir.path() / "a2") + " --shard " + shard).exit_status, 0);
  // A merge before every shard has run names what is missing.
  std::filesystem::rename(dir.path() / "a2" / "frame_0002.xyz", dir.path() / "frame_0002.xyz");
  const auto early = run_skylit(animate + quoted(dir.path() / "a2") + " --merge");
  EXPECT_EQ(early.exit_status, 2);
  EXPECT_NE(early.output.find("frame_0002.xyz"), std::string::npos) << early.output;
  std::filesystem::rename(dir.path() / "frame_0002.xyz", dir.path() / "a2" / "frame_0002.xyz");
  ASSERT_EQ(run_skylit(animate + quoted(dir.path() / "a2") + " --merge").exit_status, 0);
  expect_same_files(dir.path() / "a1", dir.path() / "a2");
}

TEST(SplitRuns, TwoMpiRanksWriteTheBytesOfOneProcess) {
  if (!mpi_available()) GTEST_SKIP() << "skylit built without MPI, no mpirun, or under AddressSanitizer";
  TempDir dir;
  const auto scene = dir.write("scene.json", sited_scene());
  const std::string sweep =
      "sweep " + quoted(scene) + kSmall + " --vary time=2026-06-21T08:00Z,2026-06-21T12:00Z," + "2026-06-21T16:00Z -o ";
  ASSERT_EQ(run_skylit(sweep + quoted(dir.path() / "s1" / "s.png")).exit_status, 0);
  const auto s2 = run_skylit_with_env(kMpirun, sweep + quoted(dir.path() / "s2" / "s.png"));
  ASSERT_EQ(s2.exit_status, 0) << s2.output;
  expect_same_files(dir.path() / "s1", dir.path() / "s2");

  const std::string animate = "animate " + quoted(scene) + kSmall + " --dates 03-21,06-21,12-21 --at 12:00 -o ";
  ASSERT_EQ(run_skylit(animate + quoted(dir.path() / "a1")).exit_status, 0);
  ASSERT_EQ(run_skylit_with_env(kMpirun, animate + quoted(dir.path() / "a2")).exit_status, 0);
  expect_same_files(dir.path() / "a2", dir.path() / "a1");

  // 40 × 24 is two tiles: one per rank, and the second pass's edges read across them.
  const std::string render = "render " + quoted(scene) + kSmall + " --mkdir";
  const auto outputs = [&](const char* folder) {
    return " -o " + quoted(dir.path() / folder / "r.exr") + " -o " + quoted(dir.path() / folder / "r.png");
  };
  ASSERT_EQ(run_skylit(render + outputs("r1")).exit_status, 0);
  const auto r2 = run_skylit_with_env(kMpirun, render + outputs("r2"));
  ASSERT_EQ(r2.exit_status, 0) << r2.output;
  expect_same_files(dir.path() / "r1", dir.path() / "r2");
  // The path-traced reference shares its tiles the same way.
  const std::string path = render + " --set render.integrator=path --set render.samples_per_pixel=4";
  ASSERT_EQ(run_skylit(path + outputs("p1")).exit_status, 0);
  ASSERT_EQ(run_skylit_with_env(kMpirun, path + outputs("p2")).exit_status, 0);
  expect_same_files(dir.path() / "p1", dir.path() / "p2");
}

TEST(SplitRuns, RenderMakesAFolderOnlyWhenAsked) {
  TempDir dir;
  const auto scene = dir.write("scene.json", testing::small_scene_json(16, 12));
  const auto refused = run_skylit("render " + quoted(scene) + " -q -o " + quoted(dir.path() / "new" / "x.png"));
  EXPECT_EQ(refused.exit_status, 2);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "new"));
  // A scene that does not load leaves no folder behind, even with --mkdir.
  EXPECT_EQ(run_skylit("render " + quoted(scene) + " --set render.width=-1 --mkdir -q -o " +
                       quoted(dir.path() / "new" / "x.png"))
                .exit_status,
            2);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "new"));
  EXPECT_EQ(
      run_skylit("render " + quoted(scene) + " --mkdir -q -o " + quoted(dir.path() / "new" / "x.png")).exit_status, 0);
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "new" / "x.png"));
}

}  // namespace
}  // namespace skylit
