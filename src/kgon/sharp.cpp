#include "kgon/sharp.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>

#include "stitch/mesh/polygon.hpp"

namespace stitch {

namespace {

/// Whether a crease or corner tag counts as infinitely sharp. An element without a tag
/// (sharpness 0) never does, whatever sharp_from is: with sharp_from = 0 every untagged edge
/// would otherwise be a crease, on meshes the K-gon set keeps no sharp-curve arrays for.
bool sharp_tag(double sharpness, const KgonOptions& options) {
  return sharpness > 0 && sharpness >= std::min(options.sharp_from, infinitely_sharp);
}

}  // namespace

bool is_sharp(const HalfedgeMesh& m, Edge e, const KgonOptions& options) {
  return m.is_boundary(e) || sharp_tag(m.sharpness(e), options);
}

VertexKind vertex_kind(const HalfedgeMesh& m, Vertex v, const KgonOptions& options) {
  int sharp = 0, holes = 0, corners = 0;
  for (Halfedge h : m.vertex_fan(v)) {
    sharp += is_sharp(m, HalfedgeMesh::edge(h), options);
    (m.is_hole(h) ? holes : corners) += 1;
  }
  if (sharp_tag(m.sharpness(v), options) || sharp >= 3) return VertexKind::corner;
  if (holes > 0 && corners == 1 && options.boundary == BoundaryInterpolation::edge_and_corner)
    return VertexKind::corner;
  if (sharp == 2) return VertexKind::crease;
  return sharp == 1 ? VertexKind::dart : VertexKind::smooth;
}

namespace detail {

namespace {

// The sharp curve is the curve version of the construction: two Chaikin steps of the polygon of
// sharp edges, whose points and midpoints are its Bézier points. At a vertex it only reads the
// vertex and its two neighbours along sharp edges (at a corner, the vertex alone), so surfaces
// that share a boundary polygon share the boundary curve.

/// The other end of the sharp edge of h.
Vec3 far_end(const HalfedgeMesh& m, Halfedge h) {
  return m.position(m.target(h));
}

/// Chaikin's corner point of v towards the far end of h: where the ghost points reflect.
Vec3 curve_corner_point(const HalfedgeMesh& m, Halfedge h) {
  return 0.75 * m.position(m.origin(h)) + 0.25 * far_end(m, h);
}

/// The curve's Bézier point next to the edge midpoint, on the half at origin(h).
Vec3 curve_edge_point(const HalfedgeMesh& m, Halfedge h) {
  return 0.625 * m.position(m.origin(h)) + 0.375 * far_end(m, h);
}

/// Unit normal of the plane through the curve's tangent line (direction t) that fits `points`
/// (relative to the curve point) best, oriented like `orientation`.
Vec3 plane_normal_containing(const Vec3& t, const std::vector<Vec3>& points,
                             const Vec3& orientation) {
  const Vec3 dir = t.normalized();
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vec3& p : points) {
    const Vec3 r = p - p.dot(dir) * dir;
    cov += r * r.transpose();
  }
  // The tangent must lie in the plane: weigh it above every other direction so it is never the
  // eigenvector of the smallest eigenvalue.
  cov += (1.0 + cov.trace()) * 4.0 * dir * dir.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(cov);
  Vec3 n = solver.eigenvectors().col(0);
  n -= n.dot(dir) * dir;
  if (n.norm() < 1e-12 || solver.eigenvalues()(1) <= 1e-300) {
    // The points are on the tangent line (or there are none): take the faces' side.
    n = orientation - orientation.dot(dir) * dir;
  }
  if (n.norm() == 0) n = dir.unitOrthogonal();
  n.normalize();
  if (n.dot(orientation) < 0) n = -n;
  return n;
}

/// The sharp curve leaving a corner along h: straight at first, read from the two ends alone.
void set_corner_curve(const HalfedgeMesh& m, Halfedge h, KgonSet& set) {
  set.sharp_curve[h.idx] = {(7.0 * m.position(m.origin(h)) + far_end(m, h)) / 8.0,
                            curve_edge_point(m, h)};
}

}  // namespace

void build_sector_kgons(const HalfedgeMesh& m, const KgonOptions& options, VertexKind kind,
                        Vertex v, KgonSet& set) {
  const auto fan = m.vertex_fan(v);
  const int n = static_cast<int>(fan.size());
  const Vec3 x = m.position(v);
  std::vector<int> sharp_spokes;
  for (int j = 0; j < n; ++j)
    if (is_sharp(m, HalfedgeMesh::edge(fan[j]), options)) sharp_spokes.push_back(j);

  Vec3 curve_point = x;
  if (kind == VertexKind::crease) {
    const Vec3 p = far_end(m, fan[sharp_spokes[0]]), q = far_end(m, fan[sharp_spokes[1]]);
    curve_point = (p + 6.0 * x + q) / 8.0;
    for (int k = 0; k < 2; ++k) {
      const Halfedge h = fan[sharp_spokes[k]];
      const Vec3 other = far_end(m, fan[sharp_spokes[1 - k]]);
      set.sharp_curve[h.idx] = {curve_point + (far_end(m, h) - other) / 16.0,
                                curve_edge_point(m, h)};
    }
  } else {
    for (int j : sharp_spokes) set_corner_curve(m, fan[j], set);
  }

  Kgon g;
  g.corners = fan;
  g.points.assign(n, curve_point);
  g.centroid = curve_point;
  Vec3 first_normal = Vec3::Zero();
  for (int j = 0; j < n; ++j) set.in_vertex[fan[j].idx] = j;

  // Sectors: the corners from one sharp spoke (counter-clockwise) up to the next. Corner fan[j]
  // lies between spokes j and j + 1.
  const int sectors = static_cast<int>(sharp_spokes.size());
  for (int s = 0; s < sectors; ++s) {
    const int first = sharp_spokes[s];
    const int last_spoke = sharp_spokes[(s + 1) % sectors];
    std::vector<int> members;
    for (int j = first; j != last_spoke || members.empty(); j = (j + 1) % n) {
      members.push_back(j);
      if ((j + 1) % n == last_spoke) break;
    }
    if (m.is_hole(fan[members[0]])) continue;  // the outside of a boundary
    const int count = static_cast<int>(members.size());
    // The sector's corner points, closed by ghosts: each end corner point reflected through the
    // curve's corner point of the sharp edge beside it (and, at a corner, one more ghost across
    // the vertex). On a regular grid this is the tensor product of the curve rule with the
    // surface rule, so the sector continues the surface as if it were reflected at the curve.
    const Vec3 w_first = set.corner_point[fan[first].idx];
    const Vec3 w_last = set.corner_point[fan[members.back()].idx];
    const Vec3 c_first = curve_corner_point(m, fan[first]);
    const Vec3 c_last = curve_corner_point(m, fan[last_spoke]);
    std::vector<Vec3> polygon;
    for (int j : members) polygon.push_back(set.corner_point[fan[j].idx]);
    polygon.push_back(2.0 * c_last - w_last);
    if (kind == VertexKind::corner)
      polygon.push_back(4.0 * x - 2.0 * (c_first + c_last) + 0.5 * (w_first + w_last));
    polygon.push_back(2.0 * c_first - w_first);
    const int k = static_cast<int>(polygon.size());
    std::vector<Vec3> points = doo_sabin_shrink(polygon);
    points.resize(count);

    Vec3 orientation = Vec3::Zero();
    for (int j : members) orientation += newell_normal(face_points(m, m.face(fan[j])));
    std::vector<Vec3> relative;
    for (const Vec3& p : points) relative.push_back(p - curve_point);
    Vec3 normal;
    const Vec3 d_first = far_end(m, fan[first]) - x, d_last = far_end(m, fan[last_spoke]) - x;
    const Vec3 span = d_first.normalized().cross(d_last.normalized());
    if (kind == VertexKind::corner && span.norm() > 1e-3) {
      // A corner's sector is tangent to both curves leaving it.
      normal = span.normalized();
      if (normal.dot(orientation) < 0) normal = -normal;
    } else {
      normal = plane_normal_containing(d_last - d_first, relative, orientation);
    }
    // As everywhere in the construction, a K-gon with K != 4 is flattened: here into a plane
    // through the curve's point that contains its tangent, which gives G1 there. A sector that
    // wraps around more than that plane can hold (the faces between two sharp edges at a cone's
    // tip) would fold; it keeps its points and the surface has a cone point there, as
    // OpenSubdiv's corners do.
    bool cone = false;
    if (k != 4) {
      std::vector<Vec3> flat = points;
      for (Vec3& p : flat) p -= (p - curve_point).dot(normal) * normal;
      // Every patch's corner must turn counter-clockwise from its first side through its inner
      // point to its second side, by less than half a turn in all.
      const Vec3 start = set.sharp_curve[fan[first].idx][0];
      const Vec3 end = set.sharp_curve[fan[last_spoke].idx][0];
      auto turns = [&](const Vec3& a, const Vec3& b) {
        return (a - curve_point).cross(b - curve_point).dot(normal) > 0;
      };
      for (int i = 0; i < count && !cone; ++i) {
        const Vec3 side0 = i == 0 ? start : 0.5 * (flat[i - 1] + flat[i]);
        const Vec3 side1 = i + 1 == count ? end : 0.5 * (flat[i] + flat[i + 1]);
        cone = !turns(side0, flat[i]) || !turns(flat[i], side1) || !turns(side0, side1);
      }
      if (!cone) points = std::move(flat);
    }
    for (int i = 0; i < count; ++i) {
      g.points[members[i]] = points[i];
      set.vertex_k[fan[members[i]].idx] = k;
      set.cone[fan[members[i]].idx] = cone ? 1 : 0;
    }
    if (first_normal == Vec3::Zero()) first_normal = normal;
  }
  g.normal = first_normal == Vec3::Zero() ? Vec3::UnitZ() : first_normal;
  set.vertex[v.idx] = std::move(g);
}

void set_dart_curve(const HalfedgeMesh& m, const KgonOptions& options, Vertex v, KgonSet& set) {
  for (Halfedge h : m.vertex_fan(v))
    if (is_sharp(m, HalfedgeMesh::edge(h), options))
      // The curve leaves the dart like the smooth surface's edge curve would, so the surface
      // keeps its tangent plane at the dart.
      set.sharp_curve[h.idx] = {
          0.5 * (set.vertex_point(m, h) + set.vertex_point(m, m.rotate_cw(h))),
          curve_edge_point(m, h)};
}

void turn_to_corner_curve(const HalfedgeMesh& m, const KgonOptions& options, Vertex v, Kgon& g,
                          KgonSet& set) {
  for (Halfedge h : m.vertex_fan(v)) {
    if (!is_sharp(m, HalfedgeMesh::edge(h), options)) continue;
    set_corner_curve(m, h, set);
    const Vec3 d = (far_end(m, h) - m.position(v)).normalized();
    Vec3 normal = g.normal - g.normal.dot(d) * d;
    if (normal.norm() < 1e-12) normal = d.unitOrthogonal();  // an edge along the normal
    normal.normalize();
    const Eigen::Matrix3d turn = Eigen::Quaterniond::FromTwoVectors(g.normal, normal).matrix();
    for (Vec3& p : g.points) p = g.centroid + turn * (p - g.centroid);
    g.normal = normal;
    return;
  }
}

Kgon sharp_edge_kgon(const HalfedgeMesh& m, Edge e, const KgonSet& set) {
  // Same order as the smooth edge K-gon: h (at a), next(t) (at a), t (at b), next(h) (at b).
  const Halfedge h = HalfedgeMesh::halfedge(e, 0), t = HalfedgeMesh::twin(h);
  const Vec3 a = m.position(m.origin(h)), b = m.position(m.target(h));
  Kgon g;
  g.corners = {h, m.next(t), t, m.next(h)};
  g.centroid = 0.5 * (a + b);
  g.points.assign(4, g.centroid);
  // Each side's two corner points closed by their reflections through the curve's corner
  // points, shrunk once: the points work out as the mean of the side's Chaikin step and the
  // curve's edge point.
  const Vec3 curve_at_a = 0.625 * a + 0.375 * b, curve_at_b = 0.375 * a + 0.625 * b;
  auto side = [&](Halfedge along, int at_start, int at_end, const Vec3& start, const Vec3& end) {
    if (m.is_hole(along)) return;
    const Vec3 w0 = set.corner_point[along.idx], w1 = set.corner_point[m.next(along).idx];
    g.points[at_start] = 0.5 * (0.75 * w0 + 0.25 * w1 + start);
    g.points[at_end] = 0.5 * (0.75 * w1 + 0.25 * w0 + end);
  };
  side(h, 0, 3, curve_at_a, curve_at_b);
  side(t, 2, 1, curve_at_b, curve_at_a);
  const Vec3 winding = newell_normal(g.points);
  g.normal = winding.norm() > 0 ? winding.normalized() : Vec3::UnitZ();
  return g;
}

}  // namespace detail

}  // namespace stitch
