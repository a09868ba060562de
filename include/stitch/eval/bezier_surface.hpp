// The surface of bicubic Bézier patches of a mesh: K-gons, one control net per corner, and
// exact hierarchical evaluation (method.md, section 5).
#pragma once

#include <vector>

#include "stitch/eval/bezier.hpp"
#include "stitch/eval/de_casteljau.hpp"
#include "stitch/kgon/kgon.hpp"
#include "stitch/net/control_net.hpp"

namespace stitch {

enum class BezierRule {
  mdc,  ///< the paper's: extraordinary patches split recursively with the modified rule
  asc,  ///< the baseline (AS&C): every patch evaluated as a plain polynomial
};

/// Exact evaluation of one patch at (u, v) in [0, 1]^2. With mdc, an extraordinary net is split
/// until (u, v) lies in a regular child (at most `max_level` splits; beyond that the child
/// polynomial is used, which differs from the limit by far less than double round-off).
/// At an extraordinary corner itself the result is the K-gon centroid with the K-gon normal.
inline constexpr int kMaxEvaluationLevel = 60;
SurfacePoint evaluate_patch(const ControlNet& net, double u, double v, BezierRule rule,
                            int max_level = kMaxEvaluationLevel);
/// The mdc descent of evaluate_patch from a net already moved by -origin (its root's first
/// point): from a cell of the hierarchy, the splits and bits of evaluate_patch's descent through
/// that cell, without the splits above it. (u, v) are the cell's; derivatives are the cell's
/// scaled by 2^levels split below it, and `max_level` counts from the cell.
SurfacePoint evaluate_relative(const ControlNet& relative, const Vec3& origin, double u, double v,
                               int max_level);

struct BezierSurface {
  KgonSet kgons;
  std::vector<ControlNet> nets;  ///< indexed by corner (half-edge)
  std::vector<Corner> corners;   ///< the live corners, in index order

  [[nodiscard]] SurfacePoint evaluate(Corner c, double u, double v, BezierRule rule) const {
    return evaluate_patch(nets[c.idx], u, v, rule);
  }
};

BezierSurface build_bezier_surface(const HalfedgeMesh& mesh, const KgonOptions& options = {});
/// The same into `into`, keeping the storage of its control nets where it is large enough.
void build_bezier_surface(const HalfedgeMesh& mesh, const KgonOptions& options,
                          BezierSurface& into);

}  // namespace stitch
