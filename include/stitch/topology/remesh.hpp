// Remeshing the whole mesh. Each returns a new mesh numbered afresh (documented per scheme and in
// docs/editing.md); the input is not changed. Numbers below are 0-based indices of the
// garbage-collected input (V vertices, E edges, H = 2E half-edges, F faces).
#pragma once

#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch {

/// The dual: vertex i at the centroid of face i, face j around vertex j, edge e crossing edge e
/// (half-edge h of the dual runs from face(twin h)'s point to face(h)'s point, inside the face of
/// origin(h)). Refused when a face runs along the same edge twice (the dual edge would be a loop).
HalfedgeMesh dual(const HalfedgeMesh& mesh);

/// Vertex insertion (the quad remesh): a vertex at every face centroid joined to the face's
/// corners, the old edges removed; each old edge becomes a quad. Vertices: the V old ones, then
/// face points V + f; faces: one quad per old edge (face e); edges: one per old corner (edge h
/// joins origin(h) to the point of face(h)).
HalfedgeMesh vertex_insertion(const HalfedgeMesh& mesh);

/// One Doo-Sabin step: a new vertex per corner h (vertex h, at the mean of the corner's vertex,
/// its face's centroid and the midpoints of its two edges in that face); faces: F shrunken faces
/// (face f), then a quad per edge (F + e), then a face per old vertex (F + E + v).
HalfedgeMesh doo_sabin(const HalfedgeMesh& mesh);

/// One Catmull-Clark step through OpenSubdiv (Far::TopologyRefiner, uniform level 1):
/// vertices in OpenSubdiv's order (the V old vertices, moved, keep their numbers; then one per
/// face; then one per edge), faces: the quads of face 0 first, then face 1's, ...
/// Refused on 2-sided faces and on several edges joining the same two vertices, which
/// OpenSubdiv's face-vertex description cannot express.
HalfedgeMesh catmull_clark_step(const HalfedgeMesh& mesh);

}  // namespace stitch
