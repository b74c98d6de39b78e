// Benchmarks of the example scene (examples/building.json at 1280×720): scene set-up
// (loading, meshes, BVH), one frame, rays per second, and peak memory. Results and
// the machine go into BENCHMARKS.md; run with
//   build/bin/skylit_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <malloc.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "skylit/atmosphere/seen_sun.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/render/renderer.h"

namespace {

const std::filesystem::path kExample = std::filesystem::path(SKYLIT_SOURCE_DIR) / "examples" / "building.json";
const std::filesystem::path kFig7 = std::filesystem::path(SKYLIT_SOURCE_DIR) / "examples" / "fig7.json";

// The process's peak resident memory since the last reset_peak_memory (VmHWM). Without
// the reset it would be the whole run's peak: a benchmark after a larger one, or a
// repetition after the first, reported its predecessors' memory (the million-triangle
// load read 273, 328, 368 MiB in three repetitions of the same work).
void reset_peak_memory() { std::ofstream("/proc/self/clear_refs") << "5"; }  // Linux ≥ 4.0

double peak_memory_mib() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // in kB
  return 0;
}

// The atmosphere's tables for the example's sun and camera: the sun-independent
// ones (transmittance, multiple scattering, ground sky irradiance) and the sky model
// (sky view, aerial perspective, sky irradiance on surfaces, direct-sun profile).
void BM_AtmosphereTables(benchmark::State& state) {
  const skylit::Scene scene = skylit::load_scene(kExample);
  const skylit::Vec3 to_sun = skylit::direction_from_altitude_azimuth(scene.sun.altitude_deg, scene.sun.azimuth_deg);
  for (auto _ : state) {
    skylit::forget_shared_atmosphere_tables();  // a cold build each time, as for a new air
    const skylit::Atmosphere atmosphere(scene.atmosphere);
    const skylit::SkyModel sky(atmosphere, skylit::SunRefraction(atmosphere).true_direction(to_sun),
                               scene.camera.position.z);
    benchmark::DoNotOptimize(&sky);
  }
}
BENCHMARK(BM_AtmosphereTables)->Unit(benchmark::kMillisecond)->UseRealTime();

// Scene set-up without the atmosphere: loading, meshes, BVH.
void BM_SceneSetup(benchmark::State& state) {
  for (auto _ : state) {
    const skylit::Scene scene = skylit::load_scene(kExample);
    skylit::RayTracer tracer;
    for (const skylit::SceneObject& object : scene.objects) tracer.add_mesh(object.mesh);
    tracer.commit();
    benchmark::DoNotOptimize(&tracer);
  }
}
BENCHMARK(BM_SceneSetup)->Unit(benchmark::kMillisecond)->UseRealTime();

// Frames of one scene on `threads` threads, once its tables are built, with rays per
// second, the process's peak memory, and the last frame's parts (FrameBreakdown: the
// sky-light cache's seconds and points, the two passes' seconds).
void frames_of(benchmark::State& state, const skylit::Scene& scene, int threads = 2) {
  reset_peak_memory();  // the scene loaded is resident and counts; its loading's transients do not
  const skylit::Renderer renderer(scene);
  skylit::RenderOptions options;
  options.threads = threads;
  skylit::FrameBreakdown frame;
  options.breakdown = &frame;
  const uint64_t rays_before = renderer.rays_traced();
  for (auto _ : state) {
    skylit::XyzImage image = renderer.render(options);
    benchmark::DoNotOptimize(image.xyz.data());
  }
  state.counters["hits_s"] = frame.primary_hits_s;
  state.counters["cache_s"] = frame.caches_s;
  state.counters["passes_s"] = frame.centres_pass_s + frame.edges_pass_s;
  state.counters["cache_points"] = frame.coarse_points + frame.fine_points + frame.pixel_points;  // checks among them
  state.counters["rays_per_s"] =
      benchmark::Counter(static_cast<double>(renderer.rays_traced() - rays_before), benchmark::Counter::kIsRate);
  state.counters["peak_MiB"] = peak_memory_mib();
}

