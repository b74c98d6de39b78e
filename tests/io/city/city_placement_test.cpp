// Placement of city models on the earth (io/city/city_placement.h): the real samples
// in ../shared/data/models against PROJ's command-line tools, true north in a map
// grid whose north is not, the curvature drop, the region.
#include "skylit/io/city/city_placement.h"

#include <geodesic.h>
#include <gtest/gtest.h>
#include <proj.h>

#include <cmath>
#include <filesystem>

#include "../../test_support.h"
#include "skylit/core/angles.h"
#include "skylit/geometry/ray_tracer.h"
#include "skylit/io/city/cityjson_reader.h"
#include "skylit/sun/solar_position.h"

namespace skylit {
namespace {

// A surface of these rings, without semantics or appearance.
CitySurface surface_of(std::vector<std::vector<Vec3>> rings) {
  CitySurface surface;
  surface.rings = std::move(rings);
  return surface;
}

const std::filesystem::path kModels = std::filesystem::path(SKYLIT_SOURCE_DIR) / "../shared/data/models";

// Where the model's vertices were placed: the one nearest to `expected`, and how far.
double distance_to_nearest_vertex(const PlacedCity& city, const Vec3& expected) {
  double nearest = INFINITY;
  for (const PlacedCityObject& o : city.objects)
    for (const Vec3& v : o.mesh.vertices) nearest = std::min(nearest, length(v - expected));
  return nearest;
}

// A point at geodesic distance s and true azimuth az from the origin, in the local
// frame: the independent answer that `geod -I` gives (below).
Vec3 from_azimuth(double azimuth_deg, double distance_m, double z) {
  return {distance_m * std::sin(radians(azimuth_deg)), distance_m * std::cos(radians(azimuth_deg)), z};
}

// The tolerances are the issue's: 1 cm and 1e-6° (about 0.1 m); PROJ's transformation
// and geodesics are exact to far better (nanometres), so any miss is our frame's.
constexpr double kPositionToleranceM = 0.01;
constexpr double kAngleToleranceDeg = 1e-6;

TEST(CityPlacement, RotterdamSiteAndVerticesAgreeWithCs2csAndGeod) {
  const auto file = kModels / "rotterdam_one.city.json";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "no shared models";
  const PlacedCity city = place_city_model(read_cityjson_file(file), {}, file.string());
  // The file's CRS is EPSG:7415 (RD New + NAP height), placed through its horizontal
  // part (geo_frame.h). The centre of the vertices' box in RD, (90938.528, 435647.363), by
  //   echo 90938.528 435647.363 | cs2cs -f %.10f EPSG:28992 EPSG:4326
  //   → 51.9056375705 4.4562821710
  // (cs2cs EPSG:7415 EPSG:4979 gives 51.9065947, 4.4565823, 108 m off: without the NAP
  // grid PROJ's compound operation is a "ballpark" geographic offset, no datum shift.)
  ASSERT_TRUE(city.origin_from_model);
  EXPECT_NEAR(city.origin.latitude_deg, 51.9056375705, kAngleToleranceDeg);
  EXPECT_NEAR(city.origin.longitude_deg, 4.4562821710, kAngleToleranceDeg);
  // Vertices 0 and 7 (the file's first roof vertex, a wall's; RD (90933.358, 435649.498)
  // and (90937.034, 435644.309)) by cs2cs as above, then
  //   echo 51.9056375705 4.4562821710 LAT LON | geod -I +ellps=WGS84 -f %.10f
  // giving the true azimuth and the distance from the site. The ground level is 0 m.
  EXPECT_LT(distance_to_nearest_vertex(city, from_azimuth(-68.2951117748, 5.594, 15.311)), kPositionToleranceM);
  EXPECT_LT(distance_to_nearest_vertex(city, from_azimuth(-154.6662029455, 3.400, 11.136)), kPositionToleranceM);
  EXPECT_NEAR(city.origin.height_m, 0.0, 1e-9);
}

TEST(CityPlacement, DelftSiteAndVerticesAgreeWithCs2csAndGeod) {
  const auto file = kModels / "delft.city.json";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "no shared models";
  const PlacedCity city = place_city_model(read_cityjson_file(file), {}, file.string());
  // echo 84878.6535 447586.8175 | cs2cs -f %.10f EPSG:28992 EPSG:4326 (see Rotterdam)
  EXPECT_NEAR(city.origin.latitude_deg, 52.0122074939, kAngleToleranceDeg);
  EXPECT_NEAR(city.origin.longitude_deg, 4.3657961633, kAngleToleranceDeg);
  // Vertices 0 (85027.751, 447448.180, 0.120) and 5000 (85046.828, 447447.892, 13.672)
  // by cs2cs and geod -I as in the Rotterdam test; heights above the ground level. (The
  // ballpark offset also read Bessel's latitudes and longitudes on WGS 84's larger
  // ellipsoid: these distances were 2.4 and 2.6 cm, 1.2e-4, too long.)
  const double ground = city.origin.height_m;
  EXPECT_LT(distance_to_nearest_vertex(city, from_azimuth(132.1123692627, 203.606, 0.120 - ground)),
            kPositionToleranceM);
  EXPECT_LT(distance_to_nearest_vertex(city, from_azimuth(128.7537329153, 218.148, 13.672 - ground)),
            kPositionToleranceM);
  EXPECT_FALSE(city.curvature_applied);  // all within 1 km of the centre
}

// A vertical pole (0.1 m square, 200 m tall) and a marker 100 m from it along the
// sun's true shadow azimuth, computed on the ellipsoid (GeographicLib's direct
// problem, PROJ's geodesic.h), both written in UTM zone 31N 2.9° east of the zone's
// central meridian at 60° N, where grid north lies 2.5° west of true north.
// Files write easting first whatever their CRS's definition says: a German state model
// under AdV's name of Gauss-Krüger zone 4 (EPSG:31468, northing first by EPSG; the OGC's
// CityGML 3.0 Dynamizer sample near Munich), Helsinki's EPSG:3879 as CityJSON writes it.
// Read as defined they land in Greece, or nowhere; read the other way round inside the
// CRS's area of use, where
//   echo N E | cs2cs -f %.8f EPSG:31468 EPSG:4326 (and EPSG:3879)
// puts them. Japan's plane systems are written as defined (northing first, EPSG:6677):
// both orders fall inside Japan there, and the definition's is kept.
TEST(CityPlacement, AFileWritingEastingFirstForANorthingFirstCrsIsReadSo) {
  struct Case {
    std::string crs;
    double first, second;
    double latitude_deg, longitude_deg;
    bool swapped;
  };
  for (const Case& c : {Case{"EPSG:31468", 4490663, 5322007, 48.03610485, 11.87335469, true},
                        Case{"EPSG:3879", 25496000, 6672000, 60.16088692, 24.92796536, true},
                        Case{"EPSG:6677", -35000, -5000, 35.684516, 139.778092, false}}) {
    SCOPED_TRACE(c.crs);
    CityModel model;
    model.crs = c.crs;
    CityObject block{"block", "Building", 10, {}};
    block.surfaces.push_back(surface_of({{{c.first - 5, c.second - 5, 0},
                                          {c.first + 5, c.second - 5, 0},
                                          {c.first + 5, c.second + 5, 0},
                                          {c.first - 5, c.second + 5, 0}}}));
    model.objects.push_back(block);
    const PlacedCity city = place_city_model(model, {}, "test");
    EXPECT_EQ(city.axes_swapped, c.swapped);
    EXPECT_FALSE(city.axes_swapped_by_format);  // a GML file's order is its CRS's: worth a warning
    EXPECT_NEAR(city.origin.latitude_deg, c.latitude_deg, 1e-6);
    EXPECT_NEAR(city.origin.longitude_deg, c.longitude_deg, 1e-6);
    // CityJSON writes easting first by its own rule: read the same, nothing to warn of.
    model.easting_first = true;
    const PlacedCity as_cityjson = place_city_model(model, {}, "test");
    EXPECT_EQ(as_cityjson.axes_swapped_by_format, c.swapped);
    EXPECT_NEAR(as_cityjson.origin.latitude_deg, c.latitude_deg, 1e-6);
  }
}

TEST(CityPlacement, ShadowsFallAlongTheSunsTrueAzimuthInAMapGrid) {
  const double pole_lat = 60.0, pole_lon = 5.9;
  const OffsetDateTime when = parse_offset_date_time("2026-06-21T17:00:00+02:00", "test");
  const SolarPosition sun = solar_position(SiteLocation{pole_lat, pole_lon, 0}, when);
  ASSERT_GT(sun.altitude_deg, 10);
  ASSERT_LT(sun.altitude_deg, 60);  // the ray from the marker meets the pole below 200 m
  const double shadow_azimuth = sun.azimuth_deg + 180;

  geod_geodesic g;
  geod_init(&g, 6378137, 1 / 298.257223563);
  double marker_lat = 0, marker_lon = 0;
  geod_direct(&g, pole_lat, pole_lon, shadow_azimuth, 100.0, &marker_lat, &marker_lon, nullptr);
  PJ_CONTEXT* context = proj_context_create();
  PJ* to_utm = proj_create_crs_to_crs(context, "EPSG:4326", "EPSG:32631", nullptr);
  const PJ_COORD pole = proj_trans(to_utm, PJ_FWD, proj_coord(pole_lat, pole_lon, 0, 0));
  const PJ_COORD marker = proj_trans(to_utm, PJ_FWD, proj_coord(marker_lat, marker_lon, 0, 0));
  // The grid convergence here, to be sure the test could fail: true and grid north
  // differ by far more than the tolerance.
  const double grid_azimuth = degrees(std::atan2(marker.v[0] - pole.v[0], marker.v[1] - pole.v[1]));
  ASSERT_GT(std::abs(std::remainder(grid_azimuth - shadow_azimuth, 360.0)), 2.0);
  proj_destroy(to_utm);
  proj_context_destroy(context);

  CityModel model;
  model.crs = "EPSG:32631";
  const double e = pole.v[0], n = pole.v[1], h = 0.05;
  const Vec3 c[8] = {{e - h, n - h, 0},   {e + h, n - h, 0},   {e + h, n + h, 0},   {e - h, n + h, 0},
                     {e - h, n - h, 200}, {e + h, n - h, 200}, {e + h, n + h, 200}, {e - h, n + h, 200}};
  CityObject pole_object{"pole", "GenericCityObject", 20, {}};
  for (const auto& face : {std::array{0, 1, 5, 4}, std::array{1, 2, 6, 5}, std::array{2, 3, 7, 6},
                           std::array{3, 0, 4, 7}, std::array{4, 5, 6, 7}})
    pole_object.surfaces.push_back(surface_of({{c[face[0]], c[face[1]], c[face[2]], c[face[3]]}}));
  const double me = marker.v[0], mn = marker.v[1];
  CityObject marker_object{"marker", "GenericCityObject", 20, {}};
  marker_object.surfaces.push_back(
      surface_of({{{me - 0.01, mn - 0.01, 0}, {me + 0.01, mn - 0.01, 0}, {me, mn + 0.01, 0}}}));
  model.objects = {pole_object, marker_object};

  CityPlacementOptions options;
  options.origin = GeoPoint{pole_lat, pole_lon, 0};
  const PlacedCity city = place_city_model(model, options, "pole");
  ASSERT_EQ(city.objects.size(), 2u);
  Vec3 spot{0, 0, 0};
  for (const Vec3& v : city.objects[1].mesh.vertices) spot += v / 3.0;
  // The marker's azimuth from the pole, in the local frame, is the true one (0.1°).
  EXPECT_NEAR(std::remainder(degrees(std::atan2(spot.x, spot.y)) - shadow_azimuth, 360.0), 0.0, 0.1);

  // And the renderer's shadow test: the ray toward the sun from the marker meets the
  // pole; the pole subtends ±0.03° from there, so this holds the direction to that.
  RayTracer tracer;
  tracer.add_mesh(city.objects[0].mesh);
  tracer.commit();
  const auto toward_sun = [&](double azimuth_deg) {
    const double alt = radians(sun.altitude_deg), az = radians(azimuth_deg);
    return Vec3{std::sin(az) * std::cos(alt), std::cos(az) * std::cos(alt), std::sin(alt)};
  };
  EXPECT_TRUE(tracer.intersect({spot + Vec3{0, 0, 0.001}, toward_sun(sun.azimuth_deg)}).has_value());
  // A sun 0.1° either side casts the pole's shadow beside the marker.
  EXPECT_FALSE(tracer.intersect({spot + Vec3{0, 0, 0.001}, toward_sun(sun.azimuth_deg + 0.1)}).has_value());
  EXPECT_FALSE(tracer.intersect({spot + Vec3{0, 0, 0.001}, toward_sun(sun.azimuth_deg - 0.1)}).has_value());
}

// A triangle far away: its drop below the plane is d²/(2R)(1 − k), the geometric
// drop of a sphere's surface below its tangent plane lessened by the refraction of
// the line of sight (to 1e-4 relative at 10 km: the sphere's exact drop R(1 − cos(d/R))
// differs from d²/2R by d⁴/24R³).
TEST(CityPlacement, FarGeometryDropsByTheCurvatureLessRefraction) {
  const double d = 10000;
  CityModel model;
  model.crs = "EPSG:32631";
  CityObject far{"far", "GenericCityObject", 20, {}};
  // UTM 31N at 3° E: x 500 km is the central meridian, where grid and true north agree.
  far.surfaces.push_back(surface_of({{{500000, 6650000 + d, 0}, {500001, 6650000 + d, 0}, {500000, 6650001 + d, 0}}}));
  CityObject near{"near", "GenericCityObject", 20, {}};
  near.surfaces.push_back(surface_of({{{500000, 6650000, 0}, {500001, 6650000, 0}, {500000, 6650001, 0}}}));
  model.objects = {near, far};
  CityPlacementOptions options;
  const auto origin = CrsToWgs84("EPSG:32631", "t").transform(Vec3{500000, 6650000, 0});
  options.origin = origin;
  const PlacedCity city = place_city_model(model, options, "far");
  ASSERT_TRUE(city.curvature_applied);  // automatic: past 1 km
  const double drop = -city.objects[1].mesh.vertices[0].z;
  const double distance = std::hypot(city.objects[1].mesh.vertices[0].x, city.objects[1].mesh.vertices[0].y);
  EXPECT_NEAR(drop, distance * distance / (2 * 6371008.8) * (1 - 0.13), 1e-3);
  EXPECT_NEAR(drop, 6.8, 0.1);  // the textbook figure for 10 km
  options.curvature = EarthCurvature::off;
  EXPECT_NEAR(place_city_model(model, options, "far").objects[1].mesh.vertices[0].z, 0.0, 1e-6);
}

TEST(CityPlacement, RegionTakesTheObjectsWhoseCentreLiesInIt) {
  const auto file = kModels / "delft.city.json";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "no shared models";
  const CityModel model = read_cityjson_file(file);
  const PlacedCity all = place_city_model(model, {}, file.string());
  CityPlacementOptions options;
  options.region = CityRegion{std::array{all.origin.longitude_deg, all.origin.latitude_deg}, 100.0, std::nullopt};
  const PlacedCity part = place_city_model(model, options, file.string());
  EXPECT_GT(part.objects.size(), 10u);
  EXPECT_LT(part.objects.size(), all.objects.size());
  EXPECT_EQ(part.objects.size() + part.objects_outside_region, model.objects.size());
  for (const PlacedCityObject& o : part.objects) {
    Vec3 mean{0, 0, 0};
    for (const Vec3& v : o.mesh.vertices) mean += v / static_cast<double>(o.mesh.vertices.size());
    EXPECT_LE(std::hypot(mean.x, mean.y), 100.5) << o.id;  // the region's centre is the origin
  }
}

TEST(CityPlacement, UnknownOrMissingCrsIsOneLocatedError) {
  CityModel model;
  model.crs = "EPSG:999999";
  EXPECT_NE(testing::input_error_of([&] {
              place_city_model(model, {}, "town.city.json");
            }).find("town.city.json: the coordinate reference system 'EPSG:999999' is unknown"),
            std::string::npos);
  model.crs = "";
  EXPECT_NE(testing::input_error_of([&] { place_city_model(model, {}, "town.city.json"); }).find("\"crs\""),
            std::string::npos);
}

}  // namespace
}  // namespace skylit
