// Splitting a bicubic net at u = v = 1/2: the classic de Casteljau rule and the modified rule
// of Zarrinmehr, Akleman and Chen (method.md, section 4).
#pragma once

#include <array>

#include "stitch/net/control_net.hpp"

namespace stitch {

enum class SplitRule {
  classic,   ///< reproduces the polynomial exactly
  modified,  ///< diagonal midpoints at extraordinary corners: C1 along every edge
};

/// The four children, child [2 * qu + qv] covering u in [qu/2, (qu+1)/2], v in [qv/2, (qv+1)/2].
/// Each child keeps only the extraordinary flag of the parent corner it contains.
std::array<ControlNet, 4> split(const ControlNet& net, SplitRule rule);

}  // namespace stitch
