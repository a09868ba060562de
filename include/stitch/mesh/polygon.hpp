// Small geometric helpers on polygons given as point loops.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <span>
#include <vector>

#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch {

/// Mean of the points.
inline Vec3 centroid(std::span<const Vec3> pts) {
  Vec3 c = Vec3::Zero();
  for (const Vec3& p : pts) c += p;
  return c / static_cast<double>(pts.size());
}

/// Newell's normal: twice the area vector, oriented by the loop's winding, meaningful for
/// non-planar loops too. Not normalized (zero for a degenerate loop).
inline Vec3 newell_normal(std::span<const Vec3> pts) {
  Vec3 n = Vec3::Zero();
  const size_t k = pts.size();
  for (size_t i = 0; i < k; ++i) n += pts[i].cross(pts[(i + 1) % k]);
  return n;
}

/// The positions of the corners of face f, in loop order.
inline std::vector<Vec3> face_points(const HalfedgeMesh& mesh, Face f) {
  std::vector<Vec3> pts;
  for (Halfedge h : mesh.face_loop(f)) pts.push_back(mesh.position(mesh.origin(h)));
  return pts;
}

/// The two triangles of a quad (corners a, b, c, d in loop order, counter-clockwise), split along
/// its shorter diagonal (a-c on a tie), in the quad's orientation: {a, b, c}, {a, c, d} or
/// {a, b, d}, {b, c, d}. Every place that turns the tessellation's quads into triangles (checks,
/// STL, glTF, the renderer) splits them this way, so a check sees the triangles a file holds.
/// Why the shorter one: next to an extraordinary point of high valence (the face of a tube, 2n + 2
/// corners on an n-sided prism) a patch's grid cells are thin rhombi, and the long diagonal
/// leaves two slivers whose normals turn over where the surface bends across them (docs/method.md,
/// "Tubes that still fold"); on a flat grid of squares the rule keeps a-c.
template <class Index>
std::array<std::array<Index, 3>, 2> quad_triangles(const std::array<Index, 4>& q, const Vec3& a,
                                                   const Vec3& b, const Vec3& c, const Vec3& d) {
  if ((c - a).squaredNorm() <= (d - b).squaredNorm())
    return {{{q[0], q[1], q[2]}, {q[0], q[2], q[3]}}};
  return {{{q[0], q[1], q[3]}, {q[1], q[2], q[3]}}};
}

/// The same for a quad of indices into `positions` (anything indexed by them, e.g. a
/// std::vector<Vec3>).
template <class Index, class Positions>
std::array<std::array<Index, 3>, 2> quad_triangles(const std::array<Index, 4>& q,
                                                   const Positions& positions) {
  return quad_triangles(q, positions[q[0]], positions[q[1]], positions[q[2]], positions[q[3]]);
}

}  // namespace stitch
