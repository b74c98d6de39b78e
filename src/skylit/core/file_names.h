// File names as the program reads them: formats are chosen by extension, in any case
// (a camera's "IMG.PNG", Windows' "MODEL.OBJ").
#pragma once

#include <cctype>
#include <filesystem>
#include <string>

namespace skylit {

inline std::string lower_case(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// The extension with its dot, lower-cased: "a/B.EXR" → ".exr"; "" when there is none.
inline std::string lower_case_extension(const std::filesystem::path& path) {
  return lower_case(path.extension().string());
}

}  // namespace skylit
