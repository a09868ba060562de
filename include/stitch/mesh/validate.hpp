// Structural checks and topological counts of a half-edge mesh.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch {

/// Every structural problem found (empty when the mesh is a valid oriented 2-manifold in the
/// sense of this library: loops close, twins pair, each vertex has one fan, no live element
/// refers to a deleted one, faces have degree >= 2, vertices valence >= 2; holes do not share
/// an edge or a vertex with another hole; sharpness tags are finite and >= 0).
std::vector<std::string> find_problems(const HalfedgeMesh& mesh);

/// Throws stitch::Error with the first problems when find_problems() finds any.
void validate(const HalfedgeMesh& mesh);

struct TopologyStats {
  int vertices = 0, edges = 0, components = 0;
  int faces = 0;            ///< faces of the surface (holes not counted)
  int boundary_loops = 0;   ///< hole faces
  int crease_edges = 0;     ///< edges with a sharpness tag (boundary edges not counted)
  int corner_vertices = 0;  ///< vertices with a sharpness tag
  int euler = 0;            ///< V - E + F of the surface with its boundary
  /// Total genus: sum over components of (2 - chi_i - boundary loops_i) / 2.
  int genus = 0;
  std::map<int, int> valence_histogram;  ///< valence -> count
  std::map<int, int> degree_histogram;   ///< face degree -> count
  int extraordinary_vertices = 0;        ///< valence != 4
  int extraordinary_faces = 0;           ///< degree != 4
};

TopologyStats topology_stats(const HalfedgeMesh& mesh);

/// Component id per vertex (index by Vertex::idx; -1 for deleted), and the count.
std::vector<int> connected_components(const HalfedgeMesh& mesh, int* count = nullptr);

}  // namespace stitch
