// The data tables of data/, compiled into the library (see cmake/EmbedData.cmake),
// so that the program finds its spectral data wherever it is run from.
#pragma once

#include <string_view>
#include <vector>

namespace skylit::data {

struct EmbeddedFile {
  std::string_view name;  // file name in data/, e.g. "cie1931_2deg_cmf.csv"
  std::string_view text;  // the file's contents
};

const std::vector<EmbeddedFile>& embedded_files();

// The text of data/NAME; throws std::logic_error if it was not embedded (a build error).
std::string_view embedded_file(std::string_view name);

}  // namespace skylit::data
