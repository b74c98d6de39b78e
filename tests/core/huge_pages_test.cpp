// HugePageAllocator: a frame's large buffers in 2 MiB pages (core/huge_pages.h).
#include "skylit/core/huge_pages.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <numeric>
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

TEST(HugePages, TheKernelBacksALargeBufferWithHugePagesWhereItHasThem) {
  std::ifstream setting("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string modes;
  std::getline(setting, modes);
  if (modes.find("[never]") != std::string::npos || modes.empty())
    GTEST_SKIP() << "this kernel gives no transparent huge pages: " << modes;
  HugePageVector<char> buffer(size_t{16} << 20, 1);  // written: its pages exist
  // Eight huge pages' worth; at least one of them must be a huge page (a fragmented
  // memory may refuse some).
  EXPECT_GE(anon_huge_kb_at(buffer.data()), 2048) << "transparent huge pages: " << modes;
}

}  // namespace
}  // namespace skylit
