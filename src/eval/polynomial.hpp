// The pieces of evaluate_polynomial, for evaluators that reuse them across many points (the
// PatchSampler's basis tables): same arithmetic, same bits. Internal.
#pragma once

#include "stitch/eval/bezier.hpp"
#include "stitch/net/control_net.hpp"

namespace stitch::detail {

/// The cubic Bernstein polynomials at t, with their first and second derivatives.
struct CubicBasis {
  double b[4], d[4], dd[4];
};
CubicBasis cubic_basis(double t);

/// Below this |du x dv|^2 a point of the net counts as degenerate (see patch_normal).
double degenerate_threshold(const ControlNet& net);

/// The unit normal at (u, v) from the first derivatives there; where du x dv vanishes (a corner
/// of a 2-gon), the limit along the diagonal towards the patch centre, from the second
/// derivatives (the bases at u and v are computed only then).
Vec3 patch_normal(const ControlNet& net, double u, double v, const Vec3& du, const Vec3& dv,
                  double tiny);

}  // namespace stitch::detail
