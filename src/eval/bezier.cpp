#include "stitch/eval/bezier.hpp"

#include <algorithm>

#include "polynomial.hpp"

namespace stitch {

namespace detail {

CubicBasis cubic_basis(double t) {
  const double s = 1.0 - t;
  return {{s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t},
          {-3 * s * s, 3 * s * s - 6 * t * s, 6 * t * s - 3 * t * t, 3 * t * t},
          {6 * s, 6 * t - 12 * s, 6 * s - 12 * t, 6 * t}};
}

double degenerate_threshold(const ControlNet& net) {
  // Relative: du x dv has the units of an area, so compare with the net's size squared (its
  // diagonals bound it well enough for telling "zero" from "not zero").
  const double size2 = std::max((net.at(3, 3) - net.at(0, 0)).squaredNorm(),
                                (net.at(3, 0) - net.at(0, 3)).squaredNorm());
  return 1e-24 * size2 * size2;
}

Vec3 patch_normal(const ControlNet& net, const CubicBasis& bu, const CubicBasis& bv, double u,
                  double v, const Vec3& du, const Vec3& dv, double tiny) {
  Vec3 n = du.cross(dv);
  if (n.squaredNorm() <= tiny) {
    // A degenerate point (a corner of a 2-gon): the normal is the limit along the diagonal
    // towards the patch centre, where du ~ t (duu + duv) and dv ~ t (duv + dvv).
    Vec3 duu = Vec3::Zero(), duv = Vec3::Zero(), dvv = Vec3::Zero();
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        const Vec3& p = net.at(a, b);
        duu += bu.dd[a] * bv.b[b] * p;
        duv += bu.d[a] * bv.d[b] * p;
        dvv += bu.b[a] * bv.dd[b] * p;
      }
    const double su = u < 0.5 ? 1.0 : -1.0, sv = v < 0.5 ? 1.0 : -1.0;
    n = (su * duu + sv * duv).cross(su * duv + sv * dvv);
  }
  if (n.squaredNorm() <= tiny) n = (net.at(3, 3) - net.at(0, 0)).cross(net.at(0, 3) - net.at(3, 0));
  return n.squaredNorm() > 0 ? n.normalized() : Vec3::UnitZ();
}

}  // namespace detail

SurfacePoint evaluate_polynomial(const ControlNet& net, double u, double v) {
  const detail::CubicBasis bu = detail::cubic_basis(u), bv = detail::cubic_basis(v);
  SurfacePoint sp;
  // At a corner of the patch, as a tessellation asks at every mesh vertex, face centre and edge
  // midpoint once per patch, only two of the four basis values and derivatives are not zero in
  // each direction. A sum that starts at +0 and adds an exact zero keeps its value, so leaving
  // those terms out gives the same bits (for a finite net) for a quarter of the work.
  const bool corner = (u == 0 || u == 1) && (v == 0 || v == 1);
  for (int a = 0; a < 4; ++a) {
    if (corner && bu.b[a] == 0 && bu.d[a] == 0) continue;
    Vec3 row = Vec3::Zero(), row_dv = Vec3::Zero();  // sums over b for this a
    for (int b = 0; b < 4; ++b) {
      if (corner && bv.b[b] == 0 && bv.d[b] == 0) continue;
      row += bv.b[b] * net.at(a, b);
      row_dv += bv.d[b] * net.at(a, b);
    }
    sp.position += bu.b[a] * row;
    sp.du += bu.d[a] * row;
    sp.dv += bu.b[a] * row_dv;
  }
  sp.normal =
      detail::patch_normal(net, bu, bv, u, v, sp.du, sp.dv, detail::degenerate_threshold(net));
  return sp;
}

}  // namespace stitch
