// Extruding a face.
#pragma once

#include "stitch/mesh/halfedge_mesh.hpp"
#include "stitch/topology/verdict.hpp"

namespace stitch {

struct ExtrudeResult {
  int first_vertex = -1;  ///< the k new vertices are first_vertex .. first_vertex+k-1 (0-based)
  int first_face = -1;    ///< the k new side faces are first_face .. first_face+k-1 (0-based)
  int degree = 0;         ///< k
};

/// Extrudes face f by `distance` along its (Newell) normal: f moves to the top, with one new
/// vertex per corner (numbered in f's loop order from its first corner), and a quad side face
/// per edge of f (numbered in the same order: side i stands on the edge from corner i to corner
/// i+1). The top is scaled by `scale` about the face's centroid (a negative distance with a
/// scale below 1 makes a dent, e.g. the ends of a tube for connect_faces).
/// V + k, E + 2k, F + k; Euler characteristic, genus and components unchanged.
/// Tags: the top's edges and corners copy the sharpness of the edges and vertices under them,
/// which keep theirs; the rising edges and the side faces are smooth. A hole extrudes too: it
/// stays the top, so the boundary moves out by a ring of quads (its normal points away from the
/// surface, as the missing face's would).
/// Refused: a non-finite distance, a scale that is not positive and finite, or a face without a
/// normal (zero area, e.g. a 2-sided face).
ExtrudeResult extrude_face(HalfedgeMesh& mesh, Face f, double distance, double scale = 1.0);
/// Whether extrude_face(mesh, f, distance, scale) applies, without changing anything (time in
/// proportion to f's degree squared).
Verdict can_extrude_face(const HalfedgeMesh& mesh, Face f, double distance, double scale = 1.0);

/// The face's unit normal by Newell's method (zero vector for a face of zero area).
Vec3 face_normal(const HalfedgeMesh& mesh, Face f);

}  // namespace stitch
