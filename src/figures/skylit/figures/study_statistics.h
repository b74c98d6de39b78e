// A study's statistics over time (docs/animations.md, docs/sweeps.md): each frame's
// luminance statistics (assess/render_statistics.h) gathered into one CSV, and a plot of
// the mean luminance of every object and of the sky against time. Used by `animate
// --stats` (one frame per instant) and `sweep --stats` (one per combination, grouped by
// the values other than the time).
#pragma once

#include <string>
#include <vector>

#include "skylit/assess/render_statistics.h"
#include "skylit/figures/animation_frames.h"
#include "skylit/figures/plot.h"

namespace skylit {

// statistics_csv's rows for every frame, each led by the frame's number, date, time,
// UTC offset and sun altitude, and by its group when `groups` is given (one per frame,
// e.g. "materials.walls = tile" for a sweep that varies more than the time).
// std::invalid_argument unless there is one entry per frame.
std::string study_statistics_csv(const std::vector<AnimationFrame>& frames,
                                 const std::vector<RenderStatistics>& statistics,
                                 const std::vector<std::string>& groups = {});

// Mean luminance (cd/m²) of each object and of the sky against the time since the
// earliest frame: in hours, or in days when the study spans more than three days. With
// `groups`, each group has its own line per object ("box (materials.walls = tile)").
// Each line runs in time order.
Plot study_statistics_plot(const std::string& title, const std::vector<AnimationFrame>& frames,
                           const std::vector<RenderStatistics>& statistics,
                           const std::vector<std::string>& groups = {});

}  // namespace skylit
