// Benchmarks of the CityGML reader: the PLATEAU sample (8 LoD2 buildings, 865 kB) and a
// generated PLATEAU-like tile of 1,000,008 triangles (83,334 LoD2 houses of six
// quadrilateral boundary surfaces, in EPSG:6697 with PLATEAU's 14 decimals), read from
// a file as a user's would be. Issue 16 asks for a 1M-triangle tile in at most 10 s.
//   build/bin/skylit_bench --benchmark_filter=CityGml --benchmark_repetitions=3
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <benchmark/benchmark.h>

#include "skylit/io/city/citygml_reader.h"

namespace {

const std::filesystem::path kPlateau = std::filesystem::path(SKYLIT_SOURCE_DIR) / ".." / "shared" / "data" / "models" /
                                       "plateau_53392642_bldg_6697_op2.gml";

// Triangles the surfaces make once triangulated: n − 2 per ring of n points, plus two
// per hole (each hole adds its points and one bridge).
size_t triangle_count(const skylit::CityModel& model) {
  size_t n = 0;
  for (const auto& o : model.objects)
    for (const auto& s : o.surfaces)
      for (size_t r = 0; r < s.rings.size(); ++r) n += s.rings[r].size() + (r == 0 ? 0 : 2) - (r == 0 ? 2 : 0);
  return n;
}

void parse(benchmark::State& state, const std::filesystem::path& file) {
  size_t triangles = 0, objects = 0;
  for (auto _ : state) {
    const skylit::CityModel model = skylit::read_citygml_file(file);
    objects = model.objects.size();
    triangles = triangle_count(model);
    benchmark::DoNotOptimize(&model);
  }
  state.counters["objects"] = static_cast<double>(objects);
  state.counters["triangles"] = static_cast<double>(triangles);
  state.counters["MB"] = static_cast<double>(std::filesystem::file_size(file)) / 1e6;
}

void BM_CityGmlPlateauSample(benchmark::State& state) {
  if (!std::filesystem::exists(kPlateau)) {
    state.SkipWithError("the shared PLATEAU sample is not here");
    return;
  }
  parse(state, kPlateau);
}
BENCHMARK(BM_CityGmlPlateauSample)->Unit(benchmark::kMillisecond)->UseRealTime();

// The tile, written once per run into the temporary folder (and removed at exit).
std::filesystem::path million_triangle_tile() {
  static const std::filesystem::path file = [] {
    const auto path = std::filesystem::temp_directory_path() / "skylit_bench_citygml_tile.gml";
    std::ofstream out(path, std::ios::binary);
    out << R"(<?xml version="1.0" encoding="UTF-8"?>
<core:CityModel xmlns:core="http://www.opengis.net/citygml/2.0" xmlns:gml="http://www.opengis.net/gml" xmlns:bldg="http://www.opengis.net/citygml/building/2.0">
<gml:boundedBy><gml:Envelope srsName="http://www.opengis.net/def/crs/EPSG/0/6697" srsDimension="3"/></gml:boundedBy>
)";
    constexpr int kSide = 289;  // 289² = 83,521 plots; 83,334 houses fill them
    constexpr int kHouses = 83334;
    char point[80];
    const auto ring = [&](const double(*corners)[3]) {
      std::string text = "<gml:posList>";
      for (int k = 0; k <= 4; ++k) {
        const double* c = corners[k % 4];
        std::snprintf(point, sizeof point, "%.14f %.14f %.4f ", c[0], c[1], c[2]);
        text += point;
      }
      text.back() = '<';
      return text + "/gml:posList>";
    };
    for (int h = 0; h < kHouses; ++h) {
      // 10 m plots on a 1/1200° (~9 m) grid near Tokyo.
      const double lat = 35.5 + (h / kSide) / 1200.0, lon = 139.7 + (h % kSide) / 1200.0;
      const double d = 0.00005, z0 = 3.0, z1 = 9.0;
      const double g[4][3] = {{lat, lon, z0}, {lat + d, lon, z0}, {lat + d, lon + d, z0}, {lat, lon + d, z0}};
      const double r[4][3] = {{lat, lon, z1}, {lat, lon + d, z1}, {lat + d, lon + d, z1}, {lat + d, lon, z1}};
      out << "<core:cityObjectMember><bldg:Building gml:id=\"b" << h << "\">\n";
      const auto surface = [&](const char* kind, const double(*corners)[3]) {
        out << "<bldg:boundedBy><bldg:" << kind << "><bldg:lod2MultiSurface><gml:MultiSurface><gml:surfaceMember>"
            << "<gml:Polygon><gml:exterior><gml:LinearRing>" << ring(corners)
            << "</gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember></gml:MultiSurface>"
            << "</bldg:lod2MultiSurface></bldg:" << kind << "></bldg:boundedBy>\n";
      };
      surface("GroundSurface", g);
      surface("RoofSurface", r);
      for (int k = 0; k < 4; ++k) {
        const double* a = g[k];
        const double* b = g[(k + 1) % 4];
        const double w[4][3] = {{b[0], b[1], z0}, {a[0], a[1], z0}, {a[0], a[1], z1}, {b[0], b[1], z1}};
        surface("WallSurface", w);
      }
      out << "</bldg:Building></core:cityObjectMember>\n";
    }
    out << "</core:CityModel>\n";
    std::atexit(
        [] { std::filesystem::remove(std::filesystem::temp_directory_path() / "skylit_bench_citygml_tile.gml"); });
    return path;
  }();
  return file;
}

void BM_CityGmlMillionTriangleTile(benchmark::State& state) { parse(state, million_triangle_tile()); }
BENCHMARK(BM_CityGmlMillionTriangleTile)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace
