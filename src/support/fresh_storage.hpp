// Storage for the large arrays a pass writes from end to end: control nets, tessellated
// samples, quads. On this project's 2-core VM the first touch of a fresh 4 kB page costs about
// 20 microseconds of CPU, so faulting in the 1.6 GB of a 100k-face tessellation at resolution 8
// page by page took several times as long as evaluating it. Backed by transparent huge pages,
// the same memory takes one fault per 2 MB (docs/performance.md, "Fresh memory in huge pages").
#pragma once

#include <cstddef>
#include <vector>

namespace stitch::detail {

/// Asks the kernel to back the 2 MB-aligned pages inside [begin, begin + bytes) with transparent
/// huge pages when they are first touched (Linux's madvise(MADV_HUGEPAGE)). Regions under 4 MB
/// are left alone (they would hold at most one whole huge page). Returns whether the advice was
/// given and taken; false on other systems, where THP is off, and for small regions. Only
/// advice: the memory behaves the same either way.
bool prefer_huge_pages(const void* begin, std::size_t bytes) noexcept;

/// Room for n elements in v for a pass that overwrites all of them. Storage that is large enough
/// is kept (no allocation, no fresh pages to fault in: tessellating again into the same arrays).
/// Storage that is too small is dropped first, so that growing copies nothing that is about to
/// be overwritten, and the new storage is advised into huge pages before anything touches it.
template <class T>
void reserve_for_overwrite(std::vector<T>& v, std::size_t n) {
  if (v.capacity() < n) {
    std::vector<T>().swap(v);
    v.reserve(n);
    prefer_huge_pages(v.data(), n * sizeof(T));
  }
}

/// v sized to n elements, in storage as reserve_for_overwrite gives it.
template <class T>
void size_for_overwrite(std::vector<T>& v, std::size_t n) {
  reserve_for_overwrite(v, n);
  v.resize(n);
}

/// v set to n copies of value, in storage as reserve_for_overwrite gives it.
template <class T>
void assign_for_overwrite(std::vector<T>& v, std::size_t n, const T& value) {
  reserve_for_overwrite(v, n);
  v.assign(n, value);
}

}  // namespace stitch::detail
