#include "skylit/io/model/jpeg_texels.h"

#include <csetjmp>
#include <cstdio>  // jpeglib.h needs FILE

#include <jpeglib.h>

#include "skylit/core/error.h"

namespace skylit {
namespace {

// libjpeg's state. It reports a fatal error by calling error_exit, which must not
// return: it jumps back to decode_with_libjpeg's setjmp with the message. (The error
// manager first: libjpeg hands error_exit a pointer to it.)
struct JpegState {
  jpeg_error_mgr errors;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
  jpeg_decompress_struct info;
};

[[noreturn]] void jump_back(j_common_ptr info) {
  auto* state = reinterpret_cast<JpegState*>(info->err);
  (*info->err->format_message)(info, state->message);
  std::longjmp(state->jump, 1);
}

void keep_quiet(j_common_ptr, int) {}  // warnings of recovered damage are not printed

// CMYK texels (print files: photographs of materials from print catalogues are often
// CMYK JPEGs) to RGB in place, as browsers and Pillow convert them without the file's
// colour profile: each channel the share of light its ink and the black leave,
// R = (1 − C)(1 − K). Photoshop, which writes the Adobe marker, stores the inks inverted
// (255 is no ink). Only roughly the printed colour (no profile, no ink model), but the
// texture's pattern and about its lightness, where libjpeg refused the file.
void rgba_from_cmyk(std::vector<uint8_t>& texels, bool adobe_inverted) {
  for (size_t i = 0; i + 3 < texels.size(); i += 4) {
    auto left = [&](size_t channel) { return adobe_inverted ? texels[i + channel] : 255 - texels[i + channel]; };
    const int black_left = left(3);
    for (size_t c = 0; c < 3; ++c) texels[i + c] = static_cast<uint8_t>((left(c) * black_left + 127) / 255);
    texels[i + 3] = 255;
  }
}

enum class Decoded { ok, too_large, failed };

// Everything between setjmp and longjmp happens here, in a frame holding no C++ object
// with a destructor (longjmp would skip it) and no local changed after setjmp: libjpeg's
// state and the texels live in the caller's frame.
Decoded decode_with_libjpeg(const unsigned char* bytes, size_t size, int max_side, JpegTexels* out, JpegState* state) {
  jpeg_decompress_struct& info = state->info;
  info.err = jpeg_std_error(&state->errors);
  state->errors.error_exit = &jump_back;
  state->errors.emit_message = &keep_quiet;
  if (setjmp(state->jump) != 0) {
    jpeg_destroy_decompress(&info);
    return Decoded::failed;
  }
  jpeg_create_decompress(&info);
  jpeg_mem_src(&info, bytes, static_cast<unsigned long>(size));
  jpeg_read_header(&info, TRUE);
  out->width = static_cast<int>(info.image_width);
  out->height = static_cast<int>(info.image_height);
  if (info.image_width > static_cast<JDIMENSION>(max_side) || info.image_height > static_cast<JDIMENSION>(max_side)) {
    jpeg_destroy_decompress(&info);
    return Decoded::too_large;
  }
  // libjpeg-turbo's RGBA for grey and colour alike; its CMYK (four bytes a texel too) for
  // CMYK and YCCK, which it cannot turn into RGB.
  const bool cmyk = info.jpeg_color_space == JCS_CMYK || info.jpeg_color_space == JCS_YCCK;
  info.out_color_space = cmyk ? JCS_CMYK : JCS_EXT_RGBA;
  jpeg_start_decompress(&info);
  out->rgba.assign(static_cast<size_t>(info.output_width) * info.output_height * 4, 0);
  while (info.output_scanline < info.output_height) {
    JSAMPROW row = out->rgba.data() + static_cast<size_t>(info.output_scanline) * info.output_width * 4;
    jpeg_read_scanlines(&info, &row, 1);
  }
  if (cmyk) rgba_from_cmyk(out->rgba, info.saw_Adobe_marker != 0);
  jpeg_finish_decompress(&info);
  jpeg_destroy_decompress(&info);
  return Decoded::ok;
}

}  // namespace

JpegTexels decode_jpeg(const unsigned char* bytes, size_t size, int max_side, const std::string& where) {
  JpegTexels out;
  JpegState state{};
  switch (decode_with_libjpeg(bytes, size, max_side, &out, &state)) {
    case Decoded::ok:
      return out;
    case Decoded::too_large:
      throw InputError(where + ": the image is " + std::to_string(out.width) + " × " + std::to_string(out.height) +
                       " texels; at most " + std::to_string(max_side) + " a side is read");
    case Decoded::failed:
      break;
  }
  throw InputError(where + ": cannot decode the JPEG image (" + state.message + ")");
}

}  // namespace skylit
