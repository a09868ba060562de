// Bicubic Bézier evaluation as a plain polynomial.
#pragma once

#include "stitch/net/control_net.hpp"

namespace stitch {

/// A point of the limit surface with its analytic derivatives and unit normal.
struct SurfacePoint {
  Vec3 position = Vec3::Zero();
  Vec3 du = Vec3::Zero(), dv = Vec3::Zero();  ///< in the patch's own (u, v)
  Vec3 normal = Vec3::UnitZ();                ///< unit, du x dv direction
  int level = 0;  ///< hierarchy level of the sub-patch that produced the point
};

/// Position, first derivatives and normal of the bicubic polynomial of `net` at (u, v).
/// Where du x dv vanishes (a degenerate corner) the normal is taken from the second-order
/// terms, and failing those from the net's corner quad, so it is always finite.
SurfacePoint evaluate_polynomial(const ControlNet& net, double u, double v);

}  // namespace stitch
