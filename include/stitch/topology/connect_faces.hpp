// Connecting two faces with a handle (a tube of quads), built from insert_edge.
#pragma once

#include "stitch/mesh/halfedge_mesh.hpp"
#include "stitch/topology/verdict.hpp"

namespace stitch {

struct ConnectFacesResult {
  int first_edge = -1;  ///< the k new edges are first_edge .. first_edge+k-1 (0-based)
  int degree = 0;       ///< k
};

/// Removes faces f and g (both of degree k) and joins their loops with a tube of k quads.
/// With corners f_0..f_{k-1} of f and g_0..g_{k-1} of g (each from the face's first corner, in
/// loop order), corner f_i is joined to corner g_{(twist - i) mod k}; twist turns the tube.
/// Faces on one component: genus + 1; on two components: they join. E + k, F + k - 2.
/// Numbering: the first new edge (f_0 - g_twist) merges f and g into the smaller of their
/// numbers (the larger is removed); each further edge i = 1..k-1 splits that face (insert_edge's
/// rule: the part holding its first corner keeps the number, the other gets the next one), so
/// the k quads carry the smaller number and k-1 new ones. Refused: f == g, different degrees, or
/// a pair of corners to be joined at the same vertex (the edge would be a loop).
/// Either face may be a hole: it is removed like a face, so the tube bridges two boundary loops
/// or closes one onto a face. The tube's quads and edges are smooth; the edges of f and g keep
/// their sharpness. Refused too when a tube edge would join the ends of an edge that stays on
/// the boundary (a file could not tell the two apart).
ConnectFacesResult connect_faces(HalfedgeMesh& mesh, Face f, Face g, int twist = 0);
/// Whether connect_faces(mesh, f, g, twist) applies, without changing anything.
Verdict can_connect_faces(const HalfedgeMesh& mesh, Face f, Face g, int twist = 0);

}  // namespace stitch
