#include "skylit/render/frame_breakdown.h"

#include <cstdio>

namespace skylit {

std::string describe(const FrameBreakdown& frame) {
  char line[512];
  std::snprintf(line, sizeof line,
                "frame: first hits %.2f s, caches %.2f s (sky light: %d + %d grid points and %d one-pixel "
                "points, %d of them checking cells, and %d pixels between them), centres %.2f s, edges %.2f s",
                frame.primary_hits_s, frame.caches_s, frame.coarse_points, frame.fine_points, frame.pixel_points,
                frame.cell_checks, frame.pixels_between, frame.centres_pass_s, frame.edges_pass_s);
  std::string out = line;
  if (!frame.obstacle_patches.empty()) {
    out += "; obstacle patches";
    for (size_t level = 0; level < frame.obstacle_patches.size(); ++level)
      out += (level ? " + " : " ") + std::to_string(frame.obstacle_patches[level]);
  }
  return out;
}

}  // namespace skylit