// One 1280×720 frame of the example with its own settings (2×2 samples per pixel) on
// the given number of threads.
void BM_Frame1280x720(benchmark::State& state) {
  frames_of(state, skylit::load_scene(kExample, {"render.width=1280", "render.height=720"}),
            static_cast<int>(state.range(0)));
}
BENCHMARK(BM_Frame1280x720)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The paper's Fig. 7 at 1280×720: tile walls (arg 0) and aluminium walls (arg 1), the
// sun at 17°; arg 2: tile walls with the obstacles lit by the open sky (the paper's one
// bounce, render.obstacle_light = open_sky; until 2026-12-04 args 0 and 1 had it too).
void BM_Fig7Frame(benchmark::State& state) {
  const char* walls = state.range(0) == 1 ? "materials.walls=aluminium" : "materials.walls=tile";
  const char* obstacles = state.range(0) == 2 ? "render.obstacle_light=open_sky" : "render.obstacle_light=own_sky";
  frames_of(state, skylit::load_scene(kFig7, {walls, "sun.altitude_deg=17", obstacles}));
}
BENCHMARK(BM_Fig7Frame)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The paper's Fig. 8a (fog, arg 0) and 8c (beams, arg 1) at 1280×720.
void BM_Fig8Frame(benchmark::State& state) {
  const std::filesystem::path file =
      std::filesystem::path(SKYLIT_SOURCE_DIR) / "examples" / (state.range(0) == 0 ? "fig8a.json" : "fig8c.json");
  frames_of(state, skylit::load_scene(file));
}
BENCHMARK(BM_Fig8Frame)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// Fig. 8a with the fog's multiple scattering off (arg 0, the paper's single scattering)
// and on (arg 1): what the diffuse field and its camera table cost (docs/fog.md).
void BM_Fig8FogMultipleScattering(benchmark::State& state) {
  const std::filesystem::path file = std::filesystem::path(SKYLIT_SOURCE_DIR) / "examples" / "fig8a.json";
  frames_of(state, skylit::load_scene(
                       file, {state.range(0) == 0 ? "fog.multiple_scattering=false" : "fog.multiple_scattering=true"}));
}
BENCHMARK(BM_Fig8FogMultipleScattering)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// The paper's Fig. 10a (sun in front of the camera, arg 0) and 10b (sun behind, arg 1).
void BM_Fig10Frame(benchmark::State& state) {
  const std::filesystem::path file =
      std::filesystem::path(SKYLIT_SOURCE_DIR) / "examples" / (state.range(0) == 0 ? "fig10a.json" : "fig10b.json");
  frames_of(state, skylit::load_scene(file));
}
BENCHMARK(BM_Fig10Frame)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// The paper's Fig. 9: a street at night in light fog, eleven lamps, at 1280×720.
void BM_Fig9Frame(benchmark::State& state) {
  frames_of(state, skylit::load_scene(std::filesystem::path(SKYLIT_SOURCE_DIR) / "examples" / "fig9.json"));
}
BENCHMARK(BM_Fig9Frame)->Unit(benchmark::kMillisecond)->UseRealTime();

// A model of about a million triangles with its own materials and textures: the example
// house (examples/models/house.obj, 886 triangles, 7 materials, brick and render
// textures) repeated on a 34 × 34 grid 20 m apart as one OBJ (1 024 296 triangles)
// beside copies of its MTL and textures, written once into the temporary folder; a
// scene frames it from the south-west on a clear day.
std::filesystem::path million_triangle_dir() {
  return std::filesystem::temp_directory_path() / ("skylit_bench_model_" + std::to_string(getpid()));
}

