// An allocator for large buffers, in 2 MiB pages.
//
// A frame's buffers are new memory each frame (the primary hits of a 1280 × 720 image
// are 110 MB, the sky-light cache's points tens of MB, the films 11 MB each), and
// filling one faults in each of its pages. In 4 KiB pages that took 410–470 ms for
// 110 MB on the benchmark host (a virtual machine, where a page fault is slow), in
// 2 MiB pages 12–23 ms; with these buffers in 2 MiB pages Fig. 7's frame took 22 % less
// time, Fig. 8a's 18 %, Fig. 10a's 12 % (BENCHMARKS.md). Debian's kernels give
// transparent huge pages only to memory that asks for them (`madvise`), so these
// buffers ask. Where the kernel will not, they are ordinary pages.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <vector>

namespace skylit {

// `bytes` of memory aligned to `alignment` (a power of two), in 2 MiB pages where it is
// at least one such page; throws std::bad_alloc. Freed by std::free.
void* allocate_in_huge_pages(size_t bytes, size_t alignment);

// Asks for 2 MiB pages for the whole 2 MiB pages within [p, p + bytes), memory not yet
// written (a buffer allocated elsewhere, e.g. a std::string's after `reserve`).
void advise_huge_pages(void* p, size_t bytes);

template <typename T>
struct HugePageAllocator {
  using value_type = T;
  HugePageAllocator() = default;
  template <typename U>
  explicit HugePageAllocator(const HugePageAllocator<U>&) noexcept {}
  T* allocate(size_t n) { return static_cast<T*>(allocate_in_huge_pages(n * sizeof(T), alignof(T))); }
  void deallocate(T* p, size_t) noexcept { std::free(p); }
  friend bool operator==(const HugePageAllocator&, const HugePageAllocator&) = default;
};

// A vector whose large buffers lie in 2 MiB pages.
template <typename T>
using HugePageVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace skylit
