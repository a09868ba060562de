// Internal to the library and its tests: the whole split net before it is cut into children.
#pragma once

#include <array>

#include "stitch/eval/de_casteljau.hpp"

namespace stitch {

/// The 7x7 net N = S P S^T (classic) or its modified form, whose four overlapping 4x4 blocks
/// are the children `split` returns.
std::array<std::array<Vec3, 7>, 7> split_net(const ControlNet& net, SplitRule rule);

}  // namespace stitch
