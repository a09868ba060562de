// K-gons at sharp features: vertices on boundaries and creases, and the two sides of sharp
// edges (method.md, "Boundaries, creases and corners"). Private to the kgon stage.
#pragma once

#include "stitch/kgon/kgon.hpp"

namespace stitch::detail {

/// The vertex K-gon of a crease or corner vertex, one sector at a time, and the sharp curves
/// leaving it. Needs the corner points of the faces around v.
void build_sector_kgons(const HalfedgeMesh& mesh, const KgonOptions& options, VertexKind kind,
                        Vertex v, KgonSet& set);

/// The sharp curve along the sharp edge of a dart, from the full-fan K-gon already in `set`.
void set_dart_curve(const HalfedgeMesh& mesh, const KgonOptions& options, Vertex v, KgonSet& set);

/// The whole-fan K-gon g of a corner with one sharp edge, already through the vertex, turned
/// about it so its plane holds that edge, whose curve is the corner's straight one. That curve
/// reads only the edge's two ends, like every other sharp curve at a corner, so another sheet
/// ending on the same edge (a non-manifold edge split on reading) has the same curve.
void turn_to_corner_curve(const HalfedgeMesh& mesh, const KgonOptions& options, Vertex v, Kgon& g,
                          KgonSet& set);

/// The edge K-gon of a sharp edge: on each side that is not a hole, the K-gon points of that
/// side's two corners; the centroid is the edge midpoint, where the sharp curve passes.
Kgon sharp_edge_kgon(const HalfedgeMesh& mesh, Edge e, const KgonSet& set);

}  // namespace stitch::detail
