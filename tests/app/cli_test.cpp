// The program as a user runs it: exit statuses, one-line errors, no partial output,
// and images that do not depend on the number of threads.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <vector>

#include "../../apps/skylit/exit_status.h"
#include "../test_support.h"

namespace skylit {
namespace {

using testing::quoted;
using testing::run_skylit;
using testing::TempDir;

TEST(Cli, CommandLineMistakesAreOneLineWithExitStatus2) {
  // CLI11 used to add a second line ("Run with --help for more information.").
  for (const std::string arguments : {"render", "nonsense", "sun --lat abc", "render --threads -3 x.json -o a.png"}) {
    const auto r = run_skylit(arguments);
    EXPECT_EQ(r.exit_status, 2) << arguments;
    ASSERT_FALSE(r.output.empty()) << arguments;
    EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << arguments << ": " << r.output;
    EXPECT_EQ(r.output.rfind("skylit: ", 0), 0u) << r.output;
  }
}

TEST(Cli, RendersEveryFormat) {
  TempDir dir;
  const auto scene = dir.write("scene.json", testing::small_scene_json());
  const auto r = run_skylit("render " + quoted(scene) + " --quiet -o " + quoted(dir.path() / "a.png") + " -o " +
                            quoted(dir.path() / "a.exr") + " -o " + quoted(dir.path() / "a.pfm") + " -o " +
                            quoted(dir.path() / "a.hdr"));
  ASSERT_EQ(r.exit_status, 0) << r.output;
  for (const char* name : {"a.png", "a.exr", "a.pfm", "a.hdr"})
    EXPECT_GT(std::filesystem::file_size(dir.path() / name), 100u) << name;
}

TEST(Cli, OutputDoesNotDependOnThreadCount) {
  TempDir dir;
  const auto scene = dir.write("scene.json", testing::small_scene_json(97, 61));  // tiles cut at odd edges
  const auto one = run_skylit("render " + quoted(scene) + " --threads 1 -o " + quoted(dir.path() / "one.pfm"));
  const auto two = run_skylit("render " + quoted(scene) + " --threads 2 -o " + quoted(dir.path() / "two.pfm"));
  const auto many = run_skylit("render " + quoted(scene) + " --threads 7 -o " + quoted(dir.path() / "many.pfm"));
  ASSERT_EQ(one.exit_status, 0) << one.output;
  ASSERT_EQ(two.exit_status, 0) << two.output;
  ASSERT_EQ(many.exit_status, 0) << many.output;
  const std::string a = testing::read_file(dir.path() / "one.pfm");
  EXPECT_GT(a.size(), 97u * 61u * 12u);
  EXPECT_EQ(a, testing::read_file(dir.path() / "two.pfm"));
  EXPECT_EQ(a, testing::read_file(dir.path() / "many.pfm"));
}

TEST(Cli, BadSceneExitsTwoWithOneLineAndNoOutput) {
  TempDir dir;
  const auto scene = dir.write("scene.json", "{\"camera\": [1,2,\n");
  const auto out = dir.path() / "x.png";
  const auto r = run_skylit("render " + quoted(scene) + " -o " + quoted(out));
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_NE(r.output.find("scene.json:2:1: invalid JSON"), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), std::filesystem::directory_iterator()), 1);
}

TEST(Cli, OverrideThatBreaksTheSceneExitsTwo) {
  TempDir dir;
  const auto scene = dir.write("scene.json", testing::small_scene_json());
  const auto r = run_skylit("render " + quoted(scene) + " --set render.width=-3 -o " + quoted(dir.path() / "x.png"));
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_NE(r.output.find("render.width: expected an integer from 1 to 16384"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "x.png"));
}

TEST(Cli, UnknownOutputFormatExitsTwoBeforeRendering) {
  TempDir dir;
  const auto scene = dir.write("scene.json", testing::small_scene_json());
  const auto r = run_skylit("render " + quoted(scene) + " -o " + quoted(dir.path() / "x.jpg"));
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_NE(r.output.find("x.jpg"), std::string::npos) << r.output;
}

