// OpenEXR output through the OpenEXR 3 C++ API (Imf::OutputFile into a memory stream).
// Channels R, G, B: linear sRGB / Rec. 709 primaries, absolute, so that
// 0.2126 R + 0.7152 G + 0.0722 B is luminance in cd/m²; Y: luminance in cd/m² itself.
// 32-bit FLOAT, not HALF: half tops out at 65504 and the sun's disc is ~1.6e9 cd/m².
// The standard attributes "chromaticities" (Rec. 709, D65) and "whiteLuminance" = 1
// ("luminance in cd/m² of RGB (1, 1, 1)", ImfStandardAttributes.h) tell other tools the
// values are absolute. Optional data layers (object, distance, normal) follow as more
// FLOAT channels, with the object table as the string attribute "skylit:objects".
// ZIP compression is lossless and its output deterministic.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <string>

#include "skylit/io/image/image_encoders.h"

namespace skylit {

Bytes encode_exr(const XyzImage& image, const DisplayOptions& options) {
  const int w = image.width, h = image.height;
  // Interleaved R, G, B, Y per pixel, rows top to bottom as EXR's INCREASING_Y expects.
  std::vector<float> pixels(4 * static_cast<std::size_t>(w) * h);
  for (std::size_t i = 0; i < pixels.size() / 4; ++i) {
    const Xyz p = finite_pixel_or_black(image, i);
    const Rgb rgb = linear_srgb_from_xyz(p);
    for (int c = 0; c < 3; ++c) pixels[4 * i + c] = to_finite_float(rgb[c]);
    pixels[4 * i + 3] = static_cast<float>(p.y);
  }

  Imf::Header header(w, h);
  header.compression() = Imf::ZIP_COMPRESSION;
  const char* names[4] = {"R", "G", "B", "Y"};
  for (const char* name : names) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
  const RgbPrimaries& s = kSrgbPrimaries;
  Imf::addChromaticities(header,
                         Imf::Chromaticities({float(s.red_x), float(s.red_y)}, {float(s.green_x), float(s.green_y)},
                                             {float(s.blue_x), float(s.blue_y)}, {float(s.white_x), float(s.white_y)}));
  Imf::addWhiteLuminance(header, 1.0f);
  if (options.exr_layers) {
    for (const auto& layer : options.exr_layers->channels)
      header.channels().insert(layer.first, Imf::Channel(Imf::FLOAT));
    std::string table;
    for (std::size_t i = 0; i < options.exr_layers->object_names.size(); ++i)
      table += std::to_string(i) + " " + options.exr_layers->object_names[i] + "\n";
    header.insert("skylit:objects", Imf::StringAttribute(table));
  }

  Imf::FrameBuffer frame;
  const std::size_t x_stride = 4 * sizeof(float), y_stride = x_stride * w;
  for (int c = 0; c < 4; ++c)
    frame.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(pixels.data() + c), x_stride, y_stride));
  if (options.exr_layers)
    for (const auto& layer : options.exr_layers->channels)
      // Slice wants a non-const pointer; OutputFile only reads through it.
      frame.insert(layer.first,
                   Imf::Slice(Imf::FLOAT, const_cast<char*>(reinterpret_cast<const char*>(layer.second.data())),
                              sizeof(float), sizeof(float) * w));

  Imf::StdOSStream stream;
  {
    // The file's offset table is written when OutputFile is destroyed, hence the scope.
    Imf::OutputFile file(stream, header);
    file.setFrameBuffer(frame);
    file.writePixels(h);
  }
  const std::string bytes = stream.str();
  return Bytes(bytes.begin(), bytes.end());
}

}  // namespace skylit
