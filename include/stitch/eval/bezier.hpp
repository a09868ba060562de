// Bicubic Bézier evaluation as a plain polynomial.
#pragma once

#include <algorithm>

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

/// The point of a patch nearest to `point`, sought from (u, v) by Gauss-Newton steps in the unit
/// square: `at(u, v)` gives the patch's point with its derivatives in (u, v). The distance to the
/// point found bounds the distance from `point` to the patch from above; where the patch is
/// regular near (u, v), three steps reach round-off from a start a fraction of a patch away.
template <class At>
SurfacePoint nearest_point(const At& at, const Vec3& point, double u, double v) {
  constexpr int kSteps = 3;
  SurfacePoint best = at(u, v);
  double distance = (point - best.position).norm();
  for (int step = 0; step < kSteps && distance > 0; ++step) {
    const Vec3 &du = best.du, &dv = best.dv, r = point - best.position;
    const double a = du.dot(du), b = du.dot(dv), c = dv.dot(dv), det = a * c - b * b;
    if (!(det > 1e-12 * a * c)) break;  // no tangent plane to step in
    const double step_u = (c * du.dot(r) - b * dv.dot(r)) / det;
    const double step_v = (a * dv.dot(r) - b * du.dot(r)) / det;
    // What is left along the tangent plane: below 5% of the distance, a step would shorten
    // it by less than 0.13%.
    if ((step_u * du + step_v * dv).norm() <= 0.05 * distance) break;
    u = std::clamp(u + step_u, 0.0, 1.0);
    v = std::clamp(v + step_v, 0.0, 1.0);
    const SurfacePoint next = at(u, v);
    const double next_distance = (point - next.position).norm();
    if (!(next_distance < distance)) break;
    best = next;
    distance = next_distance;
  }
  return best;
}

}  // namespace stitch
