// check_surface over triangles held in any contiguous storage: the local check builds its
// triangles in scratch storage (support/scratch.hpp), not in a TriangleSoup. Internal.
#pragma once

#include <array>
#include <span>

#include "stitch/analysis/surface_check.hpp"

namespace stitch::detail {

/// check_surface(soup, focus, options) for the soup of these positions and triangles; `focus`
/// empty for the whole surface, else one flag per triangle.
SurfaceCheckReport check_triangles(std::span<const Vec3> positions,
                                   std::span<const std::array<int, 3>> triangles,
                                   std::span<const char> focus, const SurfaceCheckOptions& options);

}  // namespace stitch::detail
