#include "support/fresh_storage.hpp"

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace stitch::detail {

bool prefer_huge_pages(const void* begin, std::size_t bytes) noexcept {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  if (begin == nullptr || bytes < 2 * kHuge) return false;
  const auto first = reinterpret_cast<std::uintptr_t>(begin);
  const std::uintptr_t from = (first + kHuge - 1) & ~(kHuge - 1);
  const std::uintptr_t to = (first + bytes) & ~(kHuge - 1);
  if (to <= from) return false;
  // NOLINTNEXTLINE(performance-no-int-to-ptr): madvise takes the page range as a pointer
  return madvise(reinterpret_cast<void*>(from), to - from, MADV_HUGEPAGE) == 0;
#else
  (void)begin;
  (void)bytes;
  return false;
#endif
}

}  // namespace stitch::detail
