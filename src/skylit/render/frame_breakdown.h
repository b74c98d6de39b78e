// A bands frame by its parts: their times, and what the sky-light cache computed.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace skylit {

// Where a bands frame's time went, and what the sky-light cache computed: what a
// benchmark reports and `skylit render --verbose` says, so that a frame's cost is seen
// by its parts (the fast path's speed bounds, issues 14 and 21, are frame times).
struct FrameBreakdown {
  double primary_hits_s = 0;  // every pixel centre's first hit
  double caches_s = 0;        // the sky-light cache and the lamps' glow image
  double centres_pass_s = 0;  // the first pass: each pixel's centre
  double edges_pass_s = 0;    // the second pass: the full sample grid where edges run
  // (No second pass with one sample a pixel; in a render split over processes the
  // passes' times leave out their exchanges.)
  // The sky-light cache's integrals (surface_cache.h): its 16- and 4-pixel grids' points
  // and the one-pixel level's (a quarter of the directions), together every integral it
  // computed; `cell_checks` of them at the 4-pixel and one-pixel levels checked a coarser
  // cell at its middle (with all the directions). And the pixels that level found
  // between their neighbours, without an integral.
  int coarse_points = 0, fine_points = 0, pixel_points = 0, cell_checks = 0, pixels_between = 0;
  // The obstacles' own sky-light patches per level (obstacle_sky_light.h) that the
  // renderer holds at the frame's end, this frame's and earlier frames': the places looked
  // up, each a patch or none where its plane has no triangle there.
  std::vector<size_t> obstacle_patches;
};

// One line for a person: the parts' seconds and the cache's counts.
std::string describe(const FrameBreakdown& frame);

}  // namespace skylit
