// Working arrays of a pass that runs many times over, as the local check does for every setting
// unfold_tubes tries. On this project's 2-core VM the first touch of a fresh 4 kB page costs
// about 20 microseconds of CPU (fresh_storage.hpp), and glibc gives arrays of a few MB back to
// the kernel when they are freed, so each check faulted its arrays in anew: most of its time
// (docs/performance.md, "Unfolding a tube after an edit"). oneTBB's scalable allocator keeps
// freed large blocks for the next request of their size. Under AddressSanitizer the standard
// allocator stays, so that the sanitizer still sees every access to these arrays.
#pragma once

#include <tbb/scalable_allocator.h>

#include <memory>
#include <vector>

#if defined(__SANITIZE_ADDRESS__)
#define STITCH_SCRATCH_STANDARD 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define STITCH_SCRATCH_STANDARD 1
#endif
#endif

namespace stitch::detail {

#ifdef STITCH_SCRATCH_STANDARD
template <class T>
using ScratchAllocator = std::allocator<T>;
#else
template <class T>
using ScratchAllocator = tbb::scalable_allocator<T>;
#endif

template <class T>
using ScratchVector = std::vector<T, ScratchAllocator<T>>;

}  // namespace stitch::detail