TEST(Cli, MissingOutputFolderExitsTwo) {
  TempDir dir;
  const auto scene = dir.write("scene.json", testing::small_scene_json());
  const auto r = run_skylit("render " + quoted(scene) + " -o " + quoted(dir.path() / "no_dir" / "x.png"));
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_NE(r.output.find("does not exist"), std::string::npos) << r.output;
}

TEST(Cli, BadArgumentsExitTwoAndHelpExitsZero) {
  EXPECT_EQ(run_skylit("render").exit_status, 2);
  EXPECT_EQ(run_skylit("render x.json -o a.png --threads lots").exit_status, 2);
  const auto help = run_skylit("render --help");
  EXPECT_EQ(help.exit_status, 0);
  EXPECT_NE(help.output.find("cd/m"), std::string::npos) << help.output;
  EXPECT_NE(help.output.find("--set"), std::string::npos) << help.output;
}

TEST(Cli, OutputSetIsAllOrNothing) {
  // Issue 19, item 12: ok.pfm used to be written before /proc/x.exr was refused.
  TempDir dir;
  const auto scene = dir.write("scene.json", testing::small_scene_json(16, 8));
  for (const std::string& bad : {std::string("/proc/x.exr"), (dir.path() / "missing" / "x.exr").string()}) {
    const auto r = run_skylit("render " + quoted(scene) + " -q -o " + quoted(dir.path() / "ok.pfm") + " -o " +
                              quoted(std::filesystem::path(bad)));
    EXPECT_EQ(r.exit_status, 2) << r.output;
    EXPECT_NE(r.output.find(bad), std::string::npos) << r.output;
    // Nothing at all beside the scene: no ok.pfm, no hidden temporary.
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), std::filesystem::directory_iterator()), 1);
  }
}

TEST(Cli, OutputThatIsAnInputIsRefused) {
  // Issue 19, item 13: `skylit render scene.pfm -o scene.pfm` overwrote its own scene.
  TempDir dir;
  const std::string text = testing::small_scene_json(16, 8);
  const auto scene = dir.write("scene.pfm", text);
  for (const std::string& out :
       {std::string("scene.pfm"), std::string("./scene.pfm"), "../" + dir.path().filename().string() + "/scene.pfm"}) {
    const auto r = run_skylit("render " + quoted(scene) + " -q -o " + quoted(dir.path() / out));
    EXPECT_EQ(r.exit_status, 2) << r.output;
    EXPECT_NE(r.output.find("it is also an input"), std::string::npos) << r.output;
    EXPECT_EQ(testing::read_file(scene), text);
  }
  const auto sweep = run_skylit("sweep " + quoted(dir.write("s.png", text)) + " --vary sun.altitude_deg=5 -q -o " +
                                quoted(dir.path() / "s.png"));
  EXPECT_EQ(sweep.exit_status, 2) << sweep.output;
  EXPECT_NE(sweep.output.find("it is also an input"), std::string::npos) << sweep.output;
}

// Starts `skylit ARGUMENTS`, waits until a hidden temporary file appears in `folder`
// (the render reserves its outputs before the work), sends `signal_number`, and returns
// how the program ended (its wait status).
int interrupt_render(const std::vector<std::string>& arguments, const std::filesystem::path& folder,
                     int signal_number) {
  std::vector<char*> argv{const_cast<char*>(SKYLIT_CLI_PATH)};
  for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t child = fork();
  if (child == 0) {
    execv(SKYLIT_CLI_PATH, argv.data());
    _exit(127);
  }
  const auto has_temporary = [&] {
    for (const auto& entry : std::filesystem::directory_iterator(folder))
      if (entry.path().extension() == ".tmp") return true;
    return false;
  };
  for (int i = 0; i < 2000 && !has_temporary(); ++i) usleep(5000);
  EXPECT_TRUE(has_temporary());
  kill(child, signal_number);
  int status = 0;
  waitpid(child, &status, 0);
  return status;
}

