// Frames into an MP4 video (H.264, yuv420p: what browsers and players expect) by
// running ffmpeg, when it is installed (Debian: apt-get install ffmpeg).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace skylit::cli {

// The ffmpeg program on PATH, if any.
std::optional<std::filesystem::path> find_ffmpeg();

// Encodes the PNGs matching `frame_pattern` (printf style, e.g. ".../frame_%04d.png",
// numbered from 1) into `video` through a temporary file renamed into place. An odd
// width or height is padded by one black pixel (yuv420p halves the colour planes).
// Returns an empty string when done, otherwise what went wrong (ffmpeg's exit status).
std::string encode_video(const std::filesystem::path& ffmpeg, const std::filesystem::path& frame_pattern,
                         double frames_per_second, const std::filesystem::path& video);

}  // namespace skylit::cli
