// The pieces of adaptive tessellation that are worth testing on their own. Internal.
#pragma once

#include <array>
#include <vector>

#include "stitch/net/control_net.hpp"

namespace stitch::detail {

/// Segments the patch of `net` needs along `side` (control_net.hpp's numbering) so that the
/// cubic flattening bound (3/4) max|second difference| / n^2 of the side's row and the next row
/// inwards stays within `tolerance` (absolute), clamped to [1, max_rate].
int side_rate(const ControlNet& net, int side, double tolerance, int max_rate);

/// Triangles (as index pairs into the two chains, {chain, index}: chain 0 outer, 1 inner)
/// joining an outer chain of `outer + 1` points at parameters k / outer to an inner chain of
/// `inner` points at (m + 1) / (inner + 1), both running the same way: a zipper that always
/// advances along the chain whose next point comes first, so no triangle spans far along the
/// strip. Needs outer >= 1 and inner >= 1; gives outer + inner - 1 triangles.
using StripCorner = std::array<int, 2>;
std::vector<std::array<StripCorner, 3>> zip_strip(int outer, int inner);

}  // namespace stitch::detail
