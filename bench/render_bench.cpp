// Benchmarks of the example scene (examples/building.json at 1280×720): scene set-up
// (loading, meshes, BVH), one frame, rays per second, and peak memory. Results and
// the machine go into BENCHMARKS.md; run with
//   build/bin/skylit_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <sys/resource.h>

#include <benchmark/benchmark.h>

#include "skylit/io/scene_loader.h"
#include "skylit/render/renderer.h"

namespace {

const std::filesystem::path kExample = std::filesystem::path(SKYLIT_SOURCE_DIR) / "examples" / "building.json";

double peak_memory_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

void BM_SceneSetup(benchmark::State& state) {
  for (auto _ : state) {
    const skylit::Scene scene = skylit::load_scene(kExample);
    const skylit::Renderer renderer(scene);
    benchmark::DoNotOptimize(&renderer);
  }
}
BENCHMARK(BM_SceneSetup)->Unit(benchmark::kMillisecond)->UseRealTime();

// One 1280×720 frame with the scene's own settings (2×2 samples per pixel) on the
// given number of threads.
void BM_Frame1280x720(benchmark::State& state) {
  skylit::Scene scene = skylit::load_scene(kExample, {"render.width=1280", "render.height=720"});
  const skylit::Renderer renderer(scene);
  skylit::RenderOptions options;
  options.threads = static_cast<int>(state.range(0));
  const uint64_t rays_before = renderer.rays_traced();
  for (auto _ : state) {
    skylit::XyzImage image = renderer.render(options);
    benchmark::DoNotOptimize(image.xyz.data());
  }
  state.counters["rays_per_s"] = benchmark::Counter(static_cast<double>(renderer.rays_traced() - rays_before),
                                                    benchmark::Counter::kIsRate);
  state.counters["peak_MiB"] = peak_memory_mib();
}
BENCHMARK(BM_Frame1280x720)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
