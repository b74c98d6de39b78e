// HugePageAllocator: a frame's large buffers in 2 MiB pages (core/huge_pages.h).
#include "skylit/core/huge_pages.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <numeric>
#include <optional>
#include <sstream>
#include <string>

namespace skylit {
namespace {

TEST(HugePages, SmallAndLargeBuffersHoldTheirValues) {
  for (const size_t n : {size_t{0}, size_t{1}, size_t{1000}, size_t{3} << 20}) {
    HugePageVector<uint32_t> values(n);
    std::iota(values.begin(), values.end(), 7u);
    for (size_t i = 0; i < n; i += 4099) ASSERT_EQ(values[i], 7u + i);
    HugePageVector<uint32_t> copy = values;
    EXPECT_EQ(copy, values);
  }
}

TEST(HugePages, SmallBuffersKeepTheirTypesAlignment) {
  struct alignas(64) Line {
    float values[16];
  };
  for (const size_t n : {size_t{1}, size_t{3}, size_t{1000}}) {
    const HugePageVector<Line> lines(n);
    EXPECT_EQ(reinterpret_cast<uintptr_t>(lines.data()) % 64, 0u) << n;
  }
}

TEST(HugePages, ALargeBufferStartsOnAHugePage) {
  // Otherwise the advice would cover only the whole 2 MiB pages inside it.
  const HugePageVector<char> buffer(size_t{5} << 20);
  EXPECT_EQ(reinterpret_cast<uintptr_t>(buffer.data()) % (size_t{2} << 20), 0u);
}

// The kilobytes of huge pages backing the mapping that holds `address` (/proc/self/smaps).
long anon_huge_kb_at(const void* address) {
  std::ifstream smaps("/proc/self/smaps");
  const uintptr_t a = reinterpret_cast<uintptr_t>(address);
  bool inside = false;
  for (std::string line; std::getline(smaps, line);) {
    uintptr_t start = 0, end = 0;
    char dash = 0;
    if (std::istringstream range(line); range >> std::hex >> start >> dash >> end && dash == '-') {
      inside = start <= a && a < end;
    } else if (inside && line.rfind("AnonHugePages:", 0) == 0) {
      return std::stol(line.substr(14));
    }
  }
  return -1;
}

// The kernel's setting of transparent huge pages, if it gives them at all.
std::optional<std::string> huge_page_modes() {
  std::ifstream setting("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string modes;
  std::getline(setting, modes);
  if (modes.empty() || modes.find("[never]") != std::string::npos) return std::nullopt;
  return modes;
}

TEST(HugePages, TheKernelBacksALargeBufferWithHugePagesWhereItHasThem) {
  const std::optional<std::string> modes = huge_page_modes();
  if (!modes) GTEST_SKIP() << "this kernel gives no transparent huge pages";
  HugePageVector<char> buffer(size_t{16} << 20, 1);  // written: its pages exist
  // Eight huge pages' worth; at least one of them must be a huge page (a fragmented
  // memory may refuse some).
  EXPECT_GE(anon_huge_kb_at(buffer.data()), 2048) << "transparent huge pages: " << *modes;
}

TEST(HugePages, AdviceOnAReservedStringGivesItHugePages) {
  // As read_text_file reads a large model's file.
  const std::optional<std::string> modes = huge_page_modes();
  if (!modes) GTEST_SKIP() << "this kernel gives no transparent huge pages";
  std::string text;
  text.reserve(size_t{16} << 20);
  advise_huge_pages(text.data(), text.capacity());
  text.resize(size_t{16} << 20, 'x');
  EXPECT_GE(anon_huge_kb_at(text.data() + (size_t{8} << 20)), 2048) << "transparent huge pages: " << *modes;
}

}  // namespace
}  // namespace skylit
