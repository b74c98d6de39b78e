// read_image (image_reader.h): the extension picks the decoder; a missing file is
// refused here, before any library sees it, so the message is ours and says what is wrong.
#include "skylit/io/image/image_reader.h"

#include <fstream>
#include <iterator>
#include <string>
#include <system_error>

#include "skylit/core/error.h"
#include "skylit/core/file_names.h"
#include "skylit/io/image/image_decoders.h"

namespace skylit {
namespace {

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw InputError("cannot read \"" + path.string() + "\": read error");
  return bytes;
}

}  // namespace

XyzImage read_image(const std::filesystem::path& path) {
  const std::string ext = lower_case_extension(path);
  if (ext != ".exr" && ext != ".pfm")
    throw InputError("cannot read \"" + path.string() +
                     "\": " + (ext.empty() ? std::string("no file extension") : "unknown extension \"" + ext + "\"") +
                     "; an image to compare is read from .exr or .pfm");
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError("cannot read \"" + path.string() + "\": no such file");
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError("cannot read \"" + path.string() + "\": not a regular file");
  return ext == ".exr" ? decode_exr(path) : decode_pfm(read_bytes(path), path);
}

}  // namespace skylit
