#include "skylit/core/huge_pages.h"

#include <sys/mman.h>

#include <algorithm>
#include <cstddef>
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
  if (!huge) return p;
#ifdef MADV_HUGEPAGE
  // Advice only: where the kernel has no transparent huge pages the call fails and the
  // buffer keeps ordinary pages.
  madvise(p, rounded, MADV_HUGEPAGE);
#endif
  return p;
}

}  // namespace skylit
