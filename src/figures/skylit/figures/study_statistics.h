// A sun study's statistics over time (docs/animations.md): each frame's luminance
// statistics (assess/render_statistics.h) gathered into one CSV, and a plot of the mean
// luminance of every object and of the sky against time.
#pragma once

#include <string>
#include <vector>

#include "skylit/assess/render_statistics.h"
#include "skylit/figures/animation_frames.h"
#include "skylit/figures/plot.h"

namespace skylit {

// statistics_csv's rows for every frame, each led by the frame's number, date, time,
// UTC offset and sun altitude. std::invalid_argument unless there is one entry per frame.
std::string study_statistics_csv(const std::vector<AnimationFrame>& frames,
                                 const std::vector<RenderStatistics>& statistics);

// Mean luminance (cd/m²) of each object and of the sky against the time since the first
// frame: in hours, or in days when the study spans more than three days.
Plot study_statistics_plot(const std::string& title, const std::vector<AnimationFrame>& frames,
                           const std::vector<RenderStatistics>& statistics);

}  // namespace skylit
