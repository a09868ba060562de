// Small geometric helpers on polygons given as point loops.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch {

/// Mean of the points.
inline Vec3 centroid(const std::vector<Vec3>& pts) {
  Vec3 c = Vec3::Zero();
  for (const Vec3& p : pts) c += p;
  return c / static_cast<double>(pts.size());
}

/// Newell's normal: twice the area vector, oriented by the loop's winding, meaningful for
/// non-planar loops too. Not normalized (zero for a degenerate loop).
inline Vec3 newell_normal(const std::vector<Vec3>& pts) {
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

}  // namespace stitch
