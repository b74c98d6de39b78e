#include "skylit/io/city/city_placement.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "skylit/core/error.h"
#include "skylit/geometry/polygon_triangulation.h"

namespace skylit {

namespace {

// A surface of a building without semantics is a roof when its normal is within 75°
// of straight up (roofs are rarely steeper), ground when it faces down as much, a
// wall otherwise.
constexpr double kRoofNormalZ = 0.25;

bool is_building_type(const std::string& type) { return type == "Building" || type == "BuildingPart"; }

std::string surface_class(const std::string& type, const CitySurface& surface, const std::vector<Vec3>& outer) {
  if (!surface.semantic.empty()) return type + "." + surface.semantic;
  if (!is_building_type(type)) return type;
  const Vec3 n = newell_normal(outer);
  const double len = length(n);
  if (!(len > 0)) return type + ".WallSurface";
  if (n.z / len >= kRoofNormalZ) return type + ".RoofSurface";
  if (n.z / len <= -kRoofNormalZ) return type + ".GroundSurface";
  return type + ".WallSurface";
}

// The points of every ring of every surface, in order, with where each object's begin.
struct FlatPoints {
  std::vector<Vec3> points;
  std::vector<size_t> object_start;  // one per object, and the end
};

FlatPoints flatten(const CityModel& model) {
  FlatPoints flat;
  for (const CityObject& object : model.objects) {
    flat.object_start.push_back(flat.points.size());
    for (const CitySurface& surface : object.surfaces)
      for (const auto& ring : surface.rings) flat.points.insert(flat.points.end(), ring.begin(), ring.end());
  }
  flat.object_start.push_back(flat.points.size());
  return flat;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

// Which objects the region takes, from each one's mean position.
std::vector<bool> objects_in_region(const CityRegion& region, const FlatPoints& flat, const std::vector<GeoPoint>& geo,
                                    const std::vector<Vec3>& local, const LocalFrame& frame) {
  const size_t count = flat.object_start.size() - 1;
  std::vector<bool> inside(count, false);
  Vec3 centre_local{0, 0, 0};
  if (region.center_lonlat_deg)
    centre_local = frame.to_local(GeoPoint{(*region.center_lonlat_deg)[1], (*region.center_lonlat_deg)[0], 0});
  for (size_t o = 0; o < count; ++o) {
    const size_t begin = flat.object_start[o], end = flat.object_start[o + 1];
    if (begin == end) continue;
    double x = 0, y = 0, lon = 0, lat = 0;
    for (size_t i = begin; i < end; ++i) {
      x += local[i].x, y += local[i].y;
      lon += geo[i].longitude_deg, lat += geo[i].latitude_deg;
    }
    const double n = static_cast<double>(end - begin);
    if (region.center_lonlat_deg) {
      inside[o] = std::hypot(x / n - centre_local.x, y / n - centre_local.y) <= region.radius_m;
    } else {
      const auto& b = *region.bbox_lonlat_deg;
      inside[o] = lon / n >= b[0] && lat / n >= b[1] && lon / n <= b[2] && lat / n <= b[3];
    }
  }
  return inside;
}

// The surface's appearance on each of its triangles (`triangles` index its rings'
// points in order); texture coordinates only when some surface of the model has some.
void add_appearance(const CitySurface& surface, const std::vector<TriangleIndices>& triangles, bool model_textured,
                    std::vector<std::array<float, 2>>& uvs, PlacedCityObject& out) {
  const bool textured = surface.texture != CitySurface::kNone;
  uvs.clear();
  if (textured)
    for (const auto& ring : surface.texture_coordinates)
      for (const auto& st : ring) uvs.push_back({st[0], 1.0F - st[1]});  // t runs up, v down
  for (const TriangleIndices& t : triangles) {
    out.triangle_material.push_back(surface.material);
    out.triangle_texture.push_back(surface.texture);
    if (!model_textured) continue;
    CornerUvs corners{};
    if (textured)
      for (size_t k = 0; k < 3; ++k) corners[k] = uvs[t[k]];
    out.corner_uvs.push_back(corners);
  }
}

GeoPoint region_centre(const CityRegion& region) {
  if (region.center_lonlat_deg) return {(*region.center_lonlat_deg)[1], (*region.center_lonlat_deg)[0], 0};
  const auto& b = *region.bbox_lonlat_deg;
  return {0.5 * (b[1] + b[3]), 0.5 * (b[0] + b[2]), 0};
}

}  // namespace

PlacedCity place_city_model(const CityModel& model, const CityPlacementOptions& options, const std::string& source) {
  PlacedCity placed;
  placed.crs = options.crs.empty() ? model.crs : options.crs;
  if (placed.crs.empty())
    throw InputError(source + ": the file names no coordinate reference system: give the object a \"crs\"");
  CrsToWgs84 to_wgs84(placed.crs, source);
  const FlatPoints flat = flatten(model);
  // The centre of the model's box in its CRS: where the axis order is judged, and the
  // origin when neither a site nor a region gives one.
  BoundingBox box;
  for (const Vec3& p : flat.points) box.add(p);
  if (!flat.points.empty()) placed.axes_swapped = to_wgs84.fit_axis_order(box.center());
  placed.axes_swapped_by_format = placed.axes_swapped && model.easting_first;
  const std::vector<GeoPoint> geo = to_wgs84.transform(flat.points);

  // The origin's latitude and longitude: the site, else the region's centre, else the
  // model's. Its height is set below, once the objects are known.
  placed.origin_from_model = !options.origin;
  if (options.origin)
    placed.origin = *options.origin;
  else if (options.region)
    placed.origin = region_centre(*options.region);
  else if (!flat.points.empty())
    placed.origin = to_wgs84.transform(box.center());
  LocalFrame frame(GeoPoint{placed.origin.latitude_deg, placed.origin.longitude_deg, 0});
  std::vector<Vec3> local = frame.to_local(geo);

  const size_t count = model.objects.size();
  std::vector<bool> taken(count, true);
  if (options.region) taken = objects_in_region(*options.region, flat, geo, local, frame);

  // The ground level: the median of the taken objects' lowest points (a few bridges or
  // canals do not move it), which becomes z = 0, where the scene's ground plane lies.
  std::vector<double> lowest;
  double farthest = 0;
  for (size_t o = 0; o < count; ++o) {
    if (!taken[o]) continue;
    double low = INFINITY;
    for (size_t i = flat.object_start[o]; i < flat.object_start[o + 1]; ++i) {
      low = std::min(low, local[i].z);
      farthest = std::max(farthest, std::hypot(local[i].x, local[i].y));
    }
    if (std::isfinite(low)) lowest.push_back(low);
  }
  placed.origin.height_m = options.ground_height_m ? *options.ground_height_m : median(lowest);
  placed.curvature_applied = options.curvature == EarthCurvature::on ||
                             (options.curvature == EarthCurvature::automatic && farthest > kCurvatureAutoDistanceM);
  for (Vec3& p : local) {
    p.z -= placed.origin.height_m;
    if (placed.curvature_applied) p.z -= curvature_drop_m(std::hypot(p.x, p.y), options.refraction_k);
  }

  std::map<std::string, uint32_t> class_index;
  std::vector<std::vector<Vec3>> rings;
  std::vector<std::array<float, 2>> uvs;  // the surface's points' texture coordinates
  const bool appearances = !model.materials.empty() || !model.textures.empty();
  const bool textured = std::any_of(model.objects.begin(), model.objects.end(), [](const CityObject& o) {
    return std::any_of(o.surfaces.begin(), o.surfaces.end(),
                       [](const CitySurface& s) { return s.texture != CitySurface::kNone; });
  });
  for (size_t o = 0; o < count; ++o) {
    if (!taken[o]) {
      ++placed.objects_outside_region;
      continue;
    }
    const CityObject& object = model.objects[o];
    PlacedCityObject out{object.id, object.type, object.lod, {}, {}, {}, {}, {}};
    size_t next = flat.object_start[o];
    for (const CitySurface& surface : object.surfaces) {
      rings.clear();
      for (const auto& ring : surface.rings) {
        rings.emplace_back(local.begin() + static_cast<std::ptrdiff_t>(next),
                           local.begin() + static_cast<std::ptrdiff_t>(next + ring.size()));
        next += ring.size();
      }
      const auto triangles = rings.empty() ? std::vector<TriangleIndices>{} : triangulate_polygon_3d(rings);
      if (triangles.empty()) {
        ++placed.degenerate_surfaces;
        continue;
      }
      const std::string key = surface_class(object.type, surface, rings[0]);
      const auto [it, added] = class_index.try_emplace(key, static_cast<uint32_t>(placed.classes.size()));
      if (added) placed.classes.push_back(key);
      const auto base = static_cast<uint32_t>(out.mesh.vertices.size());
      for (const auto& ring : rings) out.mesh.vertices.insert(out.mesh.vertices.end(), ring.begin(), ring.end());
      for (const TriangleIndices& t : triangles) {
        out.mesh.triangles.push_back({base + t[0], base + t[1], base + t[2]});
        out.triangle_class.push_back(it->second);
      }
      if (appearances) add_appearance(surface, triangles, textured, uvs, out);
    }
    if (!out.mesh.empty()) placed.objects.push_back(std::move(out));
  }
  return placed;
}

}  // namespace skylit
