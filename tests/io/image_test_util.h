// Helpers shared by the image writer tests: scratch folders, whole-file reads, and
// images built from known linear sRGB colours (so expected R, G, B are known exactly).
#pragma once

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "skylit/io/image/image.h"

namespace skylit::test {

// An empty folder of its own for one test, under the system's temporary folder,
// removed again (with its parent, once empty) when the test ends.
class ScratchFolder {
 public:
  explicit ScratchFolder(const std::string& name)
      : path_(std::filesystem::temp_directory_path() / ("skylit-io-test-" + std::to_string(::getpid())) / name) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
    std::filesystem::remove(path_.parent_path(), ec);  // only succeeds once empty
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

inline std::vector<uint8_t> read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Names of everything in `dir`, sorted (hidden temporaries included).
inline std::vector<std::string> listing(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// A 1-row image whose pixels are the given linear sRGB colours (absolute: their
// 0.2126 R + 0.7152 G + 0.0722 B is the luminance in cd/m²).
inline XyzImage image_from_srgb(const std::vector<Rgb>& colours) {
  XyzImage image(static_cast<int>(colours.size()), 1);
  for (int x = 0; x < image.width; ++x) image.set(x, 0, xyz_from_linear_srgb(colours[x]));
  return image;
}

// A 1-row image of D65 greys at the given luminances (cd/m²).
inline XyzImage row_of_greys(const std::vector<double>& luminances) {
  std::vector<Rgb> colours;
  for (double l : luminances) colours.push_back({l, l, l});
  return image_from_srgb(colours);
}

// A uniform image of D65 grey (x, y = 0.3127, 0.3290) at `luminance` cd/m².
inline XyzImage grey_image(int width, int height, double luminance) {
  XyzImage image(width, height);
  const Xyz grey = xyz_from_linear_srgb({luminance, luminance, luminance});
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) image.set(x, y, grey);
  return image;
}

}  // namespace skylit::test
