// GDAL reads the raster, its geotransform (pixel → map coordinates, in GIS order:
// east first) and its CRS; the axis mapping GDAL keeps for that CRS puts each point
// back into the CRS's own axis order.
#include "skylit/io/city/dem_reader.h"

#include <array>
#include <cmath>
#include <mutex>
#include <string>
#include <vector>

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include "skylit/core/error.h"
#include "skylit/core/text_file.h"

namespace skylit {
namespace {

std::string crs_of(const OGRSpatialReference& srs) {
  const char* authority = srs.GetAuthorityName(nullptr);
  const char* code = srs.GetAuthorityCode(nullptr);
  if (authority != nullptr && code != nullptr && std::string(authority) == "EPSG") return std::string("EPSG:") + code;
  OGRSpatialReference copy(srs);
  if (copy.AutoIdentifyEPSG() == OGRERR_NONE && copy.GetAuthorityCode(nullptr) != nullptr)
    return std::string("EPSG:") + copy.GetAuthorityCode(nullptr);
  char* wkt = nullptr;
  const char* options[] = {"FORMAT=WKT2_2019", nullptr};
  copy.exportToWkt(&wkt, options);
  std::string text = wkt != nullptr ? wkt : "";
  CPLFree(wkt);
  return text;
}

}  // namespace

CityModel read_dem_terrain(const std::filesystem::path& file) {
  const std::string name = file.string();
  require_regular_file(file, "terrain DEM");
  static std::once_flag registered;
  std::call_once(registered, [] { GDALAllRegister(); });
  CPLErrorReset();
  CPLPushErrorHandler(CPLQuietErrorHandler);
  GDALDatasetUniquePtr dataset(GDALDataset::Open(name.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  CPLPopErrorHandler();
  if (!dataset) throw InputError(name + ": cannot read the terrain DEM: " + CPLGetLastErrorMsg());
  double gt[6];
  if (dataset->GetGeoTransform(gt) != CE_None)
    throw InputError(name + ": the terrain DEM has no georeferencing (no geotransform)");
  const OGRSpatialReference* srs = dataset->GetSpatialRef();
  if (srs == nullptr || srs->IsEmpty())
    throw InputError(name + ": the terrain DEM names no coordinate reference system");
  if (dataset->GetRasterCount() < 1) throw InputError(name + ": the terrain DEM has no band");
  const size_t nx = static_cast<size_t>(dataset->GetRasterXSize()), ny = static_cast<size_t>(dataset->GetRasterYSize());
  if (nx < 2 || ny < 2) throw InputError(name + ": the terrain DEM has fewer than 2 × 2 cells");
  if (nx * ny > kMaxDemCells)
    throw InputError(name + ": the terrain DEM has " + std::to_string(nx) + " × " + std::to_string(ny) +
                     " cells, more than the 4096² read; crop or resample it (gdal_translate)");

  GDALRasterBand* band = dataset->GetRasterBand(1);
  std::vector<double> height(nx * ny);
  if (band->RasterIO(GF_Read, 0, 0, static_cast<int>(nx), static_cast<int>(ny), height.data(), static_cast<int>(nx),
                     static_cast<int>(ny), GDT_Float64, 0, 0) != CE_None)
    throw InputError(name + ": cannot read the terrain DEM's heights: " + CPLGetLastErrorMsg());
  int has_no_data = 0;
  const double no_data = band->GetNoDataValue(&has_no_data);
  const double scale = band->GetScale(), offset = band->GetOffset();
  std::vector<bool> valid(nx * ny);
  for (size_t k = 0; k < height.size(); ++k) {
    valid[k] = !(has_no_data && height[k] == no_data) && std::isfinite(height[k]);
    height[k] = height[k] * scale + offset;
  }

  // GDAL's map coordinates (east first) → the CRS's own axis order.
  OGRSpatialReference gis(*srs);
  gis.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  const std::vector<int> mapping = gis.GetDataAxisToSRSAxisMapping();
  const auto point = [&](size_t i, size_t j) {
    const double u = static_cast<double>(i) + 0.5, v = static_cast<double>(j) + 0.5;  // the cell's centre
    const double data[2] = {gt[0] + u * gt[1] + v * gt[2], gt[3] + u * gt[4] + v * gt[5]};
    double axis[3] = {0, 0, height[j * nx + i]};
    for (int d = 0; d < 2; ++d) {
      const int m = d < static_cast<int>(mapping.size()) ? mapping[static_cast<size_t>(d)] : d + 1;
      axis[std::abs(m) - 1] = m < 0 ? -data[d] : data[d];
    }
    return Vec3{axis[0], axis[1], axis[2]};
  };
  const auto east_north = [&](size_t i, size_t j) {
    const double u = static_cast<double>(i) + 0.5, v = static_cast<double>(j) + 0.5;
    return std::array<double, 2>{gt[0] + u * gt[1] + v * gt[2], gt[3] + u * gt[4] + v * gt[5]};
  };

  CityObject terrain;
  terrain.id = "terrain";
  terrain.type = "TINRelief";
  terrain.lod = 10;
  for (size_t j = 0; j + 1 < ny; ++j) {
    for (size_t i = 0; i + 1 < nx; ++i) {
      const size_t corners[4][2] = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}};
      bool all = true;
      for (const auto& c : corners) all = all && valid[c[1] * nx + c[0]];
      if (!all) continue;
      for (const auto& tri : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
        std::array<size_t, 3> k{};
        for (int m = 0; m < 3; ++m) k[static_cast<size_t>(m)] = static_cast<size_t>(tri[static_cast<size_t>(m)]);
        // Counter-clockwise seen from above, whichever way the raster's rows run.
        const auto a = east_north(corners[k[0]][0], corners[k[0]][1]);
        const auto b = east_north(corners[k[1]][0], corners[k[1]][1]);
        const auto c = east_north(corners[k[2]][0], corners[k[2]][1]);
        if ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) < 0) std::swap(k[1], k[2]);
        CitySurface surface;
        surface.rings.emplace_back();
        for (size_t m : k) surface.rings[0].push_back(point(corners[m][0], corners[m][1]));
        terrain.surfaces.push_back(std::move(surface));
      }
    }
  }
  if (terrain.surfaces.empty())
    throw InputError(name + ": the terrain DEM has no cell with heights at its four corners");
  CityModel model;
  model.crs = crs_of(*srs);
  model.objects.push_back(std::move(terrain));
  return model;
}

}  // namespace skylit
