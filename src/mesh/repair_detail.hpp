// What build_mesh needs of repair(): the repaired copy of a soup it may not change, with the
// way back to the soup's elements, and the words for a refusal when repairing is off.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "stitch/mesh/repair.hpp"

namespace stitch::detail {

struct Repaired {
  PolygonSoup soup;
  /// Index in the soup given of each vertex and face of `soup` (a copy: the vertex it copies).
  std::vector<int> vertex_from, face_from;
};

/// The soup repaired, or nothing when it needs no repair (then `report` lists no change).
/// `by_angle`: every edge that several faces each way share is paired by angle, not only those
/// the build's search cannot pair. Throws as repair() does.
std::optional<Repaired> repaired(const PolygonSoup& soup, const RepairOptions& options,
                                 RepairReport& report, bool by_angle = false);

/// Every defect repair() would fix or refuses, counted, one sentence per kind with the first
/// places ("" when there is none): what build_mesh says when it refuses a soup it was told not
/// to repair.
std::string describe_defects(const PolygonSoup& soup, const RepairOptions& options);

}  // namespace stitch::detail
