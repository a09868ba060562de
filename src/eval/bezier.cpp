#include "stitch/eval/bezier.hpp"

#include <algorithm>

#include "eval/polynomial.hpp"

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

Vec3 patch_normal(const ControlNet& net, double u, double v, const Vec3& du, const Vec3& dv,
                  double tiny) {
  Vec3 n = du.cross(dv);
  if (n.squaredNorm() <= tiny) {
    const CubicBasis bu = cubic_basis(u), bv = cubic_basis(v);
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

namespace {

// evaluate_polynomial at a corner of the patch (u and v each 0 or 1), as a tessellation asks for
// every mesh vertex, face centre and edge midpoint once per patch around it. There, of each
// direction's four basis values only one is not zero (index e, 0 or 3), and of its four
// derivatives only two (indices d and d + 1). A sum that starts at +0 and adds an exact zero keeps
// its bits, so these sums, in evaluate_polynomial's order without the zero terms, give the same
// point to the bit (for a finite net) for a fraction of the work.
SurfacePoint evaluate_at_patch_corner(const ControlNet& net, bool u_end, bool v_end) {
  // cubic_basis(0) and cubic_basis(1) give exactly these: b = 1 at index e, d = -3, 3 at d, d + 1.
  constexpr double kB = 1, kD0 = -3, kD1 = 3;
  const int eu = u_end ? 3 : 0, du = u_end ? 2 : 0;
  const int ev = v_end ? 3 : 0, dv = v_end ? 2 : 0;
  const auto row = [&](int a) -> Vec3 { return Vec3::Zero() + kB * net.at(a, ev); };
  const auto row_dv = [&](int a) -> Vec3 {
    return Vec3::Zero() + kD0 * net.at(a, dv) + kD1 * net.at(a, dv + 1);
  };
  SurfacePoint sp;
  sp.position = Vec3::Zero() + kB * row(eu);
  sp.du = Vec3::Zero() + kD0 * row(du) + kD1 * row(du + 1);
  sp.dv = Vec3::Zero() + kB * row_dv(eu);
  return sp;
}

}  // namespace

SurfacePoint evaluate_polynomial(const ControlNet& net, double u, double v) {
  if ((u == 0 || u == 1) && (v == 0 || v == 1)) {
    SurfacePoint sp = evaluate_at_patch_corner(net, u == 1, v == 1);
    sp.normal = detail::patch_normal(net, u, v, sp.du, sp.dv, detail::degenerate_threshold(net));
    return sp;
  }
  const detail::CubicBasis bu = detail::cubic_basis(u), bv = detail::cubic_basis(v);
  SurfacePoint sp;
  for (int a = 0; a < 4; ++a) {
    Vec3 row = Vec3::Zero(), row_dv = Vec3::Zero();  // sums over b for this a
    for (int b = 0; b < 4; ++b) {
      row += bv.b[b] * net.at(a, b);
      row_dv += bv.d[b] * net.at(a, b);
    }
    sp.position += bu.b[a] * row;
    sp.du += bu.d[a] * row;
    sp.dv += bu.b[a] * row_dv;
  }
  sp.normal = detail::patch_normal(net, u, v, sp.du, sp.dv, detail::degenerate_threshold(net));
  return sp;
}

}  // namespace stitch
