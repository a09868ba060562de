// Comparing meshes across renumbering: what "the same mesh" means for undo and for the
// insert/delete round trips (docs/editing.md).
#pragma once

#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch {

/// True when a and b have the same live vertices (same numbers, exactly equal positions and
/// sharpness) and their half-edges correspond one to one keeping origin vertex, next, twin, the
/// edge's sharpness and whether the face is a hole, i.e. the same faces as cyclic corner
/// sequences around the same rotation at every vertex, with the same tags. Edge and face
/// numbers, face start corners, vertex start half-edges and deleted elements may differ.
bool same_up_to_renumbering(const HalfedgeMesh& a, const HalfedgeMesh& b);

}  // namespace stitch
