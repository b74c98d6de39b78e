// Coordinates on the earth for city models and terrain: a file's CRS to WGS 84
// latitude, longitude and ellipsoidal height (EPSG:4979) by PROJ, and those to the
// scene's local frame around an origin. Double precision throughout; only the
// placed scene is single precision (Embree).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "skylit/core/vec3.h"

namespace skylit {

// A point on the earth in WGS 84 (EPSG:4979): geodetic latitude and longitude, height
// above the ellipsoid (or, where PROJ has no geoid grid for the file's vertical datum,
// the file's height as given: PROJ's "ballpark" vertical step).
struct GeoPoint {
  double latitude_deg = 0;
  double longitude_deg = 0;
  double height_m = 0;
};

// The standard coefficient of terrestrial refraction over land by day (C. F. Gauss's
// value; a line of sight curves down with 0.13 times the earth's curvature).
inline constexpr double kStandardRefractionK = 0.13;
// The earth's mean radius (IUGG, R1 = (2a + b)/3 of GRS 80).
inline constexpr double kEarthMeanRadiusM = 6371008.8;

// How far a point at horizontal distance d from the viewer lies below the viewer's
// horizontal plane, as seen through the refracting air: d²/(2R)·(1 − k).
double curvature_drop_m(double distance_m, double refraction_k);

// "EPSG:7415" for "https://www.opengis.net/def/crs/EPSG/0/7415",
// "http://www.opengis.net/def/crs/EPSG/0/7415", "urn:ogc:def:crs:EPSG::7415" or
// "EPSG:7415"; anything else unchanged (a PROJ string, WKT).
std::string normalized_crs_name(const std::string& name);

// Transforms points given in a CRS (in its own axis order: easting, northing, height
// for most projected CRSs; northing first for some, e.g. EPSG:6677; latitude first
// for geographic ones; or with the two horizontal axes the other way round where
// fit_axis_order finds the file so) to WGS 84. A compound CRS goes through its
// horizontal part, the heights as given.
class CrsToWgs84 {
 public:
  // Throws InputError "<source>: <what is wrong>" if PROJ does not know the CRS.
  CrsToWgs84(const std::string& crs, const std::string& source);
  ~CrsToWgs84();
  CrsToWgs84(const CrsToWgs84&) = delete;
  CrsToWgs84& operator=(const CrsToWgs84&) = delete;

  // For a projected CRS: whether `sample` (a point of the file) lands inside the CRS's
  // area of use only with its first two coordinates exchanged, and if so reads every
  // point so from now on. Files write easting first whatever the CRS's definition says
  // (CityJSON always; German state models under AdV's names of Gauss-Krüger zones,
  // EPSG:31466–31469, whose EPSG order is northing first; Helsinki's EPSG:3879), and some
  // follow the definition (Japan's plane rectangular systems, northing first): the area of
  // use tells them apart. Geographic CRSs keep their order (latitude first in GML).
  bool fit_axis_order(const Vec3& sample);
  bool axes_swapped() const { return swapped_; }

  // Throws InputError naming the first point PROJ cannot transform.
  std::vector<GeoPoint> transform(const std::vector<Vec3>& points) const;
  GeoPoint transform(const Vec3& point) const;

 private:
  std::optional<GeoPoint> try_transform(const Vec3& point, bool swapped) const;
  bool inside_area_of_use(const GeoPoint& point) const;

  struct Proj;
  std::unique_ptr<Proj> proj_;
  std::string crs_, source_;
  bool geographic_ = false, swapped_ = false;
  std::optional<std::array<double, 4>> area_of_use_;  // west, south, east, north (degrees)
};

// The scene's local frame: x east, y north, z up, metres, the origin at `origin`.
// Horizontally the azimuthal equidistant projection of the WGS 84 ellipsoid centred
// on the origin: each point's distance from the origin and its TRUE azimuth (from
// the meridian, not a map grid's north) are kept exactly, which is what a viewer at
// the site sees and what the sun's azimuth is measured from. z is the height above
// the origin's.
class LocalFrame {
 public:
  explicit LocalFrame(const GeoPoint& origin);
  ~LocalFrame();
  LocalFrame(const LocalFrame&) = delete;
  LocalFrame& operator=(const LocalFrame&) = delete;

  const GeoPoint& origin() const { return origin_; }
  std::vector<Vec3> to_local(const std::vector<GeoPoint>& points) const;
  Vec3 to_local(const GeoPoint& point) const;
  GeoPoint to_geographic(const Vec3& local) const;

 private:
  struct Proj;
  std::unique_ptr<Proj> proj_;
  GeoPoint origin_;
};

}  // namespace skylit
