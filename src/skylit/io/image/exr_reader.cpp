// OpenEXR input through the OpenEXR 3 C++ API (Imf::InputFile), the counterpart of
// exr_writer.cpp: R, G, B as linear sRGB primaries, absolute, and Y in cd/m². Any pixel
// type is read as FLOAT (OpenEXR converts HALF and UINT). A file that declares other
// primaries is refused rather than silently read with the wrong matrix.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>

#include <array>
#include <cmath>
#include <exception>
#include <string>
#include <vector>

#include "skylit/core/error.h"
#include "skylit/io/image/image_decoders.h"

namespace skylit {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& why) {
  throw InputError("cannot read \"" + path.string() + "\": " + why);
}

// Chromaticities are stored as floats; 1e-3 is far below any real difference of primaries.
bool is_srgb(const Imf::Chromaticities& c) {
  const RgbPrimaries& s = kSrgbPrimaries;
  const std::array<std::pair<float, double>, 8> pairs = {{{c.red.x, s.red_x},
                                                          {c.red.y, s.red_y},
                                                          {c.green.x, s.green_x},
                                                          {c.green.y, s.green_y},
                                                          {c.blue.x, s.blue_x},
                                                          {c.blue.y, s.blue_y},
                                                          {c.white.x, s.white_x},
                                                          {c.white.y, s.white_y}}};
  for (const auto& [stored, expected] : pairs)
    if (std::abs(stored - expected) > 1e-3) return false;
  return true;
}

struct ExrChannels {
  int width = 0, height = 0;
  bool has_rgb = false, has_y = false;
  std::array<std::vector<float>, 4> values;  // R, G, B, Y
};

ExrChannels read_channels(const std::filesystem::path& path) {
  Imf::InputFile file(path.c_str());
  const Imf::Header& header = file.header();
  if (Imf::hasChromaticities(header) && !is_srgb(Imf::chromaticities(header)))
    fail(path, "its chromaticities are not sRGB / Rec. 709 with D65 white; convert it first");
  const Imath::Box2i window = header.dataWindow();
  ExrChannels out;
  out.width = window.max.x - window.min.x + 1;
  out.height = window.max.y - window.min.y + 1;
  const std::size_t n = static_cast<std::size_t>(out.width) * out.height;
  const Imf::ChannelList& channels = header.channels();
  out.has_rgb = channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B");
  out.has_y = channels.findChannel("Y") != nullptr;
  if (!out.has_rgb && !out.has_y) fail(path, "it has neither R, G, B nor Y channels");
  Imf::FrameBuffer frame;
  const char* names[4] = {"R", "G", "B", "Y"};
  for (int c = 0; c < 4; ++c) {
    if (c < 3 ? !out.has_rgb : !out.has_y) continue;
    out.values[c].assign(n, 0.0f);
    frame.insert(names[c], Imf::Slice::Make(Imf::FLOAT, out.values[c].data(), window));
  }
  file.setFrameBuffer(frame);
  file.readPixels(window.min.y, window.max.y);
  return out;
}

}  // namespace

XyzImage decode_exr(const std::filesystem::path& path) {
  ExrChannels channels;
  try {
    channels = read_channels(path);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    // OpenEXR's messages (Iex) say what is wrong with the file, e.g. a bad magic number.
    fail(path, std::string("not a readable OpenEXR file (") + e.what() + ")");
  }
  XyzImage image(channels.width, channels.height);
  const Xyz d65_white = xyz_from_linear_srgb({1.0, 1.0, 1.0});  // Y = 1
  for (std::size_t i = 0; i < static_cast<std::size_t>(channels.width) * channels.height; ++i) {
    Xyz p;
    if (channels.has_rgb) {
      p = xyz_from_linear_srgb({channels.values[0][i], channels.values[1][i], channels.values[2][i]});
      if (channels.has_y) p.y = channels.values[3][i];
    } else {
      const double y = channels.values[3][i];
      p = {d65_white.x * y, y, d65_white.z * y};
    }
    image.set(static_cast<int>(i % channels.width), static_cast<int>(i / channels.width), p);
  }
  return image;
}

}  // namespace skylit
