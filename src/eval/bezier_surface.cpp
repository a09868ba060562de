#include "stitch/eval/bezier_surface.hpp"

#include "eval/descent.hpp"

namespace stitch {

SurfacePoint evaluate_patch(const ControlNet& root, double u, double v, BezierRule rule,
                            int max_level) {
  if (rule == BezierRule::asc || root.regular()) return evaluate_polynomial(root, u, v);
  const Vec3 origin = root.p[0];
  ControlNet relative = root;
  for (Vec3& p : relative.p) p -= origin;
  return evaluate_relative(relative, origin, u, v, max_level);
}

SurfacePoint evaluate_relative(const ControlNet& relative, const Vec3& origin, double u, double v,
                               int max_level) {
  // Two buffers: the net being split lives in the one not being written.
  std::array<std::array<ControlNet, 4>, 2> children;
  int latest = 0;
  return detail::descend(
      relative, origin, u, v, max_level, [&](const ControlNet& net, std::uint64_t) -> const auto& {
        latest ^= 1;
        children[latest] = split(net, SplitRule::modified);
        return children[latest];
      });
}

BezierSurface build_bezier_surface(const HalfedgeMesh& mesh, const KgonOptions& options) {
  BezierSurface s;
  build_bezier_surface(mesh, options, s);
  return s;
}

void build_bezier_surface(const HalfedgeMesh& mesh, const KgonOptions& options,
                          BezierSurface& into) {
  build_kgons(mesh, options, into.kgons);
  build_control_nets(mesh, into.kgons, into.nets);
  into.corners = mesh.patch_corners();
}

}  // namespace stitch
