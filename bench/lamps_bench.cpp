// Lamps in fog on real-sized geometry (issue 18, "Scale"): the Delft sample
// (../shared/data/models, read by the CityJSON reader; skipped when absent) with 20 street
// lamps along a street, and a generated block of about 500,000 triangles with 100 lamps;
// both in fog of 600 m visibility, the camera at street level, at the size given as the
// benchmark's argument (width; height 9/16 of it). BENCHMARKS.md has the results.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <benchmark/benchmark.h>

#include "skylit/io/scene/scene_loader.h"
#include "skylit/render/renderer.h"

namespace {

namespace fs = std::filesystem;

const fs::path kSource = fs::path(SKYLIT_SOURCE_DIR);
const fs::path kDelft = kSource / ".." / "shared" / "data" / "models" / "delft.city.json";

fs::path scratch_dir() {
  const fs::path dir = fs::temp_directory_path() / ("skylit_lamps_bench_" + std::to_string(getpid()));
  fs::create_directories(dir);
  return dir;
}

// Night, fog of 600 m visibility thinning upward, the road a CIE R3 surface.
const char* const kNightAndFog = R"("sun": {"altitude_deg": -14, "azimuth_deg": 250},
  "fog": {"visibility_m": 600, "scale_height_m": 60, "top_m": 40},
  "materials": {"asphalt": {"type": "road", "r_table": "R3", "q0": 0.07}, "plaster": {"type": "diffuse", "reflectance": 0.5}},)";

std::string lamp_row(const std::string& name, const std::string& centre_line, double spacing_m) {
  return R"({"name": ")" + name + R"(", "centre_line": )" + centre_line + R"(, "road_width_m": 7, "spacing_m": )" +
         std::to_string(spacing_m) +
         R"(, "height_m": 8, "overhang_m": 1, "tilt_deg": 5, "arrangement": "staggered", "ies": ")" +
         (kSource / "examples" / "lamps" / "road_luminaire.ies").string() +
         R"(", "lamp": "led", "temperature_k": 3000})";
}

// The Delft sample (36,271 triangles) seen along the street on its south-west side, with
// 20 lamps staggered 12 m apart along it.
fs::path delft_night_scene() {
  const fs::path scene = scratch_dir() / "delft_night.json";
  std::ofstream(scene)
      << R"({"camera": {"position": [-72, -22, 1.7], "look_at": [15, -95, 4], "vertical_fov_deg": 55},)" << kNightAndFog
      << R"("objects": [
    {"name": "ground", "type": "plane", "material": "asphalt", "center": [0, 0, -0.6], "size_m": 3000},
    {"name": "delft", "type": "city", "file": ")"
      << kDelft.string() << R"("}], "lamp_rows": [)"
      << lamp_row("street", "[[-80, -25, 0], [-30, -65, 0], [15, -95, 0], [70, -125, 0], [125, -140, 0]]", 12) << "]}";
  return scene;
}

