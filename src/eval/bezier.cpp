#include "stitch/eval/bezier.hpp"

#include <algorithm>

namespace stitch {

namespace {

struct Basis {
  double b[4], d[4], dd[4];
};

Basis cubic_basis(double t) {
  const double s = 1.0 - t;
  return {{s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t},
          {-3 * s * s, 3 * s * s - 6 * t * s, 6 * t * s - 3 * t * t, 3 * t * t},
          {6 * s, 6 * t - 12 * s, 6 * s - 12 * t, 6 * t}};
}

}  // namespace

SurfacePoint evaluate_polynomial(const ControlNet& net, double u, double v) {
  const Basis bu = cubic_basis(u), bv = cubic_basis(v);
  SurfacePoint sp;
  Vec3 duu = Vec3::Zero(), duv = Vec3::Zero(), dvv = Vec3::Zero();
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      const Vec3& p = net.at(a, b);
      sp.position += bu.b[a] * bv.b[b] * p;
      sp.du += bu.d[a] * bv.b[b] * p;
      sp.dv += bu.b[a] * bv.d[b] * p;
      duu += bu.dd[a] * bv.b[b] * p;
      duv += bu.d[a] * bv.d[b] * p;
      dvv += bu.b[a] * bv.dd[b] * p;
    }
  double scale2 = 0;
  for (const Vec3& p : net.p) scale2 = std::max(scale2, (p - net.p[0]).squaredNorm());
  // Relative threshold: du x dv has the units of an area, so compare with the net's size squared.
  const double tiny = 1e-24 * scale2;
  Vec3 n = sp.du.cross(sp.dv);
  if (n.squaredNorm() <= tiny * scale2) {
    // A degenerate point (a corner of a 2-gon): the normal is the limit along the diagonal
    // towards the patch centre, where du ~ t (duu + duv) and dv ~ t (duv + dvv).
    const double su = u < 0.5 ? 1.0 : -1.0, sv = v < 0.5 ? 1.0 : -1.0;
    n = (su * duu + sv * duv).cross(su * duv + sv * dvv);
  }
  if (n.squaredNorm() <= tiny * scale2)
    n = (net.at(3, 3) - net.at(0, 0)).cross(net.at(0, 3) - net.at(3, 0));
  sp.normal = n.squaredNorm() > 0 ? n.normalized() : Vec3::UnitZ();
  return sp;
}

}  // namespace stitch
