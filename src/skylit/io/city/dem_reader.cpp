// GDAL reads the raster, its geotransform (pixel → map coordinates, in GIS order:
// east first) and its CRS; the axis mapping GDAL keeps for that CRS puts each point
// back into the CRS's own axis order.
#include "skylit/io/city/dem_reader.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <mutex>
#include <string>
#include <vector>

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include "skylit/core/error.h"
#include "skylit/core/formatted.h"
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

// GDAL's messages are gathered for ours, not printed: a damaged file gives one line.
class QuietGdalErrors {
 public:
  QuietGdalErrors() {
    CPLErrorReset();
    CPLPushErrorHandler(CPLQuietErrorHandler);
  }
  ~QuietGdalErrors() { CPLPopErrorHandler(); }
  QuietGdalErrors(const QuietGdalErrors&) = delete;
  QuietGdalErrors& operator=(const QuietGdalErrors&) = delete;
  // GDAL's last message, or what is known without one (a file it does not recognise
  // leaves none).
  static std::string reason() {
    const std::string message = CPLGetLastErrorMsg();
    return message.empty() ? "not a raster GDAL reads" : message;
  }
};

// Metres per unit of a height unit's name (GDAL's band unit or a vertical CRS's unit):
// feet are the international foot unless US survey feet are named; `known` is false
// for a name not recognised (read as metres).
double metres_per_unit(std::string name, bool& known) {
  for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  known = true;
  const bool us = name.find("us") != std::string::npos || name.find("survey") != std::string::npos;
  if (name.find("foot") != std::string::npos || name.find("feet") != std::string::npos || name == "ft" ||
      name == "ftus" || name == "us-ft" || name == "us_ft")
    return us ? 1200.0 / 3937.0 : 0.3048;
  if (name == "cm" || name.rfind("centimet", 0) == 0) return 0.01;
  if (name == "mm" || name.rfind("millimet", 0) == 0) return 0.001;
  if (name.empty() || name == "m" || name.rfind("metre", 0) == 0 || name.rfind("meter", 0) == 0) return 1;
  known = false;
  return 1;
}

}  // namespace

DemTerrain read_dem_terrain(const std::filesystem::path& file, bool crs_given, size_t max_cells) {
  const std::string name = file.string();
  require_regular_file(file, "terrain DEM");
  static std::once_flag registered;
  std::call_once(registered, [] { GDALAllRegister(); });
  const QuietGdalErrors quiet;
  GDALDatasetUniquePtr dataset(GDALDataset::Open(name.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!dataset) throw InputError(name + ": cannot read the terrain DEM: " + QuietGdalErrors::reason());
  double gt[6];
  if (dataset->GetGeoTransform(gt) != CE_None)
    throw InputError(name + ": the terrain DEM has no georeferencing (no geotransform)");
  const OGRSpatialReference* srs = dataset->GetSpatialRef();
  const bool has_crs = srs != nullptr && !srs->IsEmpty();
  if (!has_crs && !crs_given)
    throw InputError(name + ": the terrain DEM names no coordinate reference system; give the terrain's \"crs\"");
  if (dataset->GetRasterCount() < 1) throw InputError(name + ": the terrain DEM has no band");
  DemTerrain out;
  out.file_width = dataset->GetRasterXSize();
  out.file_height = dataset->GetRasterYSize();
  if (out.file_width < 2 || out.file_height < 2)
    throw InputError(name + ": the terrain DEM has fewer than 2 × 2 cells");
  // A larger raster is read averaged down to fit, its aspect kept.
  const double cells = static_cast<double>(out.file_width) * out.file_height;
  const double shrink = std::max(1.0, std::sqrt(cells / static_cast<double>(max_cells)));
  out.read_width = std::max(2, static_cast<int>(out.file_width / shrink));
  out.read_height = std::max(2, static_cast<int>(out.file_height / shrink));
  const size_t nx = static_cast<size_t>(out.read_width), ny = static_cast<size_t>(out.read_height);
  const double sx = static_cast<double>(out.file_width) / out.read_width;
  const double sy = static_cast<double>(out.file_height) / out.read_height;
  gt[1] *= sx, gt[4] *= sx, gt[2] *= sy, gt[5] *= sy;
  out.cell_size_x = std::hypot(gt[1], gt[4]);
  out.cell_size_y = std::hypot(gt[2], gt[5]);

  GDALRasterBand* band = dataset->GetRasterBand(1);
  std::vector<double> height(nx * ny);
  GDALRasterIOExtraArg resampling;
  INIT_RASTERIO_EXTRA_ARG(resampling);
  resampling.eResampleAlg = GRIORA_Average;  // no-data cells are left out of the means
  if (band->RasterIO(GF_Read, 0, 0, out.file_width, out.file_height, height.data(), static_cast<int>(nx),
                     static_cast<int>(ny), GDT_Float64, 0, 0, &resampling) != CE_None)
    throw InputError(name + ": cannot read the terrain DEM's heights: " + QuietGdalErrors::reason());
  int has_no_data = 0;
  const double no_data = band->GetNoDataValue(&has_no_data);
  const double scale = band->GetScale(), offset = band->GetOffset();
  // The heights' unit: the band's, else the vertical CRS's (a compound CRS in US feet).
  out.height_unit = band->GetUnitType();
  if (out.height_unit.empty() && has_crs && srs->IsCompound()) {
    const char* vertical = nullptr;
    srs->GetTargetLinearUnits("VERT_CS", &vertical);
    if (vertical != nullptr) out.height_unit = vertical;
  }
  out.metres_per_height_unit = metres_per_unit(out.height_unit, out.height_unit_known);
  std::vector<bool> valid(nx * ny);
  for (size_t k = 0; k < height.size(); ++k) {
    valid[k] = !(has_no_data && height[k] == no_data) && std::isfinite(height[k]);
    if (!has_no_data && (height[k] == -9999 || height[k] == -32767 || height[k] == -32768)) {
      ++out.undeclared_no_data_cells;
      out.undeclared_no_data_value = height[k];
    }
    height[k] = (height[k] * scale + offset) * out.metres_per_height_unit;
    if (valid[k] && !(height[k] >= kLowestTerrainM && height[k] <= kHighestTerrainM))
      throw InputError(name + ": the terrain DEM's cell at pixel " + std::to_string(k % nx) + ", line " +
                       std::to_string(k / nx) + (shrink > 1 ? " (of the raster resampled to fit)" : "") +
                       " has a height of " + formatted("%g", height[k]) +
                       " m, beyond any terrain on earth: a no-data value the file does not declare?");
  }

  // GDAL's map coordinates (east first) → the CRS's own axis order.
  // Without a CRS of its own the scene's gives the order, and the file's is GDAL's.
  OGRSpatialReference gis;
  if (has_crs) gis = *srs;
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
  if (has_crs) out.model.crs = crs_of(*srs);
  out.model.objects.push_back(std::move(terrain));
  return out;
}

}  // namespace skylit
