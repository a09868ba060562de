// Private helpers of the topology operators: building a mesh from explicit half-edge arrays and
// the small queries several operators share.
#pragma once

#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "stitch/mesh/halfedge_mesh.hpp"
#include "stitch/topology/verdict.hpp"

namespace stitch::detail {

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

/// The first vertex a face's loop visits twice (a loop that touches itself), or an invalid one.
Vertex vertex_visited_twice(const HalfedgeMesh& mesh, Face f);

/// The live edges joining a and b.
std::vector<Edge> edges_between(const HalfedgeMesh& mesh, Vertex a, Vertex b);

/// Removing a set of edges from the map (delete-face, open-face): what goes and what the kept
/// half-edges link to afterwards.
struct EdgeRemoval {
  std::vector<std::uint8_t> gone;  ///< per edge: removed (with the edges left dangling)
  std::vector<int> next;           ///< per kept half-edge: its successor once the rest are gone
  std::vector<Halfedge> kept;      ///< the live half-edges that stay, in index order
  std::set<int> touched_faces;     ///< faces that lose a half-edge (their loops change)
};

/// Plans removing the edges marked in `gone`: grows it by every edge then left dangling (an end
/// vertex with no other edge) until none is. The mesh is not changed.
EdgeRemoval plan_edge_removal(const HalfedgeMesh& mesh, std::vector<std::uint8_t> gone);

/// Carries out the plan: every changed loop takes the smallest free number among the faces it
/// came from (loops ordered by the smallest face number they came from), further loops new
/// numbers, and numbers left over are removed; then the edges, and the vertices left without
/// edges, are deleted. A loop reusing a number keeps that face's tags (a new face starts smooth,
/// not a hole). Returns the faces of the changed loops. The result is not validated.
std::vector<Face> remove_edges(HalfedgeMesh& mesh, const EdgeRemoval& plan);

/// Why a boundary edge may not share both ends with another edge: the message tail for refusals.
/// A file names an edge by its two vertices, so the reader could not tell which of them is on the
/// boundary, and the mesh would not read back.
inline constexpr const char* kBesideBoundary =
    "a file names edges by their two vertices, so it could not tell which of them is on the "
    "boundary";

/// Refused (named for `op`) when the element is not a live element of the mesh.
Verdict exists(const HalfedgeMesh& mesh, Vertex v, const char* op);
Verdict exists(const HalfedgeMesh& mesh, Face f, const char* op);
Verdict exists(const HalfedgeMesh& mesh, Edge e, const char* op);
Verdict exists(const HalfedgeMesh& mesh, Corner c, const char* op);

}  // namespace stitch::detail
