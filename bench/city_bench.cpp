// Loading a city model: the CityJSON reader and the placement (PROJ to the local
// frame, triangulation) on a generated district of 6,400 LoD2 gabled houses (102,400
// triangles; issue 16 asks for 100,000 in at most 2 s), and on the Delft sample
// (../shared/data/models) when it is there. BENCHMARKS.md has the results.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "skylit/io/city/city_placement.h"
#include "skylit/io/city/cityjson_reader.h"

namespace {

// An 80 × 80 grid of houses 10 × 8 m, walls 6 m, ridge 9 m, 20 m apart, in RD New +
// NAP (EPSG:7415) around Delft, quantised to millimetres.
std::string district_cityjson(int side) {
  std::string vertices, objects;
  int next = 0;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      const int x = 84000000 + i * 20000, y = 447000000 + j * 20000;  // mm
      const int corners[10][3] = {
          {x, y, 0},           {x + 10000, y, 0},          {x + 10000, y + 8000, 0},    {x, y + 8000, 0},
          {x, y, 6000},        {x + 10000, y, 6000},       {x + 10000, y + 8000, 6000}, {x, y + 8000, 6000},
          {x, y + 4000, 9000}, {x + 10000, y + 4000, 9000}};
      for (const auto& c : corners)
        vertices += (vertices.empty() ? "[" : ",[") + std::to_string(c[0]) + "," + std::to_string(c[1]) + "," +
                    std::to_string(c[2]) + "]";
      const auto v = [&](int k) { return std::to_string(next + k); };
      const std::string shell = "[[[" + v(0) + "," + v(3) + "," + v(2) + "," + v(1) + "]],[[" + v(0) + "," + v(1) +
                                "," + v(5) + "," + v(4) + "]],[[" + v(2) + "," + v(3) + "," + v(7) + "," + v(6) +
                                "]],[[" + v(1) + "," + v(2) + "," + v(6) + "," + v(9) + "," + v(5) + "]],[[" + v(3) +
                                "," + v(0) + "," + v(4) + "," + v(8) + "," + v(7) + "]],[[" + v(4) + "," + v(5) + "," +
                                v(9) + "," + v(8) + "]],[[" + v(6) + "," + v(7) + "," + v(8) + "," + v(9) + "]]]";
      next += 10;
      objects += std::string(objects.empty() ? "" : ",") + "\"h" + std::to_string(i * side + j) +
                 "\":{\"type\":\"Building\",\"geometry\":[{\"type\":\"Solid\",\"lod\":\"2\",\"boundaries\":[" + shell +
                 "],\"semantics\":{\"surfaces\":[{\"type\":\"GroundSurface\"},{\"type\":\"WallSurface\"},{\"type\":"
                 "\"RoofSurface\"}],\"values\":[[0,1,1,1,1,2,2]]}}]}";
    }
  return R"({"type":"CityJSON","version":"2.0","transform":{"scale":[0.001,0.001,0.001],"translate":[0,0,0]},)"
         R"("metadata":{"referenceSystem":"https://www.opengis.net/def/crs/EPSG/0/7415"},"vertices":[)" +
         vertices + "],\"CityObjects\":{" + objects + "}}";
}

void BM_CityDistrict100kTriangles(benchmark::State& state) {
  const std::string text = district_cityjson(80);
  size_t triangles = 0;
  for (auto _ : state) {
    const skylit::PlacedCity city =
        skylit::place_city_model(skylit::read_cityjson_text(text, "district.city.json"), {}, "district.city.json");
    triangles = 0;
    for (const auto& o : city.objects) triangles += o.mesh.triangles.size();
  }
  state.counters["triangles"] = static_cast<double>(triangles);
}
BENCHMARK(BM_CityDistrict100kTriangles)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_CityDelft(benchmark::State& state) {
  const auto file = std::filesystem::path(SKYLIT_SOURCE_DIR) / "../shared/data/models/delft.city.json";
  if (!std::filesystem::exists(file)) {
    state.SkipWithError("no ../shared/data/models/delft.city.json");
    return;
  }
  size_t triangles = 0;
  for (auto _ : state) {
    const skylit::PlacedCity city = skylit::place_city_model(skylit::read_cityjson_file(file), {}, file.string());
    triangles = 0;
    for (const auto& o : city.objects) triangles += o.mesh.triangles.size();
  }
  state.counters["triangles"] = static_cast<double>(triangles);
}
BENCHMARK(BM_CityDelft)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
