// Editing the feature tags: opening a face into a hole, filling a hole, and the sharpness of
// edges (creases) and vertices (corners). Like every operator, each either applies completely,
// leaving a valid mesh, or throws TopologyError saying why and leaves the mesh as it was.
#pragma once

#include <vector>

#include "stitch/mesh/halfedge_mesh.hpp"
#include "stitch/topology/verdict.hpp"

namespace stitch {

struct OpenFaceResult {
  /// The holes the face became: itself, or the hole it merged into (more than one when the
  /// merge split the boundary).
  std::vector<Face> holes;
  std::vector<Face> merged;  ///< holes it merged with, by their old numbers (now removed)
  int removed_edges = 0, removed_vertices = 0;
};

/// Makes face f a hole: the surface gets a boundary along f's loop. Where f shares edges with a
/// hole (or runs along an edge twice), those edges would have a hole on both sides: they are
/// removed, with the edges then left dangling and the vertices left without edges, and f and the
/// hole merge into one (numbered as delete_face numbers its loops: the smallest number among
/// those merged; a further loop, when the merge splits the boundary, a new number). Sharpness
/// tags stay where they are.
/// Refused: f is a hole already; the boundary would pass through a vertex twice (f touches a
/// hole, or itself, at a vertex without sharing the edges there); a resulting hole would have 2
/// sides (a slit a file cannot tell from a closed seam); a new boundary edge would share both
/// vertices with another edge (a file could not tell them apart); no surface would remain in
/// the mesh or in f's component.
OpenFaceResult open_face(HalfedgeMesh& mesh, Face f);
/// Whether open_face(mesh, f) applies, without changing anything: f's neighbourhood when f
/// shares no edge with a hole, else the work on a copy of the mesh (as open_face itself does).
Verdict can_open_face(const HalfedgeMesh& mesh, Face f);

/// Makes hole f a face again (it will make patches). Refused when f is not a hole.
void fill_hole(HalfedgeMesh& mesh, Face f);
Verdict can_fill_hole(const HalfedgeMesh& mesh, Face f);

/// Sets edge e's sharpness (0 smooth, >= infinitely_sharp a crease; in between semi-sharp, as in
/// OpenSubdiv). Refused for a sharpness that is negative or not finite.
void set_crease(HalfedgeMesh& mesh, Edge e, double sharpness);
Verdict can_set_crease(const HalfedgeMesh& mesh, Edge e, double sharpness);

/// Sets vertex v's sharpness (a corner). Refused as set_crease.
void set_corner(HalfedgeMesh& mesh, Vertex v, double sharpness);
Verdict can_set_corner(const HalfedgeMesh& mesh, Vertex v, double sharpness);

}  // namespace stitch
