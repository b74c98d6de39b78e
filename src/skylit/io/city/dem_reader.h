// Reading a digital elevation model (a GeoTIFF, or any raster GDAL reads) as terrain:
// a TIN relief in the raster's own CRS, so that it is placed in the scene exactly as a
// city model in that CRS is (city_placement.h).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

#include "skylit/io/city/city_model.h"

namespace skylit {

// The most raster cells read: about a million (1024²), two triangles each. A city
// model's surfaces cost about 1 kB of memory a triangle pair by the time they are
// placed and shaded (a 2048² DEM took 4.5 GB and 110 s), so a larger DEM is read
// resampled by GDAL's averaging to fit, and `skylit info` says so.
inline constexpr size_t kMaxDemCells = size_t{1} << 20;

// Heights beyond these are no terrain on earth (the deepest sea floor, above the
// highest summit): a no-data value the file does not declare, or a unit mistake.
inline constexpr double kLowestTerrainM = -12000, kHighestTerrainM = 9000;

struct DemTerrain {
  // One "TINRelief" object. Its CRS is "EPSG:code" when the raster names one, else
  // its WKT; empty when it names none (the scene's `crs` then says which).
  CityModel model;
  int file_width = 0, file_height = 0;      // cells in the file
  int read_width = 0, read_height = 0;      // cells read: fewer when resampled to kMaxDemCells
  double cell_size_x = 0, cell_size_y = 0;  // of the cells read, in the CRS's units
  // The heights' unit as the file names it (the band's unit, else its vertical CRS's),
  // and metres per unit; "" when it names none (metres).
  std::string height_unit;
  double metres_per_height_unit = 1;
  bool height_unit_known = true;  // false: a unit name not recognised, read as metres
  // Without a declared no-data value: how many cells hold one of the values commonly
  // written for it (-9999, -32767, -32768), read as heights (pits), and which.
  size_t undeclared_no_data_cells = 0;
  double undeclared_no_data_value = 0;
};

// The first band's heights (scaled and offset as the band says, converted to metres) at
// the cells' centres, as two triangles per cell whose four corners all have a height
// (cells touching the no-data value are left out), each counter-clockwise seen from
// above. Points are in the CRS's own axis order (latitude first for a geographic CRS),
// as a city file's are. Throws InputError naming the file for a file GDAL cannot read,
// without georeferencing, without a CRS when `crs_given` is false, with a height beyond
// kLowestTerrainM–kHighestTerrainM (naming the cell), or without any cell.
// `max_cells` other than kMaxDemCells is for tests.
DemTerrain read_dem_terrain(const std::filesystem::path& file, bool crs_given = false, size_t max_cells = kMaxDemCells);

}  // namespace skylit