std::filesystem::path million_triangle_scene() {
  namespace fs = std::filesystem;
  const fs::path dir = million_triangle_dir();
  const fs::path scene = dir / "city.json";
  if (fs::exists(scene)) return scene;
  fs::create_directories(dir);
  // 111 MB a run: every run had left its folder behind.
  std::atexit([] {
    std::error_code ignored;
    std::filesystem::remove_all(million_triangle_dir(), ignored);
  });
  const fs::path models = fs::path(SKYLIT_SOURCE_DIR) / "examples" / "models";
  for (const char* file : {"house.mtl", "brick.png", "render.png"})
    fs::copy_file(models / file, dir / file, fs::copy_options::overwrite_existing);
  std::ifstream in(models / "house.obj");
  std::vector<std::string> uv_lines, face_lines;
  std::vector<std::array<double, 3>> vertices;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("vt ", 0) == 0) {
      uv_lines.push_back(line);
    } else if (line.rfind("v ", 0) == 0) {
      std::array<double, 3> v{};
      std::sscanf(line.c_str(), "v %lf %lf %lf", &v[0], &v[1], &v[2]);
      vertices.push_back(v);
    } else if (line.rfind("f ", 0) == 0 || line.rfind("usemtl ", 0) == 0) {
      face_lines.push_back(line);
    }
  }
  std::ofstream out(dir / "city.obj");
  out << "mtllib house.mtl\n";
  constexpr int kGrid = 34;
  for (int copy = 0; copy < kGrid * kGrid; ++copy) {
    const double dx = 20.0 * (copy % kGrid - kGrid / 2), dy = 20.0 * (copy / kGrid - kGrid / 2);
    char text[96];
    for (const auto& v : vertices) {
      std::snprintf(text, sizeof text, "v %.4f %.4f %.4f\n", v[0] + dx, v[1] + dy, v[2]);
      out << text;
    }
    for (const std::string& line : uv_lines) out << line << '\n';
    // Relative indices (vertex/uv), so every copy's faces read the same.
    const long n = static_cast<long>(vertices.size()), nt = static_cast<long>(uv_lines.size());
    for (const std::string& line : face_lines) {
      if (line[0] == 'u') {
        out << line << '\n';
        continue;
      }
      std::istringstream words(line.substr(2));
      out << 'f';
      for (std::string corner; words >> corner;) {
        const size_t slash = corner.find('/');
        out << ' ' << std::stol(corner) - n - 1;
        if (slash != std::string::npos) out << '/' << std::stol(corner.substr(slash + 1)) - nt - 1;
      }
      out << '\n';
    }
  }
  std::ofstream(scene) << R"({"camera": {"frame": ["city"], "from_azimuth_deg": 225, "elevation_deg": 25},
    "sun": {"altitude_deg": 35, "azimuth_deg": 200}, "materials": {"lawn": "grass"},
    "objects": [{"name": "ground", "type": "plane", "material": "lawn", "size_m": 4000},
                {"name": "city", "type": "mesh", "file": "city.obj"}],
    "render": {"width": 1280, "height": 720}})";
  return scene;
}

// Loading it: parsing, triangulation, materials, the up-axis turn (no BVH yet).
void BM_LoadMillionTriangleModel(benchmark::State& state) {
  const std::filesystem::path scene = million_triangle_scene();
  size_t triangles = 0;
  // glibc raises its mmap threshold to the size of each mmapped block freed (up to
  // 32 MiB): after a first load, a second takes its growing arrays from the heap, where
  // the outgrown buffers stay resident, and peaked at 328–396 MiB against the first's
  // 268. Fixed at its initial 128 KiB, every repetition loads as a new process's first
  // load does (253 MiB each).
  mallopt(M_MMAP_THRESHOLD, 128 * 1024);
  reset_peak_memory();
  for (auto _ : state) {
    const skylit::Scene loaded = skylit::load_scene(scene);
    triangles = loaded.objects[1].mesh.triangles.size();
    benchmark::DoNotOptimize(&loaded);
  }
  state.counters["triangles"] = static_cast<double>(triangles);
  state.counters["peak_MiB"] = peak_memory_mib();
}
BENCHMARK(BM_LoadMillionTriangleModel)->Unit(benchmark::kMillisecond)->UseRealTime();

// One clear-day 1280×720 frame of it on 2 threads, the BVH built beforehand; arg 1 with
// the obstacles lit by the open sky (the paper's one bounce; until 2026-12-04 arg 0 had
// it and arg 1 their own sky, now the default).
void BM_MillionTriangleFrame(benchmark::State& state) {
  frames_of(state, skylit::load_scene(
                       million_triangle_scene(),
                       {state.range(0) == 1 ? "render.obstacle_light=open_sky" : "render.obstacle_light=own_sky"}));
}
BENCHMARK(BM_MillionTriangleFrame)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
