// The descent of exact hierarchical evaluation (method.md, section 5), shared by evaluate_patch
// and the PatchSampler, which keeps the splits it made: both give the same bits. Internal.
#pragma once

#include <array>
#include <cstdint>

#include "stitch/eval/bezier.hpp"
#include "stitch/net/control_net.hpp"

namespace stitch::detail {

/// Splits an extraordinary net until (u, v) lies in a regular child (at most max_level times)
/// and evaluates that child. `relative` is the root net minus `origin` (its first point): deep
/// splits subtract nearly equal points, and working relative to the net keeps the round-off
/// proportional to the patch's size rather than to its distance from the origin.
/// split_at(net, path) returns the four children of `net`, the net reached by `path` (1 for the
/// root, path * 4 + child below it; 0 below level 30, where it would not fit); the reference
/// must stay valid for one more call.
template <class SplitAt>
SurfacePoint descend(const ControlNet& relative, const Vec3& origin, double u, double v,
                     int max_level, SplitAt&& split_at) {
  const ControlNet* net = &relative;
  std::uint64_t path = 1;
  int level = 0;
  // A corner of the current net is interpolated exactly by its polynomial (position = corner
  // point, tangent plane = the K-gon plane), so the descent stops there too.
  auto at_corner = [](double x, double y) { return (x == 0 || x == 1) && (y == 0 || y == 1); };
  while (!net->regular() && !at_corner(u, v) && level < max_level) {
    const int qu = u >= 0.5 ? 1 : 0, qv = v >= 0.5 ? 1 : 0;
    net = &split_at(*net, path)[2 * qu + qv];
    path = level < 30 ? path * 4 + static_cast<std::uint64_t>(2 * qu + qv) : 0;
    u = 2 * u - qu;
    v = 2 * v - qv;
    ++level;
  }
  SurfacePoint sp = evaluate_polynomial(*net, u, v);
  const double scale = static_cast<double>(1ull << level);  // d/du of the root = 2^level d/du'
  sp.du *= scale;
  sp.dv *= scale;
  sp.position += origin;
  sp.level = level;
  return sp;
}

}  // namespace stitch::detail
