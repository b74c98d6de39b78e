#include "skylit/core/huge_pages.h"

#include <sys/mman.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>

namespace skylit {

namespace {
constexpr size_t kHugePageBytes = size_t{2} << 20;
}

void* allocate_in_huge_pages(size_t bytes, size_t alignment) {
  const bool huge = bytes >= kHugePageBytes;
  if (huge) alignment = kHugePageBytes;
  alignment = std::max(alignment, alignof(std::max_align_t));
  // std::aligned_alloc wants a multiple of the alignment.
  const size_t rounded = (std::max<size_t>(bytes, 1) + alignment - 1) / alignment * alignment;
  void* p = std::aligned_alloc(alignment, rounded);
  if (!p) throw std::bad_alloc();
  if (huge) advise_huge_pages(p, rounded);
  return p;
}

void advise_huge_pages(void* p, size_t bytes) {
  // From the first 2 MiB boundary in the range, whole huge pages only.
  const size_t skip = (kHugePageBytes - reinterpret_cast<uintptr_t>(p) % kHugePageBytes) % kHugePageBytes;
  if (bytes < skip + kHugePageBytes) return;
#ifdef MADV_HUGEPAGE
  // Advice only: where the kernel has no transparent huge pages the call fails and the
  // memory keeps ordinary pages.
  madvise(static_cast<char*>(p) + skip, (bytes - skip) / kHugePageBytes * kHugePageBytes, MADV_HUGEPAGE);
#endif
}

}  // namespace skylit
