// The CRS step and the local frame (io/city/geo_frame.h) against PROJ's cs2cs and the
// CRS names as files write them.
#include "skylit/io/city/geo_frame.h"

#include <gtest/gtest.h>

#include "../../test_support.h"

namespace skylit {
namespace {

TEST(GeoFrame, CrsNamesAsFilesWriteThem) {
  EXPECT_EQ(normalized_crs_name("https://www.opengis.net/def/crs/EPSG/0/7415"), "EPSG:7415");
  EXPECT_EQ(normalized_crs_name("http://www.opengis.net/def/crs/EPSG/0/2056"), "EPSG:2056");
  EXPECT_EQ(normalized_crs_name("urn:ogc:def:crs:EPSG::6697"), "EPSG:6697");
  EXPECT_EQ(normalized_crs_name("urn:ogc:def:crs:EPSG:8.6:28992"), "EPSG:28992");
  EXPECT_EQ(normalized_crs_name("epsg:6677"), "EPSG:6677");
  EXPECT_EQ(normalized_crs_name("+proj=utm +zone=31"), "+proj=utm +zone=31");
}

// Each in its CRS's own axis order; the expected values from
//   echo X Y Z | cs2cs -f %.10f EPSG:CODE EPSG:4979
// (latitude, longitude, height). 1e-9° is 0.1 mm.
TEST(GeoFrame, AxisOrdersOfProjectedAndGeographicCrssAgreeWithCs2cs) {
  struct Case {
    const char* crs;
    Vec3 point;
    double latitude, longitude, height;
  };
  for (const Case& c : {Case{"EPSG:6677", {-35000, -10000, 10}, 35.6844776329, 139.7228512850, 10},  // northing first
                        Case{"EPSG:2056", {2600000, 1200000, 500}, 46.9510828757, 7.4386324953, 500},
                        Case{"EPSG:6697", {35.5, 139.7, 10}, 35.5, 139.7, 10}}) {  // latitude first
    const GeoPoint p = CrsToWgs84(c.crs, "t").transform(c.point);
    EXPECT_NEAR(p.latitude_deg, c.latitude, 1e-9) << c.crs;
    EXPECT_NEAR(p.longitude_deg, c.longitude, 1e-9) << c.crs;
    EXPECT_NEAR(p.height_m, c.height, 1e-6) << c.crs;
  }
}

TEST(GeoFrame, LocalFrameRoundTripsAndPointsNorthAlongY) {
  const LocalFrame frame(GeoPoint{52.0, 4.4, 3.0});
  const Vec3 north = frame.to_local(GeoPoint{52.001, 4.4, 5.0});
  EXPECT_NEAR(north.x, 0.0, 1e-6);
  EXPECT_NEAR(north.y, 111.25, 0.05);  // a meridian's 0.001° at 52°: 111.25 m (WGS 84)
  EXPECT_NEAR(north.z, 2.0, 1e-12);
  const GeoPoint back = frame.to_geographic(Vec3{1234.5, -987.6, 7});
  const Vec3 again = frame.to_local(back);
  EXPECT_NEAR(again.x, 1234.5, 1e-6);
  EXPECT_NEAR(again.y, -987.6, 1e-6);
  EXPECT_NEAR(again.z, 7.0, 1e-12);
}

}  // namespace
}  // namespace skylit
