#include "stitch/eval/bezier_surface.hpp"

namespace stitch {

SurfacePoint evaluate_patch(const ControlNet& root, double u, double v, BezierRule rule,
                            int max_level) {
  if (rule == BezierRule::asc || root.regular()) return evaluate_polynomial(root, u, v);
  // Deep splits subtract nearly equal points; working relative to the net's first point keeps
  // the round-off proportional to the patch's size rather than to its distance from the origin.
  const Vec3 origin = root.p[0];
  ControlNet net = root;
  for (Vec3& p : net.p) p -= origin;
  int level = 0;
  // A corner of the current net is interpolated exactly by its polynomial (position = corner
  // point, tangent plane = the K-gon plane), so the descent stops there too.
  auto at_corner = [](double x, double y) { return (x == 0 || x == 1) && (y == 0 || y == 1); };
  while (!net.regular() && !at_corner(u, v) && level < max_level) {
    const int qu = u >= 0.5 ? 1 : 0, qv = v >= 0.5 ? 1 : 0;
    net = split(net, SplitRule::modified)[2 * qu + qv];
    u = 2 * u - qu;
    v = 2 * v - qv;
    ++level;
  }
  SurfacePoint sp = evaluate_polynomial(net, u, v);
  const double scale = static_cast<double>(1ull << level);  // d/du of the root = 2^level d/du'
  sp.du *= scale;
  sp.dv *= scale;
  sp.position += origin;
  sp.level = level;
  return sp;
}

BezierSurface build_bezier_surface(const HalfedgeMesh& mesh, const KgonOptions& options) {
  BezierSurface s;
  s.kgons = build_kgons(mesh, options);
  s.nets = build_control_nets(mesh, s.kgons);
  s.corners = mesh.halfedges();
  return s;
}

}  // namespace stitch
