// Connecting two faces with a handle (a tube of quads), built from insert_edge and extrude_face.
#pragma once

#include <optional>

#include "stitch/mesh/halfedge_mesh.hpp"
#include "stitch/topology/verdict.hpp"

namespace stitch {

struct ConnectFacesResult {
  /// The k edges of the tube's last ring are first_edge .. first_edge+k-1 (0-based).
  int first_edge = -1;
  int degree = 0;  ///< k
  int twist = 0;   ///< the twist used (chosen by least_twist when none was given)
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

/// The twist (0..k-1) whose joined corners are closest: the least sum of squared distances
/// between f_i and g_{(twist - i) mod k}. That sum is the same up to a constant as the sum over
/// the corners' positions relative to their faces' centroids, so it picks the correspondence in
/// which the two faces' shapes line up best, whatever the distance between them: corners
/// straight across for faces facing each other or away from each other (no twist of the tube),
/// and the nearest corners for faces at an angle. Twists that would join two corners at one
/// vertex are skipped; ties go to the smaller twist. Throws TopologyError for faces of different
/// degree or when every twist joins some corner to itself.
int least_twist(const HalfedgeMesh& mesh, Face f, Face g);

/// A handle after TopMod's "create handle": `segments` rings of quads along a curved path.
struct HandleOptions {
  std::optional<int> twist;  ///< none: least_twist
  int segments = 1;          ///< rings of quads along the tube (1: connect_faces's tube)
  /// The middle ring's size against the faces (the rings between shrink along 4t(1-t) from the
  /// ends), so that a tube through a solid stays off the faces around its ends.
  double waist = 0.5;
  bool operator==(const HandleOptions&) const = default;
};

/// connect_faces with segments - 1 rings of new vertices between the faces. The path is the
/// cubic Hermite curve between the faces' centroids whose end tangents are the faces' normals
/// (their length the distance between the centroids), each turned to point to the other face's
/// side: a tube between faces facing away from each other runs through the solid, between faces
/// facing each other across the gap. Ring j (t = j / segments) holds, for each pair of joined
/// corners, the blend (1 - t) a + t b of their positions about their face's centroid, each turned
/// with the path's tangent (the least rotation from its end's tangent), scaled by
/// 1 - (1 - waist) 4t(1-t) and placed on the path. Built as segments - 1 extrusions of f and a
/// connect_faces of the last one with g: f's number is the last ring's, the vertices and side
/// faces are numbered as extrude_face numbers them, ring by ring. Refused as connect_faces is,
/// and when segments < 1 or waist is not positive and finite; nothing changes then.
ConnectFacesResult connect_faces(HalfedgeMesh& mesh, Face f, Face g, const HandleOptions& options);
/// Whether connect_faces(mesh, f, g, options) applies, without changing anything.
Verdict can_connect_faces(const HalfedgeMesh& mesh, Face f, Face g, const HandleOptions& options);

}  // namespace stitch
