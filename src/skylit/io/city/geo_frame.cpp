#include "skylit/io/city/geo_frame.h"

#include <proj.h>

#include <cmath>
#include <cstdio>
#include <regex>

#include "skylit/core/error.h"

namespace skylit {

namespace {

constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;

// A PROJ context and one operation, freed together. Each object has its own context,
// so that frames on different threads never share PROJ's state.
struct ProjHandle {
  PJ_CONTEXT* context = proj_context_create();
  PJ* operation = nullptr;
  ProjHandle() { proj_log_level(context, PJ_LOG_NONE); }
  ~ProjHandle() {
    if (operation) proj_destroy(operation);
    proj_context_destroy(context);
  }
  ProjHandle(const ProjHandle&) = delete;
  ProjHandle& operator=(const ProjHandle&) = delete;
  std::string last_error() const { return proj_context_errno_string(context, proj_context_errno(context)); }
};

bool finite(const PJ_COORD& c) { return std::isfinite(c.v[0]) && std::isfinite(c.v[1]) && std::isfinite(c.v[2]); }

std::string describe(const Vec3& p) {
  // Ten significant digits: millimetres of a projected coordinate, and a wild one
  // (1e117) short enough to read.
  char text[120];
  std::snprintf(text, sizeof text, "(%.10g, %.10g, %.10g)", p.x, p.y, p.z);
  return text;
}

}  // namespace

double curvature_drop_m(double distance_m, double refraction_k) {
  return distance_m * distance_m / (2.0 * kEarthMeanRadiusM) * (1.0 - refraction_k);
}

std::string normalized_crs_name(const std::string& name) {
  static const std::regex url(R"(^https?://www\.opengis\.net/def/crs/EPSG/[0-9.]+/([0-9]+)$)");
  static const std::regex urn(R"(^urn:ogc:def:crs:EPSG:[0-9.]*:([0-9]+)$)");
  static const std::regex epsg(R"(^EPSG:+([0-9]+)$)", std::regex::icase);
  std::smatch m;
  if (std::regex_match(name, m, url) || std::regex_match(name, m, urn) || std::regex_match(name, m, epsg))
    return "EPSG:" + m[1].str();
  return name;
}

struct CrsToWgs84::Proj : ProjHandle {};

CrsToWgs84::CrsToWgs84(const std::string& crs, const std::string& source)
    : proj_(std::make_unique<Proj>()), crs_(normalized_crs_name(crs)), source_(source) {
  PJ_CONTEXT* context = proj_->context;
  PJ* given = proj_create(context, crs_.c_str());
  if (!given || !proj_is_crs(given)) {
    if (given) proj_destroy(given);
    throw InputError(source_ + ": the coordinate reference system '" + crs + "' is unknown to PROJ");
  }
  // A compound CRS (RD New + NAP height, EPSG:7415) through its horizontal part, the
  // heights as the file gives them. Without the geoid grid of its vertical datum (not in
  // Debian's proj-data) PROJ's whole operation took a "ballpark" horizontal step too
  // (no datum shift: the 3D BAG 108 m off); with the grid it would add the geoid's
  // undulation to every height alike, which the local frame subtracts again.
  PJ* horizontal = proj_get_type(given) == PJ_TYPE_COMPOUND_CRS ? proj_crs_get_sub_crs(context, given, 0) : nullptr;
  PJ* source_crs = horizontal ? horizontal : given;
  geographic_ =
      proj_get_type(source_crs) == PJ_TYPE_GEOGRAPHIC_2D_CRS || proj_get_type(source_crs) == PJ_TYPE_GEOGRAPHIC_3D_CRS;
  double west = 0, south = 0, east = 0, north = 0;
  if (proj_get_area_of_use(context, source_crs, &west, &south, &east, &north, nullptr) && west > -1000)
    area_of_use_ = {west, south, east, north};
  PJ* wgs84 = proj_create(context, "EPSG:4979");
  // The best operation PROJ has (with its grids where installed) for each point's area.
  proj_->operation = proj_create_crs_to_crs_from_pj(context, source_crs, wgs84, nullptr, nullptr);
  proj_destroy(wgs84);
  if (horizontal) proj_destroy(horizontal);
  proj_destroy(given);
  if (!proj_->operation)
    throw InputError(source_ + ": PROJ cannot transform '" + crs + "' to WGS 84: " + proj_->last_error());
}

CrsToWgs84::~CrsToWgs84() = default;

std::optional<GeoPoint> CrsToWgs84::try_transform(const Vec3& p, bool swapped) const {
  const double first = swapped ? p.y : p.x, second = swapped ? p.x : p.y;
  // EPSG:4979 in its own axis order: latitude, longitude (degrees), height.
  const PJ_COORD c = proj_trans(proj_->operation, PJ_FWD, proj_coord(first, second, p.z, 0));
  if (!finite(c)) return std::nullopt;
  return GeoPoint{c.v[0], c.v[1], c.v[2]};
}

bool CrsToWgs84::inside_area_of_use(const GeoPoint& g) const {
  if (!area_of_use_) return true;
  const auto [west, south, east, north] = *area_of_use_;
  // A margin of a degree: models reach past a zone's edge, and areas are rounded.
  constexpr double kMarginDeg = 1.0;
  const bool lon_inside = west <= east ? g.longitude_deg >= west - kMarginDeg && g.longitude_deg <= east + kMarginDeg
                                       : g.longitude_deg >= west - kMarginDeg || g.longitude_deg <= east + kMarginDeg;
  return lon_inside && g.latitude_deg >= south - kMarginDeg && g.latitude_deg <= north + kMarginDeg;
}

bool CrsToWgs84::fit_axis_order(const Vec3& sample) {
  swapped_ = false;
  if (geographic_) return false;  // latitude first as the CRS says (GML, PLATEAU's EPSG:6697)
  const std::optional<GeoPoint> as_defined = try_transform(sample, false);
  if (as_defined && inside_area_of_use(*as_defined)) return false;
  const std::optional<GeoPoint> swapped = try_transform(sample, true);
  swapped_ = swapped && inside_area_of_use(*swapped);
  return swapped_;
}

std::vector<GeoPoint> CrsToWgs84::transform(const std::vector<Vec3>& points) const {
  std::vector<GeoPoint> out(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const std::optional<GeoPoint> g = try_transform(points[i], swapped_);
    if (!g)
      throw InputError(source_ + ": PROJ cannot transform the point " + describe(points[i]) + " of " + crs_ +
                       " to WGS 84 (outside the CRS's area?)");
    out[i] = *g;
  }
  return out;
}

GeoPoint CrsToWgs84::transform(const Vec3& point) const { return transform(std::vector<Vec3>{point})[0]; }

struct LocalFrame::Proj : ProjHandle {};

LocalFrame::LocalFrame(const GeoPoint& origin) : proj_(std::make_unique<Proj>()), origin_(origin) {
  char definition[200];
  std::snprintf(definition, sizeof definition, "+proj=aeqd +lat_0=%.12f +lon_0=%.12f +x_0=0 +y_0=0 +ellps=WGS84",
                origin.latitude_deg, origin.longitude_deg);
  proj_->operation = proj_create(proj_->context, definition);
  if (!proj_->operation) throw std::runtime_error("LocalFrame: PROJ refused " + std::string(definition));
}

LocalFrame::~LocalFrame() = default;

Vec3 LocalFrame::to_local(const GeoPoint& p) const {
  const PJ_COORD c =
      proj_trans(proj_->operation, PJ_FWD,
                 proj_coord(p.longitude_deg / kDegreesPerRadian, p.latitude_deg / kDegreesPerRadian, 0, 0));
  return {c.v[0], c.v[1], p.height_m - origin_.height_m};
}

std::vector<Vec3> LocalFrame::to_local(const std::vector<GeoPoint>& points) const {
  std::vector<Vec3> out;
  out.reserve(points.size());
  for (const GeoPoint& p : points) out.push_back(to_local(p));
  return out;
}

GeoPoint LocalFrame::to_geographic(const Vec3& local) const {
  const PJ_COORD c = proj_trans(proj_->operation, PJ_INV, proj_coord(local.x, local.y, 0, 0));
  return {c.v[1] * kDegreesPerRadian, c.v[0] * kDegreesPerRadian, local.z + origin_.height_m};
}

}  // namespace skylit
