// What every fuzz target shares: the rule that an InputError is a fine answer, and a
// private folder for parsers that read files rather than bytes.
#pragma once

#include <stdlib.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "skylit/core/error.h"

namespace skylit::fuzz {

inline std::string_view text_of(const uint8_t* data, size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// Runs `parse`; a user's mistake (InputError) is the expected answer to bad input.
// Any other exception escapes, and libFuzzer reports it as a crash.
template <class F>
int accept_input_errors(F&& parse) {
  try {
    parse();
  } catch (const InputError&) {
  }
  return 0;
}

// A folder of this process's own, made once, removed at exit (kept on the heap so
// that it outlives the static destructors that run before the exit handler).
inline const std::filesystem::path& work_dir() {
  static const std::filesystem::path* dir = [] {
    std::string pattern = (std::filesystem::temp_directory_path() / "skylit-fuzz-XXXXXX").string();
    if (!mkdtemp(pattern.data())) abort();
    auto* made = new std::filesystem::path(pattern);
    std::atexit([] {
      std::error_code ignored;
      std::filesystem::remove_all(work_dir(), ignored);
    });
    return made;
  }();
  return *dir;
}

// Writes the bytes to `name` in the work folder and returns its path.
inline std::filesystem::path write_file(const std::string& name, std::string_view bytes) {
  const std::filesystem::path path = work_dir() / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) abort();
  return path;
}

}  // namespace skylit::fuzz
