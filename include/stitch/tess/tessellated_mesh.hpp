// The tessellated surface: a quad mesh of limit-surface samples with their analytic normals.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch {

struct TessellatedMesh {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;              ///< unit, per vertex
  std::vector<Eigen::Vector2d> uv;        ///< the sample's (u, v) in its patch
  std::vector<int> patch;                 ///< the corner (half-edge index) whose patch it lies on
  std::vector<int> level;                 ///< hierarchy level of the sub-patch it came from
  std::vector<std::array<int, 4>> quads;  ///< counter-clockwise seen from the normal side

  [[nodiscard]] int num_vertices() const { return static_cast<int>(positions.size()); }
};

/// The first sample whose position or normal is not finite, or -1 when there is none.
int first_non_finite_sample(const TessellatedMesh& mesh);

}  // namespace stitch
