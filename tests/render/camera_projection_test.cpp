// The camera's projections (render/camera.h) against their formulas written out here
// independently: where a direction lands in the image (to 0.5 px, the issue's
// tolerance; the code agrees to ~1e-9 px), that the ray through that pixel meets a small
// box placed in that direction, the solid angles adding up to the sphere's share the
// image covers, lens shift keeping verticals vertical, and Radiance's VIEW= options.
#include "skylit/render/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "skylit/geometry/primitives.h"
#include "skylit/io/image/radiance_view.h"

namespace skylit {
namespace {

// A camera at the origin looking north (+y), up +z: right is east (+x).
Camera camera_looking_north(Projection projection, double vertical_fov_deg, double horizontal_fov_deg = 360) {
  Camera c;
  c.position = {0, 0, 0};
  c.look_at = {0, 1, 0};
  c.projection = projection;
  c.vertical_fov_deg = vertical_fov_deg;
  c.horizontal_fov_deg = horizontal_fov_deg;
  return c;
}

// The direction θ from the view axis (north), turned ψ from the right (east) toward up.
Vec3 off_axis(double theta, double psi) {
  return {std::sin(theta) * std::cos(psi), std::cos(theta), std::sin(theta) * std::sin(psi)};
}

// The direction at azimuth φ right of north and elevation e.
Vec3 azimuth_elevation(double phi, double e) {
  return {std::cos(e) * std::sin(phi), std::cos(e) * std::cos(phi), std::sin(e)};
}

// Checks that `direction` projects to (x, y), that the ray through (x, y) has that
// direction, and that it meets a 0.1 m box 20 m away that way (a ray 2 px lower misses).
void expect_lands(const ImageCamera& camera, const Vec3& direction, double x, double y, const std::string& what) {
  const auto at = camera.project(20 * direction);
  ASSERT_TRUE(at) << what;
  EXPECT_NEAR(at->first, x, 0.5) << what;
  EXPECT_NEAR(at->second, y, 0.5) << what;
  const Ray ray = camera.ray_through(x, y);
  EXPECT_NEAR(dot(ray.direction, direction), 1.0, 1e-9) << what;
  RayTracer tracer;
  const Vec3 c = 20 * direction;
  tracer.add_mesh(make_box(c - Vec3{0.05, 0.05, 0.05}, c + Vec3{0.05, 0.05, 0.05}));
  tracer.commit();
  EXPECT_TRUE(tracer.intersect(ray).has_value()) << what;
  EXPECT_FALSE(tracer.intersect(camera.ray_through(x, y + 2)).has_value()) << what;
}

TEST(CameraProjection, FisheyesPlaceDirectionsByTheirRadiusFormulas) {
  // A 180° fisheye in a 301 × 301 image: the image circle's radius is 150.5 px.
  const int n = 301;
  const double radius_px = n / 2.0;
  struct Case {
    Projection projection;
    const char* name;
    double (*radius)(double theta);  // image radius / circle radius, for a 180° lens
  };
  const Case cases[] = {
      {Projection::fisheye_equidistant, "equidistant", [](double t) { return t / (kPi / 2); }},
      {Projection::fisheye_equisolid, "equisolid", [](double t) { return std::sin(t / 2) / std::sin(kPi / 4); }},
      {Projection::fisheye_hemispherical, "hemispherical", [](double t) { return std::sin(t); }},
  };
  for (const Case& c : cases) {
    const ImageCamera camera(camera_looking_north(c.projection, 180), n, n);
    for (double theta_deg : {0.0, 10.0, 35.0, 60.0, 85.0})
      for (double psi_deg : {0.0, 30.0, 135.0, 250.0}) {
        const double theta = radians(theta_deg), psi = radians(psi_deg);
        const double r = c.radius(theta) * radius_px;
        expect_lands(camera, off_axis(theta, psi), n / 2.0 + r * std::cos(psi), n / 2.0 - r * std::sin(psi),
                     std::string(c.name) + " θ=" + std::to_string(theta_deg) + " ψ=" + std::to_string(psi_deg));
      }
    EXPECT_FALSE(camera.sees(1, 1)) << c.name;  // the corner lies outside a 180° circle
    EXPECT_TRUE(camera.sees(n / 2.0, 1)) << c.name;
  }
}

TEST(CameraProjection, PanoramasPlaceAzimuthAndElevationByTheirFormulas) {
  const int w = 720, h = 200;
  // Cylindrical: 360° across, vertical perspective with 60° across the height.
  const ImageCamera cylinder(camera_looking_north(Projection::cylindrical, 60, 360), w, h);
  // Equirectangular: 360° × 180°.
  const ImageCamera sphere(camera_looking_north(Projection::equirectangular, 180, 360), w, 360);
  for (double phi_deg : {-150.0, -40.0, 0.0, 20.0, 170.0})
    for (double e_deg : {-25.0, 0.0, 12.0}) {
      const double phi = radians(phi_deg), e = radians(e_deg);
      const std::string what = "φ=" + std::to_string(phi_deg) + " e=" + std::to_string(e_deg);
      expect_lands(cylinder, azimuth_elevation(phi, e), w / 2.0 + phi / kPi * w / 2.0,
                   h / 2.0 - std::tan(e) / std::tan(radians(30)) * h / 2.0, "cylindrical " + what);
      expect_lands(sphere, azimuth_elevation(phi, e), w / 2.0 + phi / kPi * w / 2.0, 180.0 - e / (kPi / 2) * 180.0,
                   "equirectangular " + what);
    }
  expect_lands(sphere, azimuth_elevation(0.7, radians(80)), w / 2.0 + 0.7 / kPi * w / 2.0, 180.0 - 80.0 / 90 * 180,
               "equirectangular near the zenith");
}

// Σ pixel_solid_angle over the pixels the camera sees.
double total_solid_angle(const ImageCamera& camera, int w, int h) {
  double sum = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (camera.sees(x + 0.5, y + 0.5)) sum += camera.pixel_solid_angle(x + 0.5, y + 0.5);
  return sum;
}

TEST(CameraProjection, PixelSolidAnglesAddUpToTheSphereCovered) {
  // Midpoint sums; the fisheyes' jagged circle edge adds ~1/radius: 0.5 % at 400 px.
  EXPECT_NEAR(
      total_solid_angle(ImageCamera(camera_looking_north(Projection::equirectangular, 180), 400, 200), 400, 200),
      4 * kPi, 1e-3 * 4 * kPi);
  EXPECT_NEAR(total_solid_angle(ImageCamera(camera_looking_north(Projection::cylindrical, 90), 400, 200), 400, 200),
              2 * kPi * std::sqrt(2.0), 1e-3 * 2 * kPi);  // 2π · 2 sin 45°: the band |e| ≤ 45°
  for (Projection p : {Projection::fisheye_equidistant, Projection::fisheye_equisolid})
    EXPECT_NEAR(total_solid_angle(ImageCamera(camera_looking_north(p, 180), 400, 400), 400, 400), 2 * kPi,
                5e-3 * 2 * kPi);
  // Perspective: a 90° × 90° frustum covers 2π/3 (a cube's face).
  EXPECT_NEAR(total_solid_angle(ImageCamera(camera_looking_north(Projection::perspective, 90), 400, 400), 400, 400),
              2 * kPi / 3, 1e-3 * 2 * kPi / 3);
}

TEST(CameraProjection, LensShiftKeepsVerticalsVerticalAndMovesTheImage) {
  // Looking level at a tall building 30 m north, shifted up by 0.3 of the height: its
  // vertical edge stays one column, and the horizon moves from the middle to 0.8 H.
  Camera c = camera_looking_north(Projection::perspective, 60);
  c.shift_y = 0.3;
  const int w = 400, h = 600;
  const ImageCamera camera(c, w, h);
  const auto foot = camera.project({-8, 30, -1.6}), top = camera.project({-8, 30, 60});
  ASSERT_TRUE(foot && top);
  EXPECT_NEAR(foot->first, top->first, 1e-9);
  EXPECT_NEAR(camera.project({0, 1e4, 0})->second, 0.8 * h, 1e-6);
  const Ray ray = camera.ray_through(foot->first, foot->second);
  EXPECT_NEAR(dot(ray.direction, normalize(Vec3{-8, 30, -1.6})), 1.0, 1e-12);
}

TEST(CameraProjection, RadianceViewOptions) {
  EXPECT_EQ(*radiance_view_options(camera_looking_north(Projection::fisheye_equidistant, 180), 300, 300),
            "-vta -vp 0 0 0 -vd 0 1 0 -vu 0 0 1 -vh 180 -vv 180");
  EXPECT_EQ(*radiance_view_options(camera_looking_north(Projection::fisheye_hemispherical, 180), 300, 300),
            "-vth -vp 0 0 0 -vd 0 1 0 -vu 0 0 1 -vh 180 -vv 180");
  EXPECT_EQ(*radiance_view_options(camera_looking_north(Projection::cylindrical, 60, 270), 600, 200),
            "-vtc -vp 0 0 0 -vd 0 1 0 -vu 0 0 1 -vh 270 -vv 60");
  Camera shifted = camera_looking_north(Projection::perspective, 90);
  shifted.shift_x = 0.1;
  shifted.shift_y = 0.25;
  // -vh: 2 atan(tan 45° · 2) = 126.87°.
  EXPECT_EQ(*radiance_view_options(shifted, 200, 100),
            "-vtv -vp 0 0 0 -vd 0 1 0 -vu 0 0 1 -vh 126.869898 -vv 90 -vs 0.1 -vl 0.25");
  EXPECT_FALSE(radiance_view_options(camera_looking_north(Projection::equirectangular, 180), 400, 200));
  EXPECT_FALSE(radiance_view_options(camera_looking_north(Projection::fisheye_equisolid, 180), 300, 300));
}

}  // namespace
}  // namespace skylit
