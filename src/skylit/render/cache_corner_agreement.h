// When the corners of a sky-light cache cell (render/surface_cache.h) may stand in for a
// point inside it (issue 14, item 3). Corners on the same plane can still see different
// skies: near the horizon one cell spans tens of metres of the ground, from a street
// beside a tower (much of its sky hidden) to open grass, and interpolating across it put
// the sky light on Fig. 7's ground up to 28 % off at 320 × 180 (99th percentile of the
// pixels). A cell is used only where its corners' sky light agrees and, if fewer than
// four corners lie on the point's surface, where at least two do (on the coarse and
// fine grids; the per-pixel level has nothing finer) and lie near the point, and where
// its corners lie within their obstacles' reach of the point (below), and where the
// cell's blend matched the value computed at its middle (kCellCheck); elsewhere the
// next finer level of the cache is computed there, down to the pixel's own centre.
//
// A lone corner stood in within its obstacles' reach until 2026-12-06. That reach is
// the corner's own: a point of its cell nearer a small obstacle (the glass beside a
// window's frame, a wall under the eaves) sees less sky than the corner shows, and on
// examples/house.json at 320 × 180 a third of the pixels served by a lone coarse corner
// were more than 2 % off. Refused on both grids (against the exact sky light at every
// pixel, 99th percentile, 320 × 180 / 480 × 270): the house 9.95 / 11.8 → 7.2 / 9.4 %,
// the default example 2.69 / 3.19 → 2.40 / 3.06 %, Fig. 7 2.20 / 2.03 → 2.04 / 1.93 %,
// for 1.5 % more per-pixel points on Fig. 7 at 1280 × 720 (+0.6 % of its cache) and 17 %
// more on the million-triangle city (+1.4 s, BENCHMARKS.md).
#pragma once

#include <span>

#include "skylit/render/surface_point.h"

