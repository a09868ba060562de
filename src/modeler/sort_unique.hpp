// Private helper of the modeler library: a vector of handles made sorted and free of repeats.
#pragma once

#include <algorithm>
#include <vector>

namespace stitch::modeler::detail {

template <class T>
void sort_unique(std::vector<T>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

}  // namespace stitch::modeler::detail
