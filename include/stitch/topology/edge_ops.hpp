// Subdividing and collapsing one edge.
#pragma once

#include "stitch/mesh/halfedge_mesh.hpp"
#include "stitch/topology/verdict.hpp"

namespace stitch {

struct SubdivideEdgeResult {
  Vertex vertex;  ///< the new valence-2 vertex (next vertex number), at the edge's midpoint
  Edge edge;      ///< the new edge (next edge number): new vertex -> the old edge's second end
};

/// Splits edge e (from origin(2e) to origin(2e+1)) at its midpoint. Edge e keeps the part at its
/// first end; both faces gain one corner. The new edge takes e's sharpness (a crease stays whole)
/// and the new vertex is smooth; on a boundary edge the hole gains the corner too. Never refused
/// on a valid mesh.
SubdivideEdgeResult subdivide_edge(HalfedgeMesh& mesh, Edge e);
/// Whether subdivide_edge(mesh, e) applies: whenever e is a live edge.
Verdict can_subdivide_edge(const HalfedgeMesh& mesh, Edge e);

/// Collapses edge e into vertex `keep` (one of its ends), which moves to the edge's midpoint; the
/// other end and the edge are removed, both faces lose a corner. `keep` takes the larger of the
/// two vertex sharpnesses. Refused when another edge also joins the two ends (it would become a
/// loop; this covers 2-sided faces on e); when both ends touch the boundary but e is not a
/// boundary edge (the boundary would pinch at one vertex); when a hole on e has 3 sides (it
/// would become a 2-sided slit); or when the ends have a common neighbour with one of the two
/// edges to it on the boundary (they would become parallel, which a file cannot tell apart).
void collapse_edge(HalfedgeMesh& mesh, Edge e, Vertex keep);
/// Whether collapse_edge(mesh, e, keep) applies, without changing anything (time in proportion
/// to the valences of e's ends).
Verdict can_collapse_edge(const HalfedgeMesh& mesh, Edge e, Vertex keep);

}  // namespace stitch
