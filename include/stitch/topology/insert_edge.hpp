// Insert edge and delete edge: the two operators every other edit is built from (TopMod's
// doubly linked face list, method.md section 7). Each either applies completely, leaving a valid
// closed oriented 2-manifold, or throws TopologyError saying why and leaves the mesh untouched.
//
// Numbering (docs/editing.md): untouched elements keep their numbers; a new edge or face takes the
// next number (its index = the old capacity); a removed one leaves a gap (marked deleted).
#pragma once

#include "stitch/mesh/halfedge_mesh.hpp"
#include "stitch/topology/verdict.hpp"

namespace stitch {

struct InsertEdgeResult {
  Edge edge;           ///< the new edge; its half-edge 2e runs from corner a's vertex to b's
  bool split = false;  ///< true: a and b were on one face, which split in two
  Face face;           ///< split: the part keeping the old number; merge: the merged face
  Face other;          ///< split: the new face; merge: the face that was removed
};

/// Inserts an edge from corner a's vertex to corner b's vertex across their faces.
/// Same face: the face splits. The part whose loop holds the face's start half-edge (its first
/// corner as read from the file) keeps the face's number and the other part is a new face.
/// Different faces: they merge into one face whose loop runs along the new edge twice; it keeps
/// the smaller of the two numbers and the other is removed. Merging faces of different
/// components joins them; of one component, adds a handle (genus + 1).
/// Refused: a == b, both corners at the same vertex (the edge would be a loop), or a corner in a
/// hole (the new edge would have the hole on both sides), or a boundary edge already joining the
/// two vertices (a file could not tell the two apart). The new edge is smooth (sharpness 0).
InsertEdgeResult insert_edge(HalfedgeMesh& mesh, Corner a, Corner b);
/// Whether insert_edge(mesh, a, b) applies, without changing anything (constant time).
Verdict can_insert_edge(const HalfedgeMesh& mesh, Corner a, Corner b);

struct DeleteEdgeResult {
  bool split = false;  ///< true: both sides were one face, which split in two
  Face face;   ///< merge: the surviving face (smaller number); split: the part keeping the number
  Face other;  ///< merge: the removed face; split: the new face
};

/// Deletes edge e, the exact inverse of insert_edge. Two different faces merge (the smaller
/// number survives). A face that runs along e twice splits: the part holding the face's start
/// half-edge keeps its number, the other part becomes a new face; this lowers the genus or
/// separates a component. Refused when an end vertex has valence 2 (it would be left with one
/// edge), or when e lies on the boundary (a hole on one side: the face on the other side would
/// merge into the hole; open_face says that).
DeleteEdgeResult delete_edge(HalfedgeMesh& mesh, Edge e);
/// Whether delete_edge(mesh, e) applies, without changing anything (constant time).
Verdict can_delete_edge(const HalfedgeMesh& mesh, Edge e);

}  // namespace stitch
