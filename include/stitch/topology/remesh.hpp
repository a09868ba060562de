// Remeshing the whole mesh. Each returns a new mesh numbered afresh (documented per scheme and in
// docs/editing.md); the input is not changed. Numbers below are 0-based indices of the
// garbage-collected input (V vertices, E edges, H = 2E half-edges, F faces).
// dual, vertex_insertion, doo_sabin and catmull_clark_step refuse (TopologyError) a mesh with a
// hole or a sharpness tag: they have no rule here for boundaries and creases, and dropping the tags
// would change the surface without saying so.
#pragma once

#include <vector>

#include "stitch/mesh/halfedge_mesh.hpp"
#include "stitch/topology/verdict.hpp"

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

/// One Catmull-Clark step with OpenSubdiv's rules (Sdc::Scheme<SCHEME_CATMARK> masks, the same
/// weights its Far refiner applies) on any mesh this library holds, including 2-sided faces,
/// several edges between two vertices and faces running along one edge twice.
/// Vertices: the V old vertices (moved) keep their numbers, then one per face (V + f), then one
/// per edge (V + F + e). Faces: one quad per old corner, face by face in loop order from
/// halfedge(f); the quad of corner c runs from c's vertex point to the edge point of edge(c),
/// the face point and the edge point of edge(prev(c)), and starts there (halfedge(quad)).
/// catmull_clark_refinement itself applies the smooth rules everywhere: a hole is refined as a
/// face and sharpness tags are ignored (callers that need tags check them first).
struct CatmullClarkRefinement {
  HalfedgeMesh mesh;
  std::vector<Face> corner_quad;  ///< per half-edge of the input: its quad (invalid if deleted)
};
CatmullClarkRefinement catmull_clark_refinement(const HalfedgeMesh& mesh);

/// catmull_clark_refinement(mesh).mesh; refused for a mesh with holes or sharpness tags.
HalfedgeMesh catmull_clark_step(const HalfedgeMesh& mesh);

/// The four remeshings, as the operation table names them.
enum class Remeshing { doo_sabin, vertex_insertion, catmull_clark, dual };

/// The scheme's operation name ("doo-sabin", ...).
const char* remeshing_name(Remeshing scheme);

/// dual, vertex_insertion, doo_sabin or catmull_clark_step by scheme.
HalfedgeMesh remesh(const HalfedgeMesh& mesh, Remeshing scheme);

/// Whether remesh(mesh, scheme) applies: no holes or tags (and, for the dual, no face running
/// along an edge twice). Time in proportion to the mesh, as the remeshing's own.
Verdict can_remesh(const HalfedgeMesh& mesh, Remeshing scheme);

}  // namespace stitch
