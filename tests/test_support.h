// Helpers shared by the tests: a fresh temporary folder, files written into it,
// running the built `skylit` program, and the message of the InputError a call throws.
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "skylit/core/error.h"

namespace skylit::testing {

// The InputError message, or "" if `f` did not throw one.
template <typename F>
std::string input_error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// A folder under the system's temporary folder, removed with its contents on destruction.
class TempDir {
 public:
  TempDir() {
    std::random_device seed;
    path_ = std::filesystem::temp_directory_path() / ("skylit_test_" + std::to_string(seed()) + std::to_string(seed()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const std::filesystem::path file = path_ / name;
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }

 private:
  std::filesystem::path path_;
};

inline std::string read_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct CommandResult {
  int exit_status;
  std::string output;  // stdout and stderr together
};

// A path in single quotes for the shell. Built by appending: `"'" + p.string()` trips
// GCC 12's false -Wrestrict (GCC bug 105329).
inline std::string quoted(const std::filesystem::path& p) {
  std::string text = "'";
  text += p.string();
  text += '\'';
  return text;
}

// Runs a shell command line; `output` collects what it prints on stdout (add 2>&1 for
// stderr too).
inline CommandResult run_command(const std::string& command) {
  CommandResult result{-1, {}};
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  char buffer[4096];
  size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) result.output.append(buffer, n);
  const int status = pclose(pipe);
  result.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

// Runs the built program with the given arguments (already shell-quoted); `environment`
// (VAR=value ... or a launcher such as `mpirun -n 2`) goes before it.
inline CommandResult run_skylit_with_env(const std::string& environment, const std::string& arguments) {
  return run_command(environment + " '" + SKYLIT_CLI_PATH + "' " + arguments + " 2>&1");
}

// Runs the built program with the given arguments (already shell-quoted).
inline CommandResult run_skylit(const std::string& arguments) { return run_skylit_with_env("", arguments); }

// A small valid scene: a box on a plane under a high sun.
inline std::string small_scene_json(int width = 48, int height = 32) {
  return R"({
  "camera": {"position": [0, -20, 2], "look_at": [0, 0, 3], "vertical_fov_deg": 60},
  "sun": {"altitude_deg": 40, "azimuth_deg": 135},
  "materials": {"white": {"type": "diffuse", "reflectance": 0.8},
                "red": {"type": "diffuse", "reflectance": {"srgb": [0.7, 0.2, 0.1]}}},
  "objects": [
    {"type": "plane", "material": "white", "size_m": 200},
    {"type": "box", "material": "red", "center": [0, 0, 3], "size": [4, 4, 6], "rotation_z_deg": 30}
  ],
  "render": {"width": )" +
         std::to_string(width) + R"(, "height": )" + std::to_string(height) + R"(}
})";
}

// The small test scene with `key: value` added at its top level.
inline std::string small_scene_with(const std::string& key, const std::string& value) {
  std::string text = small_scene_json();
  text.insert(text.rfind('}'), ", \"" + key + "\": " + value + "\n");
  return text;
}

}  // namespace skylit::testing
