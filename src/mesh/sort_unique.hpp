// Private helper of the core: a vector of handles made sorted and free of repeats (the element
// sets of incremental updates and local checks).
#pragma once

#include <algorithm>
#include <vector>

namespace stitch::detail {

template <class T>
void sort_unique(std::vector<T>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

}  // namespace stitch::detail
