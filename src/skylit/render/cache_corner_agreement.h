// When the corners of a sky-light cache cell (render/surface_cache.h) may stand in for a
// point inside it (issue 14, item 3). Corners on the same plane can still see different
// skies: near the horizon one cell spans tens of metres of the ground, from a street
// beside a tower (much of its sky hidden) to open grass, and interpolating across it put
// the sky light on Fig. 7's ground up to 28 % off at 320 × 180 (99th percentile of the
// pixels). A cell is used only where its corners' sky light agrees and, if fewer than
// four corners lie on the point's surface, where they lie near the point; elsewhere the
// next finer level of the cache is computed there, down to the pixel's own centre.
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
// the time of the cache without it.
inline constexpr double kCornerSpread = 0.2;

// How far a cached point may lie from the point it stands in for, as a fraction of the
// point's distance from the camera, when the cell's other corners see other surfaces
// (or a sliver takes its nearest neighbour's value): such corners cannot show how the
// sky light changes in between. Sky light changes over the distance to the obstacles
// that hide it, and what the camera sees at distance d shows obstacles about that far
// apart; a cell seen at a grazing angle is many times longer in depth than across.
inline constexpr double kCornerReach = 0.05;

bool within_reach(const SurfacePoint& cached, const SurfacePoint& point);

// Whether corners of these illuminances agree within kCornerSpread of the largest.
bool corners_agree(std::span<const double> corner_illuminance_lx);

}  // namespace skylit
