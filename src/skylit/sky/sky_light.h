// Sky light on the scene's surfaces with the sky hidden by other objects (§4 of the
// paper): the diffuse irradiance that the sky dome's band sources give a point, where
// elements hidden by obstacles (other buildings, the ground) are replaced by the light
// those obstacles send back (what lights them is the caller's: render/obstacle_sky_light.h).
//
// The unobstructed irradiance comes from the sky model's table over orientations (the
// paper's look-up table for diffuse reflection); what obstacles change is found by
// tracing one ray per band-source element toward the sky (rather than intersecting each
// band's sample plane with the obstacles as the paper does: Embree makes the rays cheap
// and handles any mesh), and subtracting the hidden sky's share while adding the
// obstacle's.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "skylit/atmosphere/atmosphere.h"
#include "skylit/geometry/ray_tracer.h"
#include "skylit/material/material.h"
#include "skylit/media/fog_shadowed_sunlight.h"
#include "skylit/media/fog_surface_light.h"
#include "skylit/sky/band_sources.h"
#include "skylit/spectrum/spectrum_grid.h"

namespace skylit {

// What the obstacle hit by a ray sends back along it: its radiance (W m⁻² sr⁻¹ nm⁻¹),
// and, where that radiance leaves out the obstacle's sky light, the Lambertian albedo
// toward the ray's origin with which it returns the point's own instead
// (SkyLight::diffuse_irradiance). Made from a radiance alone, so that a callback giving
// only that is one.
struct ObstacleLight {
  ObstacleLight(const Radiance& radiance_sent, const Reflectance& albedo = Reflectance(0.0f))
      : radiance(radiance_sent), lit_as_the_point(albedo) {}
  Radiance radiance;
  Reflectance lit_as_the_point;
};
// The callback is told the width (radians) of the element the ray stands for, so that
// light that changes sharply within it (a shadow edge across a sunlit wall) can be
// averaged over it rather than taken at its centre.
using ObstacleRadiance = std::function<ObstacleLight(const Ray& ray, const Hit& hit, double element_width_rad)>;

class SkyLight {
 public:
  // Directions for finding what obstacles hide: a spherical Fibonacci set, chosen over
  // the paper's band elements by measurement (docs/sky-light.md): point samples on the
  // bands' regular lattice line up with straight building edges and misjudge a street
  // canyon's sky by up to 0.03 of the view factor at 1024 rays; this set, by 0.01.
  static constexpr int kDefaultDirections = 1024;

  // The paper's ε of Eq. (8), relative to the largest G met: the walk stops where an
  // element's share falls below it.
  static constexpr double kSpecularThreshold = 2e-3;
  // Width of the specular band sources and their segments, as a fraction of the
  // roughness m (radians), within [1°, 5°]: chosen by measured error against a dense
  // quadrature (tests/sky/specular_sky_test.cpp, docs/sky-light.md).
  static constexpr double kSpecularElementPerRoughness = 0.5;

  // How finely an integral resolves the sky within its elements.
  enum class Cells {
    // Each element's centre radiance for what an obstacle hides; the open sky from the
    // sky model's table.
    kCentres,
    // Each element's sky is its cell's mean radiance (3 × 3 sub-cells of 4 × 4 samples),
    // the open sky's irradiance is summed from the same means (a table over normals)
    // rather than the sky model's table, and where an obstacle's outline crosses an
    // element whose sub-cells differ by more than kVaryingCell × the sky's mean (the
    // sun's aureole, the horizon), or that the horizon crosses (its rows laid so that
    // the horizon is a bound between them), its sub-cells are traced apart, each hidden
    // one taking out its own mean up to the outline found between it and an open
    // neighbour in its column (`refined`, kOutlineBisections). The open sky and what
    // obstacles hide then come from the same radiances: from the table's 2,048 point
    // samples and the elements' centres, a block whose top passed near a low sun took
    // out whole 6° elements of the aureole, ±3–5 % of a wall's sky light from one metre
    // to the next (docs/sky-light.md). Elsewhere an outline's elements are traced apart
    // (their sub-cells, not bisected) as far as they could matter (kOutlineTolerance).
    kMeans,
    // The same means, with sub-cells traced apart only where an outline crosses an
    // element whose sub-cells differ (the aureole), and the outline not bisected: for
    // values that stand for one pixel, where the rest cost an eighth of a model of many
    // small parts' frame and moved the examples' pixels by a tenth of a per cent at most
    // (docs/sky-light.md, "The one-pixel level's cells").
    kMeansAcrossTheAureole,
  };
  // Whether each diffuse integral turns its directions by one of kTurns rotations of the
  // sphere, the one its caller draws (with Cells::kCentres only). A fixed
  // set of directions misjudges a narrow slit of sky or a thin sunlit band by the same
  // amount at every point that sees it alike: every point along a street canyon's wall
  // at one height. The obstacles' patches (render/obstacle_sky_light.h) are many such
  // points, averaged by the integrals that meet them: turned, their errors cancel there
  // instead of adding up (at the foot of a canyon of height/width 4, the light its
  // opposite wall had of its own sky was 8 % short, docs/sky-light.md). Not for the
  // points an image shows: neighbouring pixels would differ by those errors.
  enum class Turning { kNone, kPerPoint };
  static constexpr int kTurns = 64;
  //
  // `fog`, when given (a fog layer with multiple scattering), lights the points it
  // covers instead of the sky: the diffuse irradiance there is the fog field's, each
  // hidden direction seen through the fog (media/fog_surface_light.h); it is referred
  // to, not copied. `shadowed_fog_sunlight`, when given with it, takes out of a shaded
  // point's diffuse irradiance the sunlight the fog in the shadows around it does not
  // scatter (media/fog_shadowed_sunlight.h): for the integrals of the points seen, not
  // for the obstacles' own, so that an obstacle's light does not depend on which
  // integral asked for it first.
  SkyLight(const SkyModel& sky, const RayTracer& tracer, ObstacleRadiance obstacle_radiance,
           std::vector<SkyElement> directions = fibonacci_sphere(kDefaultDirections),
           const FogSurfaceLight* fog = nullptr, const FogShadowedSunlight* shadowed_fog_sunlight = nullptr,
           Cells cells = Cells::kCentres, Turning turning = Turning::kNone);
  static constexpr double kVaryingCell = 1.0;

