// The atmosphere's tables for the example scene one at a time, so that BM_AtmosphereTables
// (render_bench.cpp: all of them, cold) can be split into its parts: each benchmark
// builds one table from the others, which are built once outside the timed loop.
#include <cmath>
#include <filesystem>

#include <benchmark/benchmark.h>

#include "skylit/atmosphere/atmosphere.h"
#include "skylit/atmosphere/scattering_orders_table.h"
#include "skylit/core/vec3.h"
#include "skylit/io/scene/scene_loader.h"

namespace {

const std::filesystem::path kExample = std::filesystem::path(SKYLIT_SOURCE_DIR) / "examples" / "building.json";

// The example's atmosphere, sun and observer, with its sun-independent tables built.
struct ExampleSky {
  skylit::Scene scene = skylit::load_scene(kExample);
  skylit::Atmosphere atmosphere{scene.atmosphere};
  skylit::Vec3 to_sun = skylit::direction_from_altitude_azimuth(scene.sun.altitude_deg, scene.sun.azimuth_deg);
  double sun_elevation_rad = std::asin(to_sun.z);
  double observer_radius_m = atmosphere.ground_radius() + scene.camera.position.z;
  skylit::Spectrum sun = atmosphere.extraterrestrial_irradiance().spectrum();
};

const ExampleSky& example() {
  static const ExampleSky sky;
  return sky;
}

void BM_TransmittanceTable(benchmark::State& state) {
  const ExampleSky& e = example();
  for (auto _ : state) {
    const skylit::TransmittanceTable table(e.atmosphere.medium(), e.atmosphere.ground_radius(),
                                           e.atmosphere.transmittance().top_radius());
    benchmark::DoNotOptimize(&table);
  }
}
BENCHMARK(BM_TransmittanceTable)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ScatteringOrdersTable(benchmark::State& state) {
  const ExampleSky& e = example();
  for (auto _ : state) {
    const skylit::ScatteringOrdersTable table(e.atmosphere.medium(), e.atmosphere.transmittance(),
                                              e.scene.atmosphere.aerosol, e.scene.atmosphere.ground_albedo);
    benchmark::DoNotOptimize(&table);
  }
}
BENCHMARK(BM_ScatteringOrdersTable)->Unit(benchmark::kMillisecond)->UseRealTime();

// The ground's sky irradiance against the sun's height (GroundIrradianceTable), from
// the complete integrator (the Atmosphere builds it from one without the ground's light).
void BM_GroundIrradianceTable(benchmark::State& state) {
  const ExampleSky& e = example();
  for (auto _ : state) {
    const skylit::GroundIrradianceTable table =
        skylit::ScatteringIntegrator::ground_irradiance(e.atmosphere.integrator());
    benchmark::DoNotOptimize(&table);
  }
}
BENCHMARK(BM_GroundIrradianceTable)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SkyViewTable(benchmark::State& state) {
  const ExampleSky& e = example();
  for (auto _ : state) {
    const skylit::SkyViewTable table(e.atmosphere.integrator(), e.sun, e.observer_radius_m,
                                     e.atmosphere.ground_radius(), e.sun_elevation_rad);
    benchmark::DoNotOptimize(&table);
  }
}
BENCHMARK(BM_SkyViewTable)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_AerialPerspectiveTable(benchmark::State& state) {
  const ExampleSky& e = example();
  for (auto _ : state) {
    const skylit::AerialPerspectiveTable table(e.atmosphere.integrator(), e.sun, e.observer_radius_m,
                                               e.atmosphere.ground_radius(), e.sun_elevation_rad);
    benchmark::DoNotOptimize(&table);
  }
}
BENCHMARK(BM_AerialPerspectiveTable)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SkyIrradianceTable(benchmark::State& state) {
  const ExampleSky& e = example();
  const skylit::SkyViewTable sky(e.atmosphere.integrator(), e.sun, e.observer_radius_m, e.atmosphere.ground_radius(),
                                 e.sun_elevation_rad);
  for (auto _ : state) {
    const skylit::SkyIrradianceTable table(sky, e.to_sun);
    benchmark::DoNotOptimize(&table);
  }
}
BENCHMARK(BM_SkyIrradianceTable)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