TEST(Cli, InterruptedRenderLeavesNoTemporaryFile) {
  // Issue 19, item 14: SIGINT or SIGTERM left ".name.pid-n.tmp" behind. A path-traced
  // render with many samples runs for seconds, long enough to be interrupted.
  for (const int signal_number : {SIGINT, SIGTERM}) {
    TempDir dir;
    std::string text = testing::small_scene_json(64, 36);
    text.insert(text.rfind('}', text.rfind('}') - 1), R"(, "integrator": "path", "samples_per_pixel": 100000)");
    const auto scene = dir.write("scene.json", text);
    const int status = interrupt_render(
        {"render", scene.string(), "-q", "-o", (dir.path() / "a.exr").string(), "-o", (dir.path() / "a.png").string()},
        dir.path(), signal_number);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal_number) << status;
    std::vector<std::string> left;
    for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
      left.push_back(entry.path().filename().string());
    EXPECT_EQ(left, std::vector<std::string>{"scene.json"});
  }
}

TEST(ExitStatus, InputErrorsAreTwoAndInternalErrorsOne) {
  std::FILE* sink = std::tmpfile();
  EXPECT_EQ(cli::run_with_exit_status([]() -> int { throw InputError("scene.json: x: bad"); }, sink), 2);
  EXPECT_EQ(cli::run_with_exit_status([]() -> int { throw std::logic_error("bug"); }, sink), 1);
  EXPECT_EQ(cli::run_with_exit_status([] { return 0; }, sink), 0);
  std::rewind(sink);
  char line[200] = {};
  ASSERT_NE(std::fgets(line, sizeof line, sink), nullptr);
  EXPECT_STREQ(line, "skylit: scene.json: x: bad\n");
  ASSERT_NE(std::fgets(line, sizeof line, sink), nullptr);
  EXPECT_STREQ(line, "skylit: internal error: bug\n");
  std::fclose(sink);
}

}  // namespace
}  // namespace skylit

namespace skylit {
namespace {

// `skylit info`: the report on stdout, warnings on stderr, exit status 0.
TEST(Cli, InfoReportsObjectsAndWarnsWithExitStatus0) {
  TempDir dir;
  dir.write("tower.obj", "v 0 0 5\nv 1 0 5\nv 0 1 5\nf 1 2 3\n");
  const auto scene = dir.write("scene.json", R"({"camera": {"position": [0, -20, 2], "look_at": [0, 0, 3]},
    "sun": {"altitude_deg": 40, "azimuth_deg": 135}, "materials": {"white": {"type": "diffuse", "reflectance": 0.8}},
    "objects": [{"type": "mesh", "name": "tower", "file": "tower.obj", "material": "white"}]})");
  const auto r = run_skylit("info " + quoted(scene));
  EXPECT_EQ(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find("object 'tower': "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("1 triangle;"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("skylit: warning: object 'tower' floats 5.00 m above the ground"), std::string::npos)
      << r.output;
}

// --preview: half the width and height.
TEST(Cli, PreviewRendersAQuarterOfThePixels) {
  TempDir dir;
  const auto scene = dir.write("scene.json", testing::small_scene_json(48, 32));
  const auto r = run_skylit("render " + quoted(scene) + " --quiet --preview -o " + quoted(dir.path() / "p.pfm"));
  ASSERT_EQ(r.exit_status, 0) << r.output;
  EXPECT_EQ(testing::read_file(dir.path() / "p.pfm").rfind("PF\n24 16\n", 0), 0u);
}

}  // namespace
}  // namespace skylit

namespace skylit {
namespace {

// --verbose: after the render, one line with the frame's parts (FrameBreakdown).
TEST(Cli, VerboseSaysWhereTheFramesTimeWent) {
  TempDir dir;
  const auto scene = dir.write("scene.json", testing::small_scene_json(48, 32));
  const auto quiet = run_skylit("render " + quoted(scene) + " --quiet -o " + quoted(dir.path() / "q.pfm"));
  ASSERT_EQ(quiet.exit_status, 0) << quiet.output;
  EXPECT_EQ(quiet.output.find("frame: "), std::string::npos) << quiet.output;
  const auto r = run_skylit("render " + quoted(scene) + " --quiet --verbose -o " + quoted(dir.path() / "v.pfm"));
  ASSERT_EQ(r.exit_status, 0) << r.output;
  EXPECT_NE(r.output.find("frame: first hits "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(" grid points and "), std::string::npos) << r.output;
  EXPECT_EQ(testing::read_file(dir.path() / "q.pfm"), testing::read_file(dir.path() / "v.pfm"));
}

}  // namespace
}  // namespace skylit