  // Irradiance (W m⁻² nm⁻¹) on a surface at `point` with unit `normal` (facing the side
  // being lit), from the sky, the far ground, and the obstacles that hide them; inside a
  // fog given to the constructor, from the fog's light and the obstacles seen through it.
  //
  // An obstacle whose ObstacleLight has an albedo ρ (its `lit_as_the_point`) is taken
  // to receive the same sky irradiance E as the point itself, which closes the bounces
  // between obstacles:
  //   E = (E_seen + Σ_hidden w·L_obstacle) / (1 − Σ_hidden w·ρ/π),
  // w = cos·dω, per wavelength bin: exact where everything around sees the same sky
  // (a white furnace), and in a street the opposite wall at the same height does, about.
  //
  // `obstacle_distance_m`, when given, receives the harmonic mean distance to what the
  // directions meet (cos-weighted; open sky counts as infinitely far; +∞ when nothing is
  // hidden): the scale over which the irradiance changes (Ward et al. 1988).
  //
  // With Turning::kPerPoint, `turn` (modulo kTurns) picks the rotation the directions
  // take; 0 is the set as given. The caller draws it from what the point stands for (an
  // obstacle's patch), not from the point's position, which moves by a millimetre with
  // how a wall is cut into triangles.
  Irradiance diffuse_irradiance(const Vec3& point, const Vec3& normal, double* obstacle_distance_m = nullptr,
                                uint64_t turn = 0) const;
  // Whether diffuse_irradiance at altitude z already holds what the fog above takes and
  // adds (so the caller must not dim it by the fog's share of the sky light).
  bool lights_in_fog(double z_m) const { return fog_ && fog_->covers(z_m); }

  // Radiance (W m⁻² sr⁻¹ nm⁻¹) that a glossy surface reflects toward `to_viewer` from the
  // sky and the obstacles that hide it, by the paper's adaptive search (§4.2): from the
  // element nearest the mirror direction along each band, outward until the element's
  // share G = L·R_s·dω (Eq. 8) falls below ε; band after band outward until the
  // band's element nearest the mirror direction falls below ε. Hidden elements
  // reflect the obstacle's light instead. Without the sun (the caller adds its highlight).
  //
  // The bands are laid around an axis of the surface's own: perpendicular to its normal
  // and to the mirror direction, so that the mirror direction lies in the middle of the
  // first band and the surface's horizon is a band boundary. The paper's bands about
  // the world's x axis put east- and west-facing walls seen head-on at the bands' pole,
  // where the search breaks down, and cut the lobe short at grazing views (errors of
  // 5 % and 84 % against the dense quadrature).
  Radiance specular_radiance(const Vec3& point, const Vec3& normal, const Vec3& to_viewer,
                             const Material& material) const;

  // The sky view factor at a point: the share of a cosine-weighted hemisphere that sees
  // the sky (z > 0) unobstructed. 1 for a horizontal surface in the open.
  double sky_view_factor(const Vec3& point, const Vec3& normal) const;

 private:
  const SkyModel& sky_;
  const RayTracer& tracer_;
  ObstacleRadiance obstacle_radiance_;

