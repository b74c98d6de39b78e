// write_image's contract beyond the pixels: format from the extension, InputError that
// names the path, no file and no temporary left behind on failure, nothing but the
// target left on success, and the same bytes for the same image. Also XyzImage itself.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>
#include "../test_support.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "image_test_util.h"
#include "skylit/core/error.h"
#include "skylit/io/atomic_file.h"
#include "skylit/io/image/image.h"

namespace skylit {
namespace {

using testing::input_error_of;

TEST(ImageWrite, FormatFromExtensionIgnoresCase) {
  EXPECT_EQ(image_format_from_path("a/b.png"), ImageFormat::png);
  EXPECT_EQ(image_format_from_path("b.PNG"), ImageFormat::png);
  EXPECT_EQ(image_format_from_path("b.Exr"), ImageFormat::exr);
  EXPECT_EQ(image_format_from_path("b.pfm"), ImageFormat::pfm);
  EXPECT_EQ(image_format_from_path("x.y.HDR"), ImageFormat::hdr);
  EXPECT_THROW(image_format_from_path("render"), InputError);
  EXPECT_THROW(image_format_from_path("render.tiff"), InputError);
  EXPECT_THROW(image_format_from_path("png"), InputError);  // a name, not an extension
}

TEST(ImageWrite, NonFinitePixelsAreAnInternalErrorAndNothingIsWritten) {
  // Issue 19: the writers turned NaN and Inf black, which hid the renderer's bugs. Now
  // they are counted, and the image is refused in every format (a logic_error: exit 1).
  test::ScratchFolder dir("non-finite");
  XyzImage image = test::grey_image(3, 2, 10.0);
  image.set(0, 0, {NAN, 1, 1});
  image.set(2, 1, {1, INFINITY, 1});
  for (const char* name : {"a.exr", "a.pfm", "a.hdr", "a.png"}) {
    try {
      write_image(image, dir / name);
      ADD_FAILURE() << name << " was written";
    } catch (const NonFinitePixels& e) {
      EXPECT_NE(std::string(e.what()).find("2 of 6 pixels are not finite"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), std::filesystem::directory_iterator()), 0);
  EXPECT_NO_THROW(check_pixels_finite(test::grey_image(3, 2, 1e30), "fine.exr"));
}

TEST(ImageWrite, UnknownExtensionIsInputErrorAndLeavesNoFile) {
  test::ScratchFolder dir("unknown-extension");
  const std::filesystem::path path = dir / "render.tiff";
  const std::string message = input_error_of([&] { write_image(test::grey_image(2, 2, 1), path); });
  EXPECT_NE(message.find(path.string()), std::string::npos) << message;
  EXPECT_NE(message.find(".tiff"), std::string::npos) << message;
  EXPECT_TRUE(test::listing(dir.path()).empty());
}

TEST(ImageWrite, MissingFolderIsInputErrorNamingThePath) {
  test::ScratchFolder dir("missing-folder");
  for (const char* name : {"render.png", "render.exr", "render.pfm", "render.hdr"}) {
    const std::filesystem::path path = dir / "no-such-folder" / name;
    const std::string message = input_error_of([&] { write_image(test::grey_image(2, 2, 1), path); });
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
  }
  EXPECT_TRUE(test::listing(dir.path()).empty());
}

TEST(ImageWrite, FolderThatIsAFileIsInputError) {
  test::ScratchFolder dir("folder-is-file");
  { std::ofstream(dir / "file") << "x"; }
  EXPECT_THROW(write_image(test::grey_image(2, 2, 1), dir / "file" / "render.png"), InputError);
  EXPECT_EQ(test::listing(dir.path()), std::vector<std::string>{"file"});
}

TEST(ImageWrite, UnwritableFolderIsInputError) {
  if (::geteuid() == 0) GTEST_SKIP() << "root writes into read-only folders";
  test::ScratchFolder dir("unwritable");
  std::filesystem::create_directory(dir / "ro");
  ::chmod((dir / "ro").c_str(), 0555);
  const std::filesystem::path path = dir / "ro" / "render.exr";
  const std::string message = input_error_of([&] { write_image(test::grey_image(2, 2, 1), path); });
  ::chmod((dir / "ro").c_str(), 0755);
  EXPECT_NE(message.find(path.string()), std::string::npos) << message;
  EXPECT_TRUE(test::listing(dir / "ro").empty());
}

TEST(ImageWrite, SuccessLeavesOnlyTheTargetsAndOverwrites) {
  test::ScratchFolder dir("only-targets");
  { std::ofstream(dir / "render.png") << "an older file"; }
  for (const char* name : {"render.png", "render.exr", "render.pfm", "render.hdr"})
    write_image(test::grey_image(9, 3, 100), dir / name);
  EXPECT_EQ(test::listing(dir.path()),
            (std::vector<std::string>{"render.exr", "render.hdr", "render.pfm", "render.png"}));
  const std::vector<uint8_t> png = test::read_bytes(dir / "render.png");
  ASSERT_GE(png.size(), 8u);
  EXPECT_EQ(png[1], 'P');  // the old text was replaced by a PNG
}

TEST(ImageWrite, SameImageGivesSameBytes) {
  test::ScratchFolder dir("deterministic");
  XyzImage image(17, 19);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      image.set(x, y, xyz_from_linear_srgb({std::pow(1.7, x % 9), 3.0 + y, 0.5 * (x + y)}));
  for (const char* ext : {".png", ".exr", ".pfm", ".hdr"}) {
    write_image(image, dir / (std::string("a") + ext));
    write_image(image, dir / (std::string("b") + ext));
    const std::vector<uint8_t> a = test::read_bytes(dir / (std::string("a") + ext));
    EXPECT_FALSE(a.empty()) << ext;
    EXPECT_EQ(a, test::read_bytes(dir / (std::string("b") + ext))) << ext;
  }
}

TEST(ImageWrite, BadImagesAndExposureAreRefusedBeforeAnyFileExists) {
  test::ScratchFolder dir("refused");
  EXPECT_THROW(write_image(XyzImage(), dir / "empty.png"), std::invalid_argument);
  XyzImage wrong_size(2, 2);
  wrong_size.xyz.pop_back();
  EXPECT_THROW(write_image(wrong_size, dir / "wrong.exr"), std::invalid_argument);
  EXPECT_THROW(write_image(test::grey_image(2, 2, 1), dir / "ev.png", DisplayOptions{INFINITY}), InputError);
  EXPECT_TRUE(test::listing(dir.path()).empty());
}

TEST(ImageXyz, PixelsAreRowMajorFromTheTopLeftAndBoundsChecked) {
  XyzImage image(3, 2);
  EXPECT_EQ(image.xyz.size(), 18u);
  image.set(2, 1, {1, 2, 3});
  EXPECT_EQ(image.xyz[3 * (1 * 3 + 2) + 1], 2.0f);
  EXPECT_EQ(image.at(2, 1).z, 3.0);
  EXPECT_THROW(image.at(3, 0), std::out_of_range);
  EXPECT_THROW(image.set(0, 2, {}), std::out_of_range);
  EXPECT_THROW(image.at(-1, 0), std::out_of_range);
  EXPECT_THROW(XyzImage(-1, 2), std::invalid_argument);
}

TEST(ImageAtomicFile, UncommittedLeavesTheOldFileAndNoTemporary) {
  test::ScratchFolder dir("atomic-abort");
  { std::ofstream(dir / "out.png") << "old"; }
  {
    AtomicFile file(dir / "out.png");
    EXPECT_TRUE(std::filesystem::exists(file.temporary()));
    EXPECT_EQ(file.temporary().parent_path(), dir.path());  // same folder: atomic rename
  }                                                         // e.g. an exception while encoding
  EXPECT_EQ(test::listing(dir.path()), std::vector<std::string>{"out.png"});
  const std::vector<uint8_t> old = test::read_bytes(dir / "out.png");
  EXPECT_EQ(std::string(old.begin(), old.end()), "old");
}

TEST(ImageAtomicFile, CommitReplacesTheTargetWhole) {
  test::ScratchFolder dir("atomic-commit");
  { std::ofstream(dir / "out.bin") << "a much longer old content"; }
  const std::vector<uint8_t> bytes{1, 2, 3};
  {
    AtomicFile file(dir / "out.bin");
    file.commit(bytes);
  }
  EXPECT_EQ(test::read_bytes(dir / "out.bin"), bytes);
  EXPECT_EQ(test::listing(dir.path()), std::vector<std::string>{"out.bin"});
}

}  // namespace
}  // namespace skylit
