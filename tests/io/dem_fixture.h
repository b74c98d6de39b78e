// Writing small DEMs (GeoTIFF, through GDAL) for the terrain tests.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <vector>

#include <gdal_priv.h>
#include <ogr_spatialref.h>

namespace skylit::testing {

// Writes an nx × ny GeoTIFF with heights h(i, j), the geotransform and the EPSG code
// given (0: no CRS), and -9999 as its no-data value; the band's unit if given.
inline void write_dem(const std::filesystem::path& file, int nx, int ny, const double gt[6], int epsg,
                      double (*h)(int, int), const char* unit = nullptr) {
  GDALAllRegister();
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GTiff");
  ASSERT_NE(driver, nullptr);
  GDALDataset* ds = driver->Create(file.c_str(), nx, ny, 1, GDT_Float32, nullptr);
  ASSERT_NE(ds, nullptr);
  double transform[6];
  std::copy(gt, gt + 6, transform);
  ds->SetGeoTransform(transform);
  if (epsg != 0) {
    OGRSpatialReference srs;
    srs.importFromEPSG(epsg);
    ds->SetSpatialRef(&srs);
  }
  std::vector<float> values(static_cast<size_t>(nx * ny));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) values[static_cast<size_t>(j * nx + i)] = static_cast<float>(h(i, j));
  GDALRasterBand* band = ds->GetRasterBand(1);
  band->SetNoDataValue(-9999);
  if (unit != nullptr) band->SetUnitType(unit);
  ASSERT_EQ(band->RasterIO(GF_Write, 0, 0, nx, ny, values.data(), nx, ny, GDT_Float32, 0, 0), CE_None);
  GDALClose(ds);
}

}  // namespace skylit::testing
