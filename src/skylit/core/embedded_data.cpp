#include "skylit/core/embedded_data.h"

#include <stdexcept>
#include <string>

namespace skylit::data {

std::string_view embedded_file(std::string_view name) {
  for (const EmbeddedFile& file : embedded_files()) {
    if (file.name == name) return file.text;
  }
  throw std::logic_error("data table not embedded: " + std::string(name));
}

}  // namespace skylit::data
