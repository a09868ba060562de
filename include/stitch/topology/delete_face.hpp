// Deleting a face by merging it into its neighbours.
#pragma once

#include "stitch/mesh/halfedge_mesh.hpp"
#include "stitch/topology/verdict.hpp"

namespace stitch {

/// Deletes every edge of f's loop, then every edge left dangling (an end vertex with no other
/// edge) until none is, then the vertices left without edges: f and the faces around it merge.
/// Numbering: each resulting loop that changed takes the smallest free number among the faces it
/// came from (loops ordered by the smallest face number they came from), any further loop a new
/// number; the numbers left over are removed. Removed vertices and edges leave gaps.
/// Refused when nothing would remain (a mesh made of f and faces merged away entirely).
void delete_face(HalfedgeMesh& mesh, Face f);
/// Whether delete_face(mesh, f) applies, without changing anything (the same work on a copy of
/// the mesh that delete_face does).
Verdict can_delete_face(const HalfedgeMesh& mesh, Face f);

}  // namespace stitch