// A 20 × 20 grid of blocks 16 m square and 12–20 m tall, 30 m apart, whose walls are
// tessellated in 1 m × 1.5 m panels (1,282 triangles a block, 512,800 in all, in one
// OBJ), with 100 lamps along four streets.
fs::path lamp_block_scene() {
  const fs::path dir = scratch_dir();
  const fs::path scene = dir / "block_night.json";
  if (fs::exists(scene)) return scene;
  std::ofstream obj(dir / "block.obj");
  long next = 1;  // OBJ's first vertex
  auto quad = [&](const double(&a)[3], const double(&b)[3], const double(&c)[3], const double(&d)[3]) {
    for (const auto* v : {&a, &b, &c, &d}) obj << "v " << (*v)[0] << ' ' << (*v)[1] << ' ' << (*v)[2] << '\n';
    obj << "f " << next << ' ' << next + 1 << ' ' << next + 2 << "\nf " << next << ' ' << next + 2 << ' ' << next + 3
        << '\n';
    next += 4;
  };
  constexpr int kBlocks = 20, kSide = 16;
  for (int i = 0; i < kBlocks; ++i)
    for (int j = 0; j < kBlocks; ++j) {
      const double x0 = 30.0 * (i - kBlocks / 2) + 7, y0 = 30.0 * (j - kBlocks / 2) + 7;
      const double height = 12 + (i * 7 + j * 3) % 9;
      const int floors = static_cast<int>(height / 1.5);
      // The four walls, counter-clockwise seen from outside: (x, y) corners in order.
      const double corners[5][2] = {{x0, y0}, {x0 + kSide, y0}, {x0 + kSide, y0 + kSide}, {x0, y0 + kSide}, {x0, y0}};
      for (int w = 0; w < 4; ++w)
        for (int u = 0; u < kSide; ++u)
          for (int k = 0; k < floors; ++k) {
            const double s0 = static_cast<double>(u) / kSide, s1 = static_cast<double>(u + 1) / kSide;
            const double z0 = height * k / floors, z1 = height * (k + 1) / floors;
            const auto at = [&](double s, double z, double(&p)[3]) {
              p[0] = corners[w][0] + s * (corners[w + 1][0] - corners[w][0]);
              p[1] = corners[w][1] + s * (corners[w + 1][1] - corners[w][1]);
              p[2] = z;
            };
            double a[3], b[3], c[3], d[3];
            at(s0, z0, a), at(s1, z0, b), at(s1, z1, c), at(s0, z1, d);
            quad(a, b, c, d);
          }
      const double r0[3] = {x0, y0, height}, r1[3] = {x0 + kSide, y0, height}, r2[3] = {x0 + kSide, y0 + kSide, height},
                   r3[3] = {x0, y0 + kSide, height};
      quad(r0, r1, r2, r3);
    }
  // Streets run between the blocks at x, y = 30 k − 8 (k integer); four of them lit.
  std::ofstream(scene)
      << R"({"camera": {"position": [-6, -170, 1.7], "look_at": [-10, 60, 4], "vertical_fov_deg": 55},)" << kNightAndFog
      << R"("objects": [
    {"name": "ground", "type": "plane", "material": "asphalt", "size_m": 3000},
    {"name": "block", "type": "mesh", "file": "block.obj", "material": "plaster"}], "lamp_rows": [)"
      << lamp_row("north-south 1", "[[-8, -300, 0], [-8, 300, 0]]", 24) << ','
      << lamp_row("north-south 2", "[[52, -300, 0], [52, 300, 0]]", 24) << ','
      << lamp_row("east-west 1", "[[-300, -38, 0], [300, -38, 0]]", 24) << ','
      << lamp_row("east-west 2", "[[-300, 22, 0], [300, 22, 0]]", 24) << "]}";
  return scene;
}

void frames_of(benchmark::State& state, const fs::path& scene) {
  const int width = static_cast<int>(state.range(0));
  const skylit::Scene loaded = skylit::load_scene(
      scene, {"render.width=" + std::to_string(width), "render.height=" + std::to_string(width * 9 / 16)});
  state.counters["lamps"] = static_cast<double>(loaded.lights.size());
  const skylit::Renderer renderer(loaded);
  skylit::RenderOptions options;
  options.threads = 2;
  for (auto _ : state) {
    skylit::XyzImage image = renderer.render(options);
    benchmark::DoNotOptimize(image.xyz.data());
  }
}

// Issue 18: at most 10 s at 1280 × 720.
void BM_DelftNightFrame(benchmark::State& state) {
  if (!fs::exists(kDelft)) {
    state.SkipWithError("no ../shared/data/models/delft.city.json");
    return;
  }
  frames_of(state, delft_night_scene());
}
BENCHMARK(BM_DelftNightFrame)->Arg(320)->Arg(1280)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

// Issue 18: at most 60 s at 1280 × 720.
void BM_LampBlockFrame(benchmark::State& state) { frames_of(state, lamp_block_scene()); }
BENCHMARK(BM_LampBlockFrame)->Arg(320)->Arg(1280)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace
