// Every example rendered small through the program and compared with its reference
// image in tests/reference_images/ (made by scripts/make-reference-images.sh), so that a
// change that moves pixels is seen and must be explained: such a change regenerates the
// references in the same commit and says why in its message.
//
// The tolerance. The renderer is deterministic (the same bytes for any thread count),
// so today the difference is exactly 0. A refactoring that reorders float sums moves
// values by about 1e-6 relative; a real change of physics moves them by more than 1e-3.
// Between the two:
//
//  1. Per pixel, in each of X, Y and Z (so a change of colour shows, not only one of
//     luminance): |new − ref| ≤ 1e-3 · (|ref| + F), with F = 1e-2 × the reference's
//     log-average luminance (docs/images.md: what automatic exposure meters). The floor
//     1e-3 · F = 1e-5 · L_avg only matters for pixels darker than 1 % of the image's
//     typical luminance (shadows at night, the ground's far side of a lamp): there a
//     relative test would fail on rounding, and a change of 1e-5 · L_avg is far below
//     anything visible (exposed so L_avg shows as 0.18, it is under 1/100 of an 8-bit
//     code value). The log-average, not the mean, because one pixel of the sun's disc
//     (1.6e9 cd/m²) would raise the mean of a 7 000-pixel image by 2e5 cd/m² and make
//     the floor hide everything else.
//  2. A few pixels may differ more: the renderer refines a pixel to its full n × n grid
//     where a neighbour's centre differs by more than 5 % (kEdgeContrast in
//     renderer.cpp), so a 1e-6 change can flip a pixel that lies at the threshold
//     between 1 and n² samples. Such a pixel varies by about 5 % across its area, so its
//     value moves by a few per cent. At most 0.2 % of the pixels (14 of 112 × 63) may
//     exceed (1) but must stay within 5e-2 · (|ref| + F). A pixel centre that meets a
//     different object (a silhouette moved) changes by far more and fails: that is a
//     change of geometry, to be explained.
//  3. The image's mean X, Y and Z within 1e-3 relative, so that a change spread thinly
//     over all pixels (a scale of 1.002) cannot pass under (1) pixel by pixel.
//
// Measured on these examples (the sun's altitude and azimuth moved a little through
// --set, a stand-in for rounding): by 1e-5° or 1e-4° (2e-7, 2e-6 rad) no pixel moves by
// more than 8e-4 of (1)'s scale; fig10a's bright cloud edges are the most sensitive,
// every other example stays under 3e-5. By 1e-3° fig10a has one pixel at 2.7e-3, let
// through by (2), and building.json one at 23 %: one of a refined pixel's four samples
// crossed a shadow's edge. That fails, as it should: a shadow moved.
//
// On failure the message names the scene, counts the pixels over each limit, gives the
// worst pixel with both values, and keeps the new render and a difference image (PFM,
// R, G, B = (new − ref) / (|ref| + F) in X, Y, Z: ±0.001 is the per-pixel limit) in a
// folder whose path it prints.
#include <unistd.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../test_support.h"
#include "skylit/spectrum/color_space.h"

namespace skylit {
namespace {

namespace fs = std::filesystem;
using testing::quoted;

const fs::path kExamples = fs::path(SKYLIT_SOURCE_DIR) / "examples";
const fs::path kReferences = fs::path(SKYLIT_SOURCE_DIR) / "tests" / "reference_images";

// An image as absolute X, Y, Z (cd/m² for Y), rows from the top.
struct Image {
  int width = 0, height = 0;
  std::vector<std::array<double, 3>> xyz;
};

// Reads an EXR written by skylit: Y from its Y channel, X and Z from R, G, B (linear
// sRGB primaries, absolute; docs/images.md).
Image read_exr(const fs::path& path) {
  Imf::InputFile file(path.c_str());
  const Imf::Header& header = file.header();
  const Imath::Box2i window = header.dataWindow();
  Image image;
  image.width = window.max.x - window.min.x + 1;
  image.height = window.max.y - window.min.y + 1;
  const size_t n = size_t(image.width) * image.height;
  std::array<std::vector<float>, 4> channels;
  Imf::FrameBuffer frame;
  const char* names[4] = {"R", "G", "B", "Y"};
  for (int c = 0; c < 4; ++c) {
    if (header.channels().findChannel(names[c]) == nullptr)
      throw std::runtime_error(path.string() + ": no channel " + names[c]);
    channels[c].assign(n, NAN);
    frame.insert(names[c], Imf::Slice::Make(Imf::FLOAT, channels[c].data(), window));
  }
  file.setFrameBuffer(frame);
  file.readPixels(window.min.y, window.max.y);
  image.xyz.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const Xyz from_rgb = xyz_from_linear_srgb({channels[0][i], channels[1][i], channels[2][i]});
    image.xyz[i] = {from_rgb.x, channels[3][i], from_rgb.z};
  }
  return image;
}

// The tolerance explained at the top of this file.
struct Tolerance {
  double pixel_relative = 1e-3;        // (1): of |ref| + F
  double floor_of_log_average = 1e-2;  // F as a fraction of the log-average luminance
  double edge_relative = 5e-2;         // (2): for the few pixels allowed beyond (1)
  double edge_fraction = 2e-3;         // (2): the share of pixels allowed beyond (1)
  double mean_relative = 1e-3;         // (3)
};

struct Comparison {
  bool passed = true;
  std::string report;                            // why it failed, for the test's message; empty if it passed
  double floor = 0;                              // F, cd/m²
  std::vector<std::array<float, 3>> normalised;  // (new − ref) / (|ref| + F) per pixel
};

// exp(mean ln(δ + max(Y, 0))), δ = 1e-4 cd/m², over finite pixels (docs/images.md);
// computed here rather than by the library, so the test does not lean on the code it checks.
double log_average_luminance(const Image& image) {
  double sum = 0;
  size_t count = 0;
  for (const auto& p : image.xyz)
    if (std::isfinite(p[1])) sum += std::log(1e-4 + std::max(p[1], 0.0)), ++count;
  return count ? std::exp(sum / double(count)) : 1e-4;
}

Comparison compare(const Image& ref, const Image& img, const Tolerance& tol = {}) {
  Comparison out;
  std::ostringstream why;
  if (ref.width != img.width || ref.height != img.height) {
    why << "size " << img.width << " × " << img.height << ", reference " << ref.width << " × " << ref.height;
    out.passed = false;
    out.report = why.str();
    return out;
  }
  const size_t n = ref.xyz.size();
  out.floor = tol.floor_of_log_average * log_average_luminance(ref);
  out.normalised.resize(n);
  size_t beyond_pixel = 0, beyond_edge = 0, worst = 0;
  double worst_error = -1;
  std::array<double, 3> ref_sum{}, img_sum{};
  for (size_t i = 0; i < n; ++i) {
    double error = 0;
    for (int c = 0; c < 3; ++c) {
      const double a = ref.xyz[i][c], b = img.xyz[i][c];
      const double e = (b - a) / (std::abs(a) + out.floor);
      out.normalised[i][c] = float(e);
      error = std::isfinite(e) ? std::max(error, std::abs(e)) : INFINITY;  // NaN fails too
      ref_sum[c] += a;
      img_sum[c] += b;
    }
    if (error > tol.pixel_relative) ++beyond_pixel;
    if (error > tol.edge_relative) ++beyond_edge;
    if (error > worst_error) worst_error = error, worst = i;
  }
  const size_t edge_allowed = size_t(tol.edge_fraction * double(n));
  const char* axis = "XYZ";
  if (beyond_pixel > edge_allowed) {
    out.passed = false;
    why << beyond_pixel << " of " << n << " pixels differ by more than " << tol.pixel_relative
        << " (relative, floor F = " << out.floor << " cd/m²); at most " << edge_allowed << " may.\n";
  }
  if (beyond_edge > 0) {
    out.passed = false;
    why << beyond_edge << " pixels differ by more than " << tol.edge_relative << " (none may).\n";
  }
  for (int c = 0; c < 3; ++c) {
    const double a = ref_sum[c] / double(n), b = img_sum[c] / double(n);
    const double e = (b - a) / std::abs(a);
    if (!(std::abs(e) <= tol.mean_relative)) {
      out.passed = false;
      why << "mean " << axis[c] << " " << b << ", reference " << a << " (" << std::showpos << e << std::noshowpos
          << " relative; limit " << tol.mean_relative << ").\n";
    }
  }
  if (!out.passed) {
    const int wx = int(worst % size_t(ref.width)), wy = int(worst / size_t(ref.width));
    why << "Worst pixel (" << wx << ", " << wy << ") from the top left: X, Y, Z = " << img.xyz[worst][0] << ", "
        << img.xyz[worst][1] << ", " << img.xyz[worst][2] << "; reference " << ref.xyz[worst][0] << ", "
        << ref.xyz[worst][1] << ", " << ref.xyz[worst][2] << " (error " << worst_error << " of |ref| + F).\n";
    out.report = why.str();
  }
  return out;
}

// PFM (rows from the bottom, little-endian floats) of the normalised differences.
void write_difference_pfm(const Comparison& comparison, int width, int height, const fs::path& path) {
  std::ofstream out(path, std::ios::binary);
  out << "PF\n" << width << " " << height << "\n-1.0\n";
  for (int y = height - 1; y >= 0; --y)
    out.write(reinterpret_cast<const char*>(comparison.normalised[size_t(y) * width].data()),
              std::streamsize(sizeof(float) * 3 * width));
}

std::vector<std::string> example_names() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(kExamples))
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

class ReferenceImage : public ::testing::TestWithParam<std::string> {};

TEST_P(ReferenceImage, RendersAsBefore) {
  const std::string name = GetParam();
  const fs::path reference_path = kReferences / (name + ".exr");
  ASSERT_TRUE(fs::exists(reference_path)) << "examples/" << name << ".json has no reference image; run "
                                          << "scripts/make-reference-images.sh and commit the result";
  const Image reference = read_exr(reference_path);

  // A folder kept when the comparison fails, so the new render can be looked at.
  const fs::path dir = fs::temp_directory_path() / ("skylit-reference-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path rendered = dir / (name + ".exr");
  const auto r = testing::run_skylit(
      "render " + quoted(kExamples / (name + ".json")) + " --set render.width=" + std::to_string(reference.width) +
      " --set render.height=" + std::to_string(reference.height) + " --quiet -o " + quoted(rendered));
  ASSERT_EQ(r.exit_status, 0) << r.output;

  const Image image = read_exr(rendered);
  const Comparison comparison = compare(reference, image);
  if (comparison.passed) {
    fs::remove_all(dir);
    return;
  }
  fs::path difference;
  if (!comparison.normalised.empty()) {
    difference = dir / (name + "-difference.pfm");
    write_difference_pfm(comparison, image.width, image.height, difference);
  }
  ADD_FAILURE() << "examples/" << name << ".json no longer renders as its reference " << reference_path.string()
                << ":\n"
                << comparison.report << "New render: " << rendered.string() << "\n"
                << (difference.empty() ? ""
                                       : "Difference image (R, G, B = (new − ref) / (|ref| + F) of X, Y, Z): " +
                                             difference.string() + "\n")
                << "If the change is meant to move pixels, run scripts/make-reference-images.sh and say why in "
                   "the commit message (tests/reference_images/README.md).";
}

std::string scene_test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Examples, ReferenceImage, ::testing::ValuesIn(example_names()), scene_test_name);

TEST(ReferenceImages, EveryExampleHasOneAndEveryOneAnExample) {
  const std::vector<std::string> examples = example_names();
  ASSERT_FALSE(examples.empty());
  for (const std::string& name : examples)
    EXPECT_TRUE(fs::exists(kReferences / (name + ".exr")))
        << "examples/" << name << ".json has no reference image; run scripts/make-reference-images.sh";
  for (const auto& entry : fs::directory_iterator(kReferences)) {
    if (entry.path().extension() != ".exr") continue;
    EXPECT_TRUE(fs::exists(kExamples / (entry.path().stem().string() + ".json")))
        << entry.path().string() << " is the reference of no example; remove it";
  }
}

// The comparison itself: it passes a copy and rounding, and rejects the changes it must.
class ReferenceComparison : public ::testing::Test {
 protected:
  void SetUp() override { reference_ = read_exr(kReferences / "building.exr"); }
  Image reference_;
};

TEST_F(ReferenceComparison, AcceptsTheSameImageAndRounding) {
  EXPECT_TRUE(compare(reference_, reference_).passed);
  Image rounded = reference_;
  for (auto& p : rounded.xyz)
    for (double& v : p) v *= 1 + 2e-6;
  EXPECT_TRUE(compare(reference_, rounded).passed);
}

TEST_F(ReferenceComparison, AcceptsAFewEdgePixelsOffByAFewPercent) {
  Image image = reference_;
  for (int i = 0; i < 10; ++i) image.xyz[size_t(i) * 701][1] *= 1.03;
  EXPECT_TRUE(compare(reference_, image).passed) << compare(reference_, image).report;
}

TEST_F(ReferenceComparison, RejectsOnePixelOffByTenPercent) {
  Image image = reference_;
  image.xyz[image.xyz.size() / 2][1] *= 1.10;
  const Comparison c = compare(reference_, image);
  EXPECT_FALSE(c.passed);
  EXPECT_NE(c.report.find("1 pixels differ by more than 0.05"), std::string::npos) << c.report;
  EXPECT_NE(c.report.find("Worst pixel (56, 31)"), std::string::npos) << c.report;
}

TEST_F(ReferenceComparison, RejectsManyPixelsOffByAFewPercent) {
  Image image = reference_;
  for (int i = 0; i < 30; ++i) image.xyz[size_t(i) * 201][1] *= 1.03;
  EXPECT_FALSE(compare(reference_, image).passed);
}

TEST_F(ReferenceComparison, RejectsAllPixelsScaledBy1002) {
  Image image = reference_;
  for (auto& p : image.xyz)
    for (double& v : p) v *= 1.002;
  const Comparison c = compare(reference_, image);
  EXPECT_FALSE(c.passed);
  EXPECT_NE(c.report.find("mean Y"), std::string::npos) << c.report;
}

TEST_F(ReferenceComparison, RejectsAChangeOfColourAtTheSameLuminance) {
  Image image = reference_;
  for (auto& p : image.xyz) p[2] *= 1.002;  // Z only: bluer, Y unchanged
  const Comparison c = compare(reference_, image);
  EXPECT_FALSE(c.passed);
  EXPECT_NE(c.report.find("mean Z"), std::string::npos) << c.report;
}

TEST_F(ReferenceComparison, RejectsADifferentSize) { EXPECT_FALSE(compare(reference_, Image{}).passed); }

// The whole chain, through the program: the sun half a degree higher must fail.
TEST(ReferenceImages, SunHalfADegreeHigherFails) {
  const Image reference = read_exr(kReferences / "building.exr");
  testing::TempDir dir;
  const fs::path rendered = dir.path() / "building.exr";
  const auto r = testing::run_skylit("render " + quoted(kExamples / "building.json") +
                                     " --set render.width=" + std::to_string(reference.width) +
                                     " --set render.height=" + std::to_string(reference.height) +
                                     " --set sun.altitude_deg=30.5 --quiet -o " + quoted(rendered));
  ASSERT_EQ(r.exit_status, 0) << r.output;
  const Comparison c = compare(reference, read_exr(rendered));
  EXPECT_FALSE(c.passed);
  std::printf("%s", c.report.c_str());  // what a failure reports
}

}  // namespace
}  // namespace skylit
