// Reading a digital elevation model (a GeoTIFF, or any raster GDAL reads) as terrain:
// a TIN relief in the raster's own CRS, so that it is placed in the scene exactly as a
// city model in that CRS is (city_placement.h).
#pragma once

#include <cstddef>
#include <filesystem>

#include "skylit/io/city/city_model.h"

namespace skylit {

// The most raster cells read: 16.7 million (4096²), two triangles each; a larger DEM
// is refused with a message to crop or resample it (gdal_translate -srcwin / -tr).
inline constexpr size_t kMaxDemCells = size_t{1} << 24;

// The first band's heights (scaled and offset as the band says; metres) at the cells'
// centres, as one "TINRelief" object of two triangles per cell whose four corners all
// have a height (cells touching the no-data value are left out), each triangle
// counter-clockwise seen from above. The CRS is "EPSG:code" when the raster names
// one, else its WKT; points are in the CRS's own axis order (latitude first for a
// geographic CRS), as a city file's are. Throws InputError naming the file for a file
// GDAL cannot read, without georeferencing or CRS, too large, or without any cell.
CityModel read_dem_terrain(const std::filesystem::path& file);

}  // namespace skylit
