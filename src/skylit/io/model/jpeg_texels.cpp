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
  info.out_color_space = JCS_EXT_RGBA;  // libjpeg-turbo's: grey and colour alike
  jpeg_start_decompress(&info);
  out->rgba.assign(static_cast<size_t>(info.output_width) * info.output_height * 4, 0);
  while (info.output_scanline < info.output_height) {
    JSAMPROW row = out->rgba.data() + static_cast<size_t>(info.output_scanline) * info.output_width * 4;
    jpeg_read_scanlines(&info, &row, 1);
  }
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
