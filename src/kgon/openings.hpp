// K-gons of faces whose loop runs around two openings (private to the kgon stage).
//
// "Insert edge" between two faces merges them into one face whose loop runs around the first
// face's boundary, along the new edge (the bridge), around the second face's boundary and back
// along the bridge. The smooth surface over such a face is a tube joining the two openings
// (a hole through the solid, or a handle between two solids). Section 2's construction puts
// the face's K-gon at the centroid of its loop, which lies inside the tube, so the surface is
// pinched shut there. The "openings" construction instead
//  - takes each corner point from the Doo-Sabin rule over its own opening's rim (the bridge
//    vertex's point split in two along the rim), so the rims keep the shape they had before
//    the merge (on a twisted tube whose rims have more than six corners, those on the side
//    the bridge leans over slid away from it), and
//  - puts the K-gon on the tube's wall opposite the bridge, halfway between the openings, in
//    the wall's tangent plane, as a regular K-gon whose corners of each opening face that
//    opening (on a twisted tube, turned along the bridge's helix and cut across to the tube's
//    radius: affinely regular).
#pragma once

#include <optional>
#include <vector>

#include "stitch/kgon/kgon.hpp"
#include "stitch/kgon/kgon_topology.hpp"  // TwoOpenings

namespace stitch::detail {

/// The two openings of f, or nothing unless f's loop runs along exactly one edge twice and the
/// two parts on either side of it are separate simple loops (they share no vertex), or along two
/// edges twice (two faces that shared an edge, merged by an edge between them): then the bridge
/// is the edge whose two rims are planar, and the rims share the other edge's two vertices.
std::optional<TwoOpenings> find_two_openings(const HalfedgeMesh& mesh, Face f);

/// An opening's rim: its vertices' positions, the bridge vertex once (it begins and ends the
/// rim's corners).
std::vector<Vec3> rim_points(const HalfedgeMesh& mesh, const std::vector<Corner>& corners);

/// Doo-Sabin corner points of each opening over that opening's own rim, the bridge vertex's
/// point split in two along the rim for its two corners (stored by corner).
void set_opening_corner_points(const HalfedgeMesh& mesh, const TwoOpenings& openings,
                               std::vector<Vec3>& corner_point);

/// On a twisted cylinder whose rims have more than six corners, slides the corner points on each
/// rim's acute side (where the bridge's helix leans over the rim) away from the bridge along the
/// rim (docs/method.md, twisted tubes, item 7). Nothing for any other tube.
void slide_acute_sides(const HalfedgeMesh& mesh, const TwoOpenings& openings,
                       std::vector<Vec3>& corner_point);

/// The face K-gon placed on the tube wall (corners in face-loop order starting at
/// halfedge(f)), or nothing when the two openings give no usable tube direction.
std::optional<Kgon> place_tube_kgon(const HalfedgeMesh& mesh, Face f, const TwoOpenings& openings,
                                    const std::vector<Vec3>& corner_point);

/// The face K-gon of two faces that shared an edge (the rims share its two vertices) when the
/// bridge starts at an end of that edge and turns around the bent tube: the bent tube's face
/// K-gon (as for faces apart). Nothing otherwise. Used only where section 2's K-gon over the
/// rims' own corner points winds back on itself (docs/method.md, "Bent tunnels").
std::optional<Kgon> place_pinched_tube_kgon(const HalfedgeMesh& mesh, Face f,
                                            const TwoOpenings& openings,
                                            const std::vector<Vec3>& corner_point);

/// The K-gon of the bridge edge of such a face when the tube is twisted (the bridge joins
/// corners at different angles around the tube): a quad on the tube wall halfway along the
/// helix the bridge stands for, so that the surface runs around the wall instead of along the
/// chord, which cuts through the tube. Nothing for an untwisted tube (section 2's K-gon is
/// kept there) or no usable tube. `corners` in the edge K-gon's order.
std::optional<Kgon> place_bridge_kgon(const HalfedgeMesh& mesh, Face f, const TwoOpenings& openings,
                                      const std::vector<Corner>& corners,
                                      const std::vector<Vec3>& corner_point);

/// The corners of edge e's K-gon in its order: h = halfedge(e, 0) (left of e, at its first
/// end), next(twin h), twin h, next(h).
std::vector<Corner> edge_kgon_corners(const HalfedgeMesh& mesh, Edge e);

}  // namespace stitch::detail
