// DEM terrain: GeoTIFFs written here by GDAL (a projected one with a no-data corner, a
// geographic one for the axis order), read back as a TIN relief.
#include "skylit/io/city/dem_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../test_support.h"
#include "dem_fixture.h"

namespace skylit {
namespace {

using skylit::testing::input_error_of;
using skylit::testing::TempDir;
using skylit::testing::write_dem;

// The terrain read back from such a file.
CityModel written_and_read(int nx, int ny, const double gt[6], int epsg, double (*h)(int, int)) {
  TempDir dir;
  const auto file = dir.path() / "dem.tif";
  write_dem(file, nx, ny, gt, epsg, h);
  return read_dem_terrain(file).model;
}

double sloped(int i, int j) { return (i == 3 && j == 2) ? -9999 : 10 + i + 2 * j; }

TEST(DemReader, ProjectedDemBecomesATinOfCellCentres) {
  // UTM 54N, 10 m cells, north up (rows run south).
  const double gt[6] = {380000, 10, 0, 3940000, 0, -10};
  const CityModel model = written_and_read(4, 3, gt, 32654, sloped);
  EXPECT_EQ(model.crs, "EPSG:32654");
  ASSERT_EQ(model.objects.size(), 1u);
  EXPECT_EQ(model.objects[0].type, "TINRelief");
  // 3 × 2 cells, less the one whose corner (3, 2) has no height: 5 cells, 10 triangles.
  ASSERT_EQ(model.objects[0].surfaces.size(), 10u);
  for (const CitySurface& s : model.objects[0].surfaces) {
    ASSERT_EQ(s.rings.size(), 1u);
    ASSERT_EQ(s.rings[0].size(), 3u);
    for (const Vec3& p : s.rings[0]) {
      // Easting first (EPSG:32654's order); back to the cell's indices.
      const double i = (p.x - 380000) / 10 - 0.5, j = (3940000 - p.y) / 10 - 0.5;
      EXPECT_NEAR(i, std::round(i), 1e-9);
      EXPECT_NEAR(j, std::round(j), 1e-9);
      EXPECT_DOUBLE_EQ(p.z, sloped(static_cast<int>(std::lround(i)), static_cast<int>(std::lround(j))));
    }
    const Vec3 &a = s.rings[0][0], &b = s.rings[0][1], &c = s.rings[0][2];
    EXPECT_NEAR((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x), 100.0, 1e-6);  // counter-clockwise, 50 m²
  }
}

double flat(int, int) { return 4.0; }

TEST(DemReader, GeographicDemIsInLatitudeLongitudeOrder) {
  // JGD2011 (EPSG:6668), GDAL's geotransform in longitude, latitude.
  const double gt[6] = {139.7, 0.001, 0, 35.6, 0, -0.001};
  const CityModel model = written_and_read(2, 2, gt, 6668, flat);
  EXPECT_EQ(model.crs, "EPSG:6668");
  ASSERT_EQ(model.objects[0].surfaces.size(), 2u);
  const Vec3& p = model.objects[0].surfaces[0].rings[0][0];
  EXPECT_NEAR(p.x, 35.5995, 1e-9);  // latitude of the first row's centres
  EXPECT_NEAR(p.y, 139.7005, 1e-9);
}

TEST(DemReader, UnreadableOrUngeoreferencedFilesAreNamed) {
  TempDir dir;
  const auto text = dir.write("dem.tif", "not a raster\n");
  EXPECT_EQ(input_error_of([&] { read_dem_terrain(text); }).rfind(text.string() + ": cannot read the terrain DEM", 0),
            0u);
  const auto no_crs = dir.path() / "nocrs.tif";
  const double gt[6] = {0, 1, 0, 0, 0, -1};
  write_dem(no_crs, 2, 2, gt, 0, flat);
  EXPECT_EQ(input_error_of([&] { read_dem_terrain(no_crs); }),
            no_crs.string() + ": the terrain DEM names no coordinate reference system; give the terrain's \"crs\"");
  // With the scene's CRS it is read (an ESRI grid without its .prj, an XYZ file), the
  // CRS left to the scene.
  const DemTerrain given = read_dem_terrain(no_crs, /*crs_given=*/true);
  EXPECT_EQ(given.model.crs, "");
  EXPECT_EQ(given.model.objects[0].surfaces.size(), 2u);
  // A file GDAL recognises without a word still gets a reason (it once ended in ": ").
  const auto empty = dir.write("empty.tif", "");
  const std::string message = input_error_of([&] { read_dem_terrain(empty); });
  EXPECT_EQ(message.back() == ' ', false) << message;
  EXPECT_EQ(input_error_of([&] { read_dem_terrain(dir.path() / "missing.tif"); }).rfind(dir.path().string(), 0), 0u);
}

double ramp(int i, int j) { return 10 + i + 2 * j; }

TEST(DemReader, HeightsInFeetBecomeMetres) {
  TempDir dir;
  const double gt[6] = {380000, 10, 0, 3940000, 0, -10};
  for (const auto& [unit, metres] : {std::pair{"ft", 0.3048}, std::pair{"US survey foot", 1200.0 / 3937.0},
                                     std::pair{"m", 1.0}, std::pair{"cm", 0.01}}) {
    const auto file = dir.path() / (std::string(unit) + ".tif");
    write_dem(file, 3, 3, gt, 32654, ramp, unit);
    const DemTerrain dem = read_dem_terrain(file);
    EXPECT_EQ(dem.height_unit, unit);
    for (const CitySurface& s : dem.model.objects[0].surfaces)
      for (const Vec3& p : s.rings[0]) {
        const int i = static_cast<int>(std::lround((p.x - 380000) / 10 - 0.5));
        const int j = static_cast<int>(std::lround((3940000 - p.y) / 10 - 0.5));
        EXPECT_NEAR(p.z, ramp(i, j) * metres, 1e-9) << unit;
      }
  }
}

double spike(int i, int j) { return (i == 1 && j == 2) ? 1e30 : 5.0; }

TEST(DemReader, CellsOfACommonNoDataValueTheFileDoesNotDeclareAreCounted) {
  TempDir dir;
  const double gt[6] = {380000, 10, 0, 3940000, 0, -10};
  // write_dem declares -9999; the fixture's corner cell holds it, so nothing is counted.
  const auto declared = dir.path() / "declared.tif";
  write_dem(declared, 4, 3, gt, 32654, sloped);
  EXPECT_EQ(read_dem_terrain(declared).undeclared_no_data_cells, 0u);
  // The same heights as an ESRI grid without a NODATA_value line.
  const auto grid = dir.write("grid.asc",
                              "ncols 4\nnrows 3\nxllcorner 380000\nyllcorner 3939970\ncellsize 10\n"
                              "10 11 12 13\n12 13 14 15\n14 15 16 -9999\n");
  const DemTerrain dem = read_dem_terrain(grid, /*crs_given=*/true);
  EXPECT_EQ(dem.undeclared_no_data_cells, 1u);
  EXPECT_EQ(dem.undeclared_no_data_value, -9999);
}

TEST(DemReader, AHeightNoTerrainHasIsRefusedNamingItsCell) {
  TempDir dir;
  const auto file = dir.path() / "spike.tif";
  const double gt[6] = {380000, 10, 0, 3940000, 0, -10};
  write_dem(file, 3, 3, gt, 32654, spike);
  EXPECT_EQ(input_error_of([&] { read_dem_terrain(file); }),
            file.string() +
                ": the terrain DEM's cell at pixel 1, line 2 has a height of 1e+30 m, beyond any terrain on earth: "
                "a no-data value the file does not declare?");
}

TEST(DemReader, ALargeDemIsReadAveragedDownToFit) {
  TempDir dir;
  const auto file = dir.path() / "big.tif";
  // 40 × 30 cells of 10 m read into at most 300: a factor 2, 20 × 15 cells of 20 m.
  const double gt[6] = {380000, 10, 0, 3940000, 0, -10};
  write_dem(file, 40, 30, gt, 32654, ramp);
  const DemTerrain dem = read_dem_terrain(file, false, 300);
  EXPECT_EQ(dem.file_width, 40);
  EXPECT_EQ(dem.read_width, 20);
  EXPECT_EQ(dem.read_height, 15);
  EXPECT_DOUBLE_EQ(dem.cell_size_x, 20);
  EXPECT_EQ(dem.model.objects[0].surfaces.size(), 2u * 19 * 14);
  for (const CitySurface& s : dem.model.objects[0].surfaces)
    for (const Vec3& p : s.rings[0]) {
      // At a coarse cell's centre the mean of its four fine cells, which for a ramp is
      // the ramp there (fine indices i = 2I + 0.5, j = 2J + 0.5).
      const double I = (p.x - 380000) / 20 - 0.5, J = (3940000 - p.y) / 20 - 0.5;
      EXPECT_NEAR(I, std::round(I), 1e-9);
      EXPECT_NEAR(p.z, 10 + (2 * std::round(I) + 0.5) + 2 * (2 * std::round(J) + 0.5), 1e-4);
    }
}

}  // namespace
}  // namespace skylit