namespace skylit {

// The largest relative spread of the corners' diffuse sky light (illuminance, lx) for
// which a cell is interpolated. A smooth change of sky light across a cell interpolates
// well whatever its size; a spread beyond this marks an obstacle's edge of visibility
// between the corners. Chosen by measurement against the exact sky light on Fig. 7
// (tests/render/sky_light_cache_examples_test.cpp, docs/sky-light.md) as the tightest
// that keeps the Fig. 7 frame within its time budget: 0.1 takes the 99th percentile of
// the deviation from 5.4 % to 5.1 % at 480 × 270 but the frame from 1.9 to 2.3 times
// the time of the cache without it. 0.2 sufficed while obstacles were lit by the open
// sky; lit by their own sky (the default since 2026-12-04) shaded ground and walls are
// darker beside the lit ones, the sky light steeper, and 0.2 let Fig. 7's 99th
// percentile at 320 × 180 rise from 5.2 % to 5.9 %; 0.15 brings it to 4.3 % for about
// 3 % of the frame's time.
inline constexpr double kCornerSpread = 0.15;

// How far a cached point may lie from the point it stands in for, as a fraction of the
// point's distance from the camera, when the cell's other corners see other surfaces
// (or a sliver takes its nearest neighbour's value): such corners cannot show how the
// sky light changes in between. Sky light changes over the distance to the obstacles
// that hide it, and what the camera sees at distance d shows obstacles about that far
// apart; a cell seen at a grazing angle is many times longer in depth than across.
inline constexpr double kCornerReach = 0.05;

bool within_reach(const SurfacePoint& cached, const SurfacePoint& point);

// Each cell is checked where it would be used: the value computed at its middle (a point
// of the next finer level, which the finer level keeps) against the cell's blend there;
// beyond kCellCheck of it (plus the pixel's other light, as corners_agree) the cell
// serves no point and the finer level is computed. Corners that agree say nothing of
// what lies between them: on examples/building.json at 480 × 270, of the pixels more
// than 2 % off the exact sky light, two fifths lay in cells whose four corners were on
// the point's surface and agreed within kCornerSpread (a recess or a sill's shadow
// between them, a dip in a street beside a wall). The tolerance sits above the
// 1,024-direction integral's own scatter from point to point (0.5–1 % beside a detailed
// facade, where its directions meet other parts of the windows and frames as the point
// moves by millimetres), which a tighter one would take for a failed cell: at 1 % the
// Fig. 7 frame's cache needed about 11 % more integrals for 0.1–0.2 point. Measured
// against the exact sky light (99th percentile at 320 × 180 / 480 × 270,
// tests/render/sky_light_cache_examples_test.cpp): Fig. 7 2.03 / 1.91 → 1.57 / 1.66 %,
// building 2.54 / 3.20 → 1.93 / 1.75 %, the house 7.6 / 9.8 → 5.4 / 6.4 %; the frame
// 1.07–1.16 times as long (docs/sky-light.md, "Every cell checked at its middle").
inline constexpr double kCellCheck = 0.015;

// Cells not checked. Fine cells (kUncheckedCellPixels across) whose corners agree within
// kUncheckedSpread: checking them all (with a 1 % check) took the Fig. 7 frame's
// per-pixel points 1.37 times as far for 0.1 point of its 99th percentile.
inline constexpr double kUncheckedSpread = 0.02;
inline constexpr int kUncheckedCellPixels = 4;
// And a cell whose corners all lie within kSmoothReach of their harmonic mean distance
// to their obstacles (CachedSkyLight::obstacle_distance_m) from its middle: the sky light
// changes over that distance (Ward et al. 1988), by about this fraction across the
// cell, nearly linearly, and the blend follows a linear change. It takes out 43 % of the
// checks on Fig. 7 at 1280 × 720 and 56 % on the default example (the cells far from
// buildings) for no change of the 99th percentiles within 0.02 point; at 5 % the
// default example's rose to 1.97 % at 320 × 180.
inline constexpr double kSmoothReach = 0.03;

// Near obstacles the sky light changes over the distance to them, and where a cell spans
// much depth (the ground seen at a grazing angle, tens of metres of it beside a tower in
// one cell) interpolating across the screen departs from interpolating across the
// ground. There a corner stands for a point only within this fraction of its harmonic
// mean distance to the obstacles its integral met (CachedSkyLight::obstacle_distance_m;
// Ward et al. 1988's validity radius), unless the corners agree within kCloseSpread; a
// cell spans much depth when a corner's distance from the camera differs from the
// point's by more than kDepthSpan of it. Chosen by measurement against a converged sky
// light (16,384 directions, tests/render/sky_light_cache_examples_test.cpp) and the
// frame benchmarks (BENCHMARKS.md): on Fig. 7 at 320 × 180 the cache's 99th percentile
// deviation went from 12.3 % to 5.0 %, near the 1,024-direction integral's own 3.5 %.
// Without the depth condition it was 4.8 % but the million-triangle frame took 1.3 times
// as long (its aerial view's small cells beside houses); with it that frame is unchanged
// and Fig. 7's about 1.05 times. kCloseSpread was 3 % until 2026-12-06: deep corners
// that agree within a few percent can still hide a dip between them (Fig. 7 at
// 480 × 270: a row of grass between the tower and the street 5 % below two corners 50 m
// apart in depth that agreed within 2.1 %); at 1 % Fig. 7's 99th percentile (every
// pixel) at 480 × 270 went from 2.86 % to 2.03 % for about 4 % of its frame, the default
// example, Fig. 8a and the million-triangle city unchanged.
inline constexpr double kObstacleReach = 0.1;
inline constexpr double kCloseSpread = 0.01;
inline constexpr double kDepthSpan = 0.1;

// Whether `point` lies within `reach` of the cached point's harmonic mean obstacle distance from it.
bool within_obstacle_reach(const SurfacePoint& cached, double obstacle_distance_m, const SurfacePoint& point,
                           double reach = kObstacleReach);

// Whether corners of these sky-light illuminances agree within `spread` of the largest
// plus `other_lx`: the least, among the corners, of their pixels' other light
// (CachedSkyLight::other_lx). What an error in the sky light changes in the image is
// judged against all the pixel shows: at night the glow of street lamps in the fog in
// front outshines the sky a hundred- to a thousandfold, and the sky light's fast changes
// there (a kerb, a ditch, a pole's foot) need no finer level.
bool corners_agree(std::span<const double> corner_illuminance_lx, double spread = kCornerSpread, double other_lx = 0);

}  // namespace skylit
