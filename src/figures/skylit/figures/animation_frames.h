// The frames of a sun study (`skylit animate`, docs/animations.md): each frame's label
// (number, date, clock time, the sun's altitude) burnt into its display image, the same
// labels as a CSV beside the frames, and a self-contained HTML page that shows the
// frames with a time slider.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "skylit/figures/raster.h"
#include "skylit/io/image/image.h"
#include "skylit/sun/time.h"

namespace skylit {

struct AnimationFrame {
  int number = 1;  // from 1, in time order
  OffsetDateTime time;
  double sun_altitude_deg = 0, sun_azimuth_deg = 0;
};

// "3/24  2026-06-21 07:00+02:00  sun 23.4°" (the total is `frame_count`).
std::string frame_label(const AnimationFrame& frame, std::size_t frame_count);

// The frame's display image (display_srgb8 with `display`'s exposure) with `label` in
// white on a dark band along its bottom edge; the size stays the image's.
Raster labelled_frame(const XyzImage& image, const DisplayOptions& display, const std::string& label);

// One row per frame: frame,file,date,time,utc_offset,sun_altitude_deg,sun_azimuth_deg,
// exposure_ev (the study's one exposure, to 17 digits, so that a frame can be remade
// exactly with `skylit render --set render.exposure_ev=...`).
std::string frames_csv(const std::vector<AnimationFrame>& frames, const std::vector<std::string>& files,
                       double exposure_ev);

// A standalone HTML page (no external files): the PNG frames embedded as data URIs, a
// slider over them, play/pause, and each frame's label. `labels` and `pngs` have one
// entry per frame; std::invalid_argument otherwise.
std::string frame_viewer_html(const std::string& title, const std::vector<std::string>& labels,
                              const std::vector<std::vector<uint8_t>>& pngs, double frames_per_second);

// Base64 (RFC 4648, with padding), for the data URIs.
std::string base64(const std::vector<uint8_t>& bytes);

}  // namespace skylit
