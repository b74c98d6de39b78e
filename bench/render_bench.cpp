// Benchmarks of the example scene (examples/building.json at 1280×720): scene set-up
// (loading, meshes, BVH), one frame, rays per second, and peak memory. Results and
// the machine go into BENCHMARKS.md; run with
//   build/bin/skylit_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <sys/resource.h>

#include <benchmark/benchmark.h>

#include "skylit/io/scene/scene_loader.h"
#include "skylit/render/renderer.h"

namespace {

const std::filesystem::path kExample = std::filesystem::path(SKYLIT_SOURCE_DIR) / "examples" / "building.json";
const std::filesystem::path kFig7 = std::filesystem::path(SKYLIT_SOURCE_DIR) / "examples" / "fig7.json";

double peak_memory_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

// The atmosphere's tables for the example's sun and camera: the sun-independent
// ones (transmittance, multiple scattering, ground sky irradiance) and the sky model
// (sky view, aerial perspective, sky irradiance on surfaces, direct-sun profile).
void BM_AtmosphereTables(benchmark::State& state) {
  const skylit::Scene scene = skylit::load_scene(kExample);
  const skylit::Vec3 to_sun = skylit::direction_from_altitude_azimuth(scene.sun.altitude_deg, scene.sun.azimuth_deg);
  for (auto _ : state) {
    const skylit::Atmosphere atmosphere(scene.atmosphere);
    const skylit::SkyModel sky(atmosphere, to_sun, scene.camera.position.z);
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
// second and the process's peak memory.
void frames_of(benchmark::State& state, const skylit::Scene& scene, int threads = 2) {
  const skylit::Renderer renderer(scene);
  skylit::RenderOptions options;
  options.threads = threads;
  const uint64_t rays_before = renderer.rays_traced();
  for (auto _ : state) {
    skylit::XyzImage image = renderer.render(options);
    benchmark::DoNotOptimize(image.xyz.data());
  }
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
// sun at 17°.
void BM_Fig7Frame(benchmark::State& state) {
  const char* walls = state.range(0) == 0 ? "materials.walls=tile" : "materials.walls=aluminium";
  frames_of(state, skylit::load_scene(kFig7, {walls, "sun.altitude_deg=17"}));
}
BENCHMARK(BM_Fig7Frame)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// The paper's Fig. 8a (fog, arg 0) and 8c (beams, arg 1) at 1280×720.
void BM_Fig8Frame(benchmark::State& state) {
  const std::filesystem::path file =
      std::filesystem::path(SKYLIT_SOURCE_DIR) / "examples" / (state.range(0) == 0 ? "fig8a.json" : "fig8c.json");
  frames_of(state, skylit::load_scene(file));
}
BENCHMARK(BM_Fig8Frame)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

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

}  // namespace

BENCHMARK_MAIN();
