// Private helpers of the topology operators: building a mesh from explicit half-edge arrays and
// the small queries several operators share.
#pragma once

#include <string>
#include <vector>

#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch::topology_detail {

/// A mesh spelled out as arrays: half-edge 2e and 2e+1 are the two sides of edge e.
struct RawMesh {
  std::vector<Vec3> positions;
  std::vector<int> origin, next, face;  ///< per half-edge
  int num_faces = 0;
};

/// Builds the half-edge mesh (every vertex and face must be used) and validates it; `what` names
/// the operation for the error message if the result is not a valid mesh.
HalfedgeMesh build_raw(const RawMesh& raw, const std::string& what);

/// The mesh's live elements renumbered densely (a garbage-collected copy).
HalfedgeMesh compacted(const HalfedgeMesh& mesh);

/// Mean of the corner positions of the face.
Vec3 face_centroid(const HalfedgeMesh& mesh, Face f);

/// The live edges joining a and b.
std::vector<Edge> edges_between(const HalfedgeMesh& mesh, Vertex a, Vertex b);

void check_vertex(const HalfedgeMesh& mesh, Vertex v, const char* op);
void check_face(const HalfedgeMesh& mesh, Face f, const char* op);
void check_edge(const HalfedgeMesh& mesh, Edge e, const char* op);
void check_corner(const HalfedgeMesh& mesh, Corner c, const char* op);

}  // namespace stitch::topology_detail