  std::vector<SkyElement> elements_;
  std::vector<Radiance> element_radiance_;
  // With the cells' means: per element its sub-cells (directions, the middle one last: the
  // element's own direction unless the horizon crosses it; mean radiances; the rows' bounds), whether they differ
  // enough to be traced apart, and then its nearest neighbours (to find the outlines that cross it).
  static constexpr int kNeighbours = 6, kSubCells = 9;
  struct CellGrid {
    std::array<Vec3, kSubCells> directions;
    std::array<Radiance, kSubCells> radiance;
    bool varying = false;
    bool straddles_horizon = false;  // the horizon crosses it: a bound between its rows
    // Rays traced apart for its sub-cells: all nine, or eight where the middle one's is
    // the element's own (where the horizon does not cross it).
    int traced_sub_cells() const { return straddles_horizon ? kSubCells : kSubCells - 1; }
    std::array<uint32_t, kNeighbours> neighbours{};
    // The sub-cells' grid: three columns (u = −1, 0, 1) of three rows, whose bounds
    // `rows` are along `across_v` (vertical) in units of a sub-cell's width; the
    // direction at (u, v) is normalize(element + u·across_u + v·across_v). A sub-cell's
    // share of the element's solid angle is its height / 9 (1/9 unless the horizon
    // crosses the element).
    std::array<double, 4> rows{};
    double centre(size_t row) const { return 0.5 * (rows[row] + rows[row + 1]); }
    Vec3 across_u, across_v;
    Vec3 toward(const Vec3& element, double u, double v) const {
      return normalize(element + u * across_u + v * across_v);
    }
  };
  // The slot of the sub-cell in column u + 1, row r (find_cells' order: the middle last).
  static constexpr std::array<std::array<int, 3>, 3> kSlot{{{0, 1, 2}, {3, 8, 4}, {5, 6, 7}}};
  // Where two rows of a column disagree (one hidden, one not), an outline crosses the
  // column between their centres: it is found by this many bisections (to an eighth of
  // the distance), and the hidden part of each sub-cell counted to there. Counted whole,
  // a roof's edge seen near the horizon (parallel to the rows laid along it) hid or
  // showed a whole row of sub-cells at once: steps of 2–2.5 % in a wall's sky light
  // every two metres of height on Fig. 7's tower (docs/sky-light.md).
  static constexpr int kOutlineBisections = 3;
  // With Cells::kMeans, outlines across elements whose sky does not vary are traced
  // apart, the most consequential first, until the rest could misjudge the irradiance by
  // at most this share of it (RMS, each element off by kShareErrorRms of its weight
  // times the step in radiance across its outline). Counted whole, the sunlit top of a
  // street canyon's far wall (a band of 10°, between a roof's outline and a shadow
  // edge) was seen 3 % too dark from the shaded wall's foot, its sky slit 6 % too bright
  // (docs/sky-light.md).
  static constexpr double kOutlineTolerance = 0.002;
  static constexpr double kShareErrorRms = 0.29;
  // An outline crossing column `column` (0–2) of an element between the centres of rows
  // `lower_row` and the one above: it lies between v = low and high.
  struct OutlineCrossing {
    uint32_t element;
    size_t column, lower_row;
    bool lower_hidden;  // the lower row's ray met an obstacle (the upper's did not)
    double low, high;
  };
  Cells cell_detail_;
  Turning turning_;
  // With Turning::kPerPoint: the directions turned by each rotation, and the sky's
  // radiance toward each (turn 0: elements_ and element_radiance_).
  std::vector<std::vector<SkyElement>> turned_elements_;
  std::vector<std::vector<Radiance>> turned_radiance_;
  void turn_elements();
  std::vector<CellGrid> cells_;
  std::vector<double> element_cd_;  // with the cells: each element's mean luminance
  void find_cells();
  // Whether an element an outline crosses has its sub-cells traced apart for a surface
  // of `normal`: where they differ by more than kVaryingCell × the sky's mean, and where
  // the horizon crosses the element (a bound between its rows) with all its sub-cells
  // above the surface's own horizon. The step from the horizon's sky to the far ground
  // can be smaller than the sky's mean, but where the centre ray of such an element met
  // the ground its whole mean was taken out, the sky above the horizon with it: shaded
  // walls read 0.9 % darker than the path tracer (docs/sky-light.md). On a surface whose
  // own horizon is the horizon (the ground) the sub-cells below it would meet the
  // surface itself: there the centre stands for the element as before. The horizon's
  // elements are refined with Cells::kMeans only.
  bool refined(const CellGrid& c, const Vec3& normal) const;
  // Whether all of an element's sub-cells lie above the surface's own horizon.
  static bool above_surface(const CellGrid& c, const Vec3& normal);
  // With the cells' means: the open sky's irradiance Σ max(0, n·ω_i) dω_i L̄_i over normals n, on
  // a grid of elevation × azimuth (world frame), read bilinearly.
  static constexpr int kOpenElevations = 17, kOpenAzimuths = 33;
  SpectrumGrid2D open_irradiance_{kOpenAzimuths, kOpenElevations};  // x: azimuth, y: elevation
  Spectrum open_irradiance(const Vec3& normal) const;
  const FogSurfaceLight* fog_;
  const FogShadowedSunlight* shadowed_fog_sunlight_;
  std::unique_ptr<FogSurfaceLight::Directions> fog_elements_;  // with `fog_`: its light from each element
  // The elements in an order that keeps neighbouring directions together (bands of
  // height, by azimuth within each), so that the rays of one point go to the tracer in
  // coherent packets.
  std::vector<uint32_t> packet_order_;  // the sky (or far ground) at each element
};

}  // namespace skylit
