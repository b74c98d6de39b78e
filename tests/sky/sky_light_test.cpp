// Sky light with obstruction: the band sources' geometry, the sky view factor in a
// street canyon against its closed form, unobstructed irradiance against a dense
// quadrature of the same sky, and the light obstacles send back.
#include "skylit/sky/sky_light.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <vector>

#include "skylit/geometry/primitives.h"
#include "skylit/spectrum/cie.h"

namespace skylit {
namespace {

TEST(BandSources, ElementsTileTheSphereWithEqualBandsForAHorizontalSurface) {
  const BandSources bands(8, 16);
  double total = 0;
  std::vector<double> horizontal(16, 0.0);
  for (const SkyElement& e : bands.elements()) {
    total += e.solid_angle;
    EXPECT_NEAR(length(e.direction), 1.0, 1e-12);
    EXPECT_EQ(e.direction.z > 0, e.band < 8);
    if (e.direction.z > 0) horizontal[static_cast<size_t>(e.band)] += e.direction.z * e.solid_angle;
  }
  EXPECT_NEAR(total, 4 * kPi, 1e-9);
  // cos(δ−Δ) − cos(δ+Δ) = 2/N for every sky band: each carries π/N of a horizontal
  // surface's cosine-weighted hemisphere (within the midpoint rule's 3 % for 16
  // segments along the band and the band's width in δ).
  for (int l = 0; l < 8; ++l) {
    EXPECT_NEAR(std::cos(bands.tilt(l) - bands.half_width(l)) - std::cos(bands.tilt(l) + bands.half_width(l)), 2.0 / 8,
                1e-12);
    EXPECT_NEAR(horizontal[static_cast<size_t>(l)], kPi / 8, 0.03 * kPi / 8) << l;
  }
  int band, segment;
  bands.locate(bands.element(5, 11).direction, band, segment);
  EXPECT_EQ(band, 5);
  EXPECT_EQ(segment, 11);
}

struct Fixture {
  Atmosphere atmosphere{AtmosphereSettings{}};
  SkyModel sky{atmosphere, direction_from_altitude_azimuth(40, 150), 1.6};
  RayTracer tracer;
};

// Radiance of obstacles for these tests: black, so only the sky counts.
Radiance black_obstacle(const Ray&, const Hit&, double) { return Radiance(0.0f); }

// A street canyon of width w between two walls of height h, `length_m` long, along y
// (or along x when turned).
void add_canyon(RayTracer& tracer, double w, double h, double length_m, bool along_x) {
  const double half = w / 2, l = length_m / 2;
  if (along_x) {
    tracer.add_mesh(make_box({-l, half, 0}, {l, half + 10, h}));
    tracer.add_mesh(make_box({-l, -half - 10, 0}, {l, -half, h}));
  } else {
    tracer.add_mesh(make_box({half, -l, 0}, {half + 10, l, h}));
    tracer.add_mesh(make_box({-half - 10, -l, 0}, {-half, l, h}));
  }
  tracer.commit();
}

TEST(SkyLight, CanyonFloorSeesTheSkyFractionOfTheClosedForm) {
  // An infinitely long canyon (here 4 km for 10–40 m walls): a horizontal point on the
  // floor's centre line sees the sky with view factor sin φ, tan φ = (w/2)/h (the
  // crossed-strings rule for a 2-D opening).
  for (bool along_x : {false, true}) {
    for (double h_over_w : {0.5, 1.0, 2.0}) {
      Fixture f;
      const double w = 20, h = h_over_w * w;
      add_canyon(f.tracer, w, h, 4000, along_x);
      const SkyLight light(f.sky, f.tracer, black_obstacle);
      const double measured = light.sky_view_factor({0, 0, 0}, {0, 0, 1});
      const double expected = std::sin(std::atan(w / 2 / h));
      // The default 1024 directions (512 over the hemisphere) resolve the canyon's
      // edges to ~0.01 of the view factor (docs/sky-light.md has the measured errors).
      EXPECT_NEAR(measured, expected, 0.012) << "h/w " << h_over_w << (along_x ? " along x" : " along y");
    }
  }
}

TEST(SkyLight, OpenFieldGetsTheUnobstructedIrradiance) {
  Fixture f;
  f.tracer.commit();
  const SkyLight light(f.sky, f.tracer, black_obstacle);
  for (const Vec3 n : {Vec3{0, 0, 1}, Vec3{1, 0, 0}, normalize(Vec3{0, -1, 1})}) {
    const Irradiance e = light.diffuse_irradiance({0, 0, 0}, n);
    const Irradiance table = f.sky.sky_irradiance(n);
    for (int k = 0; k < kSpectralBins; ++k) EXPECT_FLOAT_EQ(e[k], table[k]);
  }
}

TEST(SkyLight, UnobstructedIrradianceMatchesADenseQuadratureOfTheSky) {
  // ∫ L(ω) max(0, n·ω) dω with 720 × 1440 midpoint samples of the same sky radiance
  // (near the ground) against the table over orientations, for a grid of normals:
  // within 1 % in illuminance (measured: 0.2 %); and the open sky the cells' means give
  // (sky_light.h; measured: 0.4 %).
  Fixture f;
  f.tracer.commit();
  const SkyLight cells(f.sky, f.tracer, black_obstacle, fibonacci_sphere(SkyLight::kDefaultDirections), nullptr,
                       nullptr, SkyLight::Cells::kMeans);
  for (double elevation : {90.0, 45.0, 0.0, -45.0}) {
    for (double azimuth : {150.0, 240.0, 330.0}) {
      const Vec3 n = direction_from_altitude_azimuth(elevation, azimuth);
      Spectrum dense;
      constexpr int kTheta = 720, kPhi = 1440;
      for (int i = 0; i < kTheta; ++i) {
        const double theta = kPi * (i + 0.5) / kTheta;
        for (int j = 0; j < kPhi; ++j) {
          const double phi = 2 * kPi * (j + 0.5) / kPhi;
          const Vec3 w{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
          const double c = dot(n, w);
          if (c <= 0) continue;
          dense += f.sky.sky_radiance_near_ground(w).spectrum() *
                   static_cast<float>(c * std::sin(theta) * (kPi / kTheta) * (2 * kPi / kPhi));
        }
      }
      const double expected = illuminance(Irradiance(dense));
      EXPECT_NEAR(illuminance(f.sky.sky_irradiance(n)), expected, 0.01 * expected) << elevation << " " << azimuth;
      const double from_cells = illuminance(cells.diffuse_irradiance({0, 0, 0}, n));
      EXPECT_NEAR(from_cells, expected, 0.01 * expected) << elevation << " " << azimuth;
    }
  }
}

// The illuminance (lx) on a surface at `point` facing `n` from 262,144 directions summed
// directly, without any table: each sees the sky or, where the tracer meets something,
// radiance `hidden`.
double dense_illuminance(const SkyModel& sky, const RayTracer& tracer, const Vec3& point, const Vec3& n,
                         const Radiance& hidden) {
  static const std::vector<SkyElement> dense = fibonacci_sphere(262144);
  Spectrum sum;
  for (const SkyElement& e : dense) {
    const double c = dot(n, e.direction);
    if (c <= 0) continue;
    const bool hit = tracer.occluded(Ray{offset_from_surface(point, n), e.direction});
    sum +=
        (hit ? hidden : sky.sky_radiance_near_ground(e.direction)).spectrum() * static_cast<float>(c * e.solid_angle);
  }
  return illuminance(Irradiance(sum));
}

// A 4 km ground plane (and any `others`) sending back a grey 20 % of the sky's mean,
// the sun at 30°, 115°; the image's sky light with the cells' means, and its relative
// error against 262,144 directions summed directly (dense_illuminance).
struct OverGreyGround {
  Atmosphere atmosphere{AtmosphereSettings{}};
  SkyModel sky{atmosphere, direction_from_altitude_azimuth(30, 115), 1.6};
  RayTracer tracer;
  Radiance grey{sky.sky_irradiance({0, 0, 1}).spectrum() * static_cast<float>(0.2 / kPi)};
  std::unique_ptr<SkyLight> cells;

  explicit OverGreyGround(const std::vector<TriangleMesh>& others = {}) {
    tracer.add_mesh(make_ground_plane({0, 0, 0}, 4000));
    for (const TriangleMesh& mesh : others) tracer.add_mesh(mesh);
    tracer.commit();
    cells = std::make_unique<SkyLight>(
        sky, tracer, [this](const Ray&, const Hit&, double) { return ObstacleLight(grey); },
        fibonacci_sphere(SkyLight::kDefaultDirections), nullptr, nullptr, SkyLight::Cells::kMeans);
  }
  double error(const Vec3& point, const Vec3& n) const {
    return illuminance(cells->diffuse_irradiance(point, n)) / dense_illuminance(sky, tracer, point, n, grey) - 1;
  }
};

TEST(SkyLight, AnOutlineAcrossTheAureoleTakesOutTheSkyItHides) {
  // A south wall facing a low sun (17°) across a 50 m street from a long black block
  // whose top passes 3° above the sun: the block hides the aureole up to its edge, and
  // as the point rises by 0.5 m steps the edge sweeps across the elements. Against
  // 262,144 directions summed directly (no table), worst of twelve heights: with the
  // cells' means and their sub-cells traced apart within 2 % (measured 1.25 %; 1.54 %
  // before the outlines across sub-cells were bisected, sky_light.h); the
  // sky model's table and the elements' centres 2.3 %, and the cells' means without
  // the sub-cells 6.4 % (the open sky and the hidden sky from different radiances).
  Atmosphere atmosphere{AtmosphereSettings{}};
  const SkyModel sky{atmosphere, direction_from_altitude_azimuth(17, 180), 1.6};
  RayTracer tracer;
  tracer.add_mesh(make_box({-400, -80, 0}, {400, -50, 50 * std::tan(radians(20.0))}));
  tracer.commit();
  const SkyLight cells(sky, tracer, black_obstacle, fibonacci_sphere(SkyLight::kDefaultDirections), nullptr, nullptr,
                       SkyLight::Cells::kMeans);
  const SkyLight plain(sky, tracer, black_obstacle);
  const Vec3 south{0, -1, 0};
  double worst_cells = 0, worst_plain = 0;
  for (int step = 0; step < 12; ++step) {
    const Vec3 point{0.37 * step, 0, 1.0 + 0.5 * step};
    const double truth = dense_illuminance(sky, tracer, point, south, Radiance(0.0f));
    worst_cells = std::max(worst_cells, std::abs(illuminance(cells.diffuse_irradiance(point, south)) / truth - 1));
    worst_plain = std::max(worst_plain, std::abs(illuminance(plain.diffuse_irradiance(point, south)) / truth - 1));
  }
  std::cout << "worst against 262,144 directions: cells " << worst_cells << ", table and centres " << worst_plain
            << "\n";
  EXPECT_LT(worst_cells, 0.02);
  EXPECT_LT(worst_cells, worst_plain);
}

TEST(SkyLight, AWallAboveTheGroundKeepsTheSkyAboveTheHorizon) {
  // Walls facing the four ways, 2–20 m above a ground plane 4 km wide that sends a
  // grass-like 20 % of the sky's mean back: the elements across the horizon hold sky
  // above it and far ground below. Against 262,144 directions summed directly, each
  // seeing the sky or the ground plane, worst of eight: within 0.8 % (measured 0.20 %;
  // 0.50 % before the outlines across sub-cells were bisected, 20 m up, where the
  // plane's edge 0.57° below the horizon falls within a sub-cell).
  // Taking an element's whole mean out where its centre met the ground read 1.6 % dark
  // (the default example's shaded east block 0.9 % darker than the path tracer); the
  // sub-cells traced apart without the horizon as a bound between their rows, 0.9 %.
  const OverGreyGround scene;
  double worst = 0;
  for (const Vec3 n : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{-1, 0, 0}, Vec3{0, -1, 0}})
    for (const double height : {2.0, 20.0}) worst = std::max(worst, std::abs(scene.error(height * Vec3{0, 0, 1}, n)));
  std::cout << "worst against 262,144 directions: " << worst << "\n";
  EXPECT_LT(worst, 0.008);
}

TEST(SkyLight, ARoofEdgeThroughTheHorizonSweepsAcrossSmoothly) {
  // A north-facing wall looking across a 40 m street at a long block 30 m tall (30 m
  // deep), over a ground plane; block and ground send back a grey 20 % of the sky's
  // mean. As the point rises from 28.6 to 31 m the roof's outline against the sky sweeps
  // from 2° above the horizon through it (its near edge, then its far edge 70 m away),
  // through the elements the horizon crosses, parallel to the rows of sub-cells laid
  // along it. Against 262,144 directions summed directly, at 25 heights 0.1 m apart: the
  // worst error, and the largest change of the error from one height to the next (a
  // step that no interpolation between heights follows). Measured: worst 0.21 %, step
  // 0.13 %; with each sub-cell counted whole (before the outlines were bisected,
  // sky_light.h) 1.35 % and 0.55 %, a row of sub-cells hidden or shown at once. Bounds:
  // about three times what is measured, below what counting whole gives. (With the edge
  // 3–6° up, across elements the horizon does not cross, whose centres stand for them,
  // the error reaches 2.3 %: docs/sky-light.md.)
  const OverGreyGround scene({make_box({-400, 40, 0}, {400, 70, 30})});
  double worst = 0, worst_step = 0, previous = 0;
  for (int step = 0; step <= 24; ++step) {
    const double error = scene.error({0, 0, 28.6 + 0.1 * step}, {0, 1, 0});
    worst = std::max(worst, std::abs(error));
    if (step > 0) worst_step = std::max(worst_step, std::abs(error - previous));
    previous = error;
  }
  std::cout << "worst against 262,144 directions: " << worst << ", largest step " << worst_step << "\n";
  EXPECT_LT(worst, 0.006);
  EXPECT_LT(worst_step, 0.004);
}

TEST(SkyLight, ACanyonWallsSlitOfSkyIsTracedAtItsOutlines) {
  // The shaded wall of a street canyon 12 m wide (h/w 2 and 4, 4 km long, black walls,
  // no ground) sees the sky through a slit between the roofs, a few elements wide; its
  // outline crosses elements whose sky hardly varies. Against 262,144 directions summed
  // directly, at 10, 30 and 50 % of the height: the elements' centres standing for them
  // misjudge it by 0.4–1.5 % (measured); with the outlines that matter traced apart
  // (sky_light.h, kOutlineTolerance) within 0.8 % (measured), asserted 1.5 %. In the
  // render the foot of such a wall read 6 % too bright in its own sky, the larger part
  // of the little light it has there (docs/sky-light.md).
  Atmosphere atmosphere{AtmosphereSettings{}};
  const SkyModel sky{atmosphere, direction_from_altitude_azimuth(30, 180), 1.6};
  double worst_cells = 0, worst_centres = 0;
  for (const double h_over_w : {2.0, 4.0}) {
    RayTracer tracer;
    add_canyon(tracer, 12, 12 * h_over_w, 4000, true);
    const SkyLight cells(sky, tracer, black_obstacle, fibonacci_sphere(SkyLight::kDefaultDirections), nullptr, nullptr,
                         SkyLight::Cells::kMeans);
    const SkyLight centres(sky, tracer, black_obstacle);
    const Vec3 north{0, 1, 0};
    for (const double share : {0.1, 0.3, 0.5}) {
      const Vec3 point{0, -6, share * 12 * h_over_w};
      const double truth = dense_illuminance(sky, tracer, point, north, Radiance(0.0f));
      const double from_cells = illuminance(cells.diffuse_irradiance(point, north)) / truth - 1;
      const double from_centres = illuminance(centres.diffuse_irradiance(point, north)) / truth - 1;
      std::cout << "h/w " << h_over_w << ", " << share << " up: cells " << from_cells << ", centres " << from_centres
                << "\n";
      worst_cells = std::max(worst_cells, std::abs(from_cells));
      worst_centres = std::max(worst_centres, std::abs(from_centres));
    }
  }
  EXPECT_LT(worst_cells, 0.015);
  EXPECT_LT(worst_cells, worst_centres);
}

TEST(SkyLight, DirectionsTurnedPerPointAverageOutAFixedSetsMisjudgement) {
  // The same slit at 256 directions (an obstacle level's, render/bands_integrator.h),
  // with the top quarter of the far wall lit (five times the sky's mean, as the sunlit
  // band of a canyon at a 30° sun), at 512 points along the wall at one height. With the
  // directions as given every point misjudges it alike (the canyon is the same all
  // along). Turned, each point by one of the kTurns rotations in turn, each errs by its
  // own amount (standard deviation σ), and their mean comes within three standard
  // errors σ/√kTurns of the truth (what the integrals that meet many patches see). A
  // point keeps its value from one call to the next.
  Atmosphere atmosphere{AtmosphereSettings{}};
  const SkyModel sky{atmosphere, direction_from_altitude_azimuth(30, 180), 1.6};
  RayTracer tracer;
  add_canyon(tracer, 12, 48, 4000, true);
  const Radiance band(sky.sky_irradiance({0, 0, 1}).spectrum() * static_cast<float>(5 / kPi));
  const auto lit_band = [&](const Ray& ray, const Hit& hit, double) {
    return ray.origin.z + hit.t * ray.direction.z > 36 ? band : Radiance(0.0f);
  };
  const SkyLight fixed(sky, tracer, lit_band, fibonacci_sphere(256));
  const SkyLight turned(sky, tracer, lit_band, fibonacci_sphere(256), nullptr, nullptr, SkyLight::Cells::kCentres,
                        SkyLight::Turning::kPerPoint);
  const Vec3 north{0, 1, 0};
  for (const double height : {4.8, 14.4, 24.0}) {
    // 262,144 directions summed directly, the band's light where they meet it.
    static const std::vector<SkyElement> dense = fibonacci_sphere(262144);
    const Vec3 at{0, -6, height};
    Spectrum sum;
    for (const SkyElement& e : dense) {
      const double c = dot(north, e.direction);
      if (c <= 0) continue;
      const Ray ray{offset_from_surface(at, north), e.direction};
      const std::optional<Hit> hit = tracer.intersect(ray);
      sum += (hit ? lit_band(ray, *hit, 0) : sky.sky_radiance_near_ground(e.direction)).spectrum() *
             static_cast<float>(c * e.solid_angle);
    }
    const double truth = illuminance(Irradiance(sum));
    constexpr int kPoints = 512;
    double fixed_mean = 0, turned_mean = 0, turned_square = 0;
    for (int k = 0; k < kPoints; ++k) {
      const Vec3 point{-400 + 1.37 * k, -6, height};
      fixed_mean += (illuminance(fixed.diffuse_irradiance(point, north)) / truth - 1) / kPoints;
      const auto turn = static_cast<uint64_t>(k);
      const double once = illuminance(turned.diffuse_irradiance(point, north, nullptr, turn));
      turned_mean += (once / truth - 1) / kPoints;
      turned_square += (once / truth - 1) * (once / truth - 1) / kPoints;
      EXPECT_EQ(once, illuminance(turned.diffuse_irradiance(point, north, nullptr, turn)));
    }
    const double sigma = std::sqrt(turned_square - turned_mean * turned_mean);
    std::cout << height << " m up: fixed " << fixed_mean << ", turned " << turned_mean << " (σ " << sigma << ")\n";
    EXPECT_LT(std::abs(turned_mean), 3 * sigma / std::sqrt(SkyLight::kTurns)) << height;
    EXPECT_LT(std::abs(turned_mean), std::abs(fixed_mean)) << height;
  }
}

TEST(SkyLight, ObstaclesSendBackTheirLight) {
  // A vertical surface facing a tall white wall 5 m away: the wall hides most of its
  // sky, and a wall of radiance L fills its view: irradiance ≈ π·L·(fraction hidden).
  Fixture f;
  f.tracer.add_mesh(make_box({-500, 5, 0}, {500, 15, 1000}));
  f.tracer.commit();
  const Radiance wall_radiance(0.01f);
  const SkyLight light(f.sky, f.tracer, [&](const Ray&, const Hit&, double) { return wall_radiance; });
  const SkyLight dark(f.sky, f.tracer, black_obstacle);
  const Vec3 point{0, 0, 500}, north{0, 1, 0};
  const double lit = illuminance(light.diffuse_irradiance(point, north));
  const double unlit = illuminance(dark.diffuse_irradiance(point, north));
  // The wall fills nearly the whole hemisphere (it subtends all but ~0.5° at 500 m up).
  const double expected = illuminance(Irradiance(wall_radiance.spectrum() * static_cast<float>(kPi)));  // π L
  EXPECT_NEAR(lit - unlit, expected, 0.03 * expected);
  EXPECT_LT(unlit, 0.03 * illuminance(f.sky.sky_irradiance(north)));
}

TEST(SkyLight, ObstaclesLitAsThePointCloseTheBouncesByTheGeometricSeries) {
  // On a canyon's floor the hidden part of the cosine-weighted hemisphere is 1 − F (F the
  // sky view factor). Obstacles of albedo ρ with no light of their own, lit as the point
  // is: E = E_seen + ρ·(1 − F)·E, so E = E_seen / (1 − ρ(1 − F)) exactly, per bin.
  Fixture f;
  add_canyon(f.tracer, 20, 30, 4000, false);
  const SkyLight seen_only(f.sky, f.tracer, black_obstacle);
  for (const float rho : {0.3f, 0.8f}) {
    const SkyLight closed(f.sky, f.tracer, [rho](const Ray&, const Hit&, double) {
      return ObstacleLight(Radiance(0.0f), Reflectance(rho));
    });
    const Vec3 point{0, 0, 0}, up{0, 0, 1};
    const double hidden = 1 - seen_only.sky_view_factor(point, up);
    EXPECT_GT(hidden, 0.5);  // the closure matters here
    const Irradiance e_seen = seen_only.diffuse_irradiance(point, up);
    const Irradiance e = closed.diffuse_irradiance(point, up);
    for (int k = 0; k < kSpectralBins; ++k)
      EXPECT_NEAR(e.spectrum()[k], e_seen.spectrum()[k] / (1 - rho * hidden), 1e-4 * e.spectrum()[k])
          << rho << " " << k;
  }
}

}  // namespace
}  // namespace skylit
