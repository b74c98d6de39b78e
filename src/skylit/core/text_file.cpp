#include "skylit/core/text_file.h"

#include <fstream>
#include <sstream>

#include "skylit/core/error.h"

namespace skylit {

std::string read_text_file(const std::filesystem::path& file, const std::string& what) {
  std::error_code error;
  // An ifstream opens a directory without complaint on Linux; refuse it here.
  if (std::filesystem::is_directory(file, error)) throw InputError(file.string() + ":1: cannot read the " + what);
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string() + ":1: cannot open the " + what);
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(file.string() + ":1: cannot read the " + what);
  return text.str();
}

}  // namespace skylit
