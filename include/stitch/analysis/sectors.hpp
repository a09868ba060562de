// How the patches around a vertex group across the sharp edges (boundary edges and creases)
// there: the surface is only C0 across a sharp edge, so tangent-plane agreement at a vertex is a
// property of each sector, not of the whole fan. Shared by the analysis and the overlays.
#pragma once

#include <cstdint>
#include <vector>

#include "stitch/eval/surface.hpp"

namespace stitch {

/// Which edges are sharp (by edge index, 1 = sharp): where the surface is only C0 by design.
/// For mdc and asc, the construction's sharp edges (KgonSet::sharp: boundaries and creases from
/// KgonOptions::sharp_from on); for cc, OpenSubdiv's (boundaries and infinitely sharp creases:
/// it rounds semi-sharp creases, so its surface is smooth across them).
std::vector<std::uint8_t> sharp_edges(const HalfedgeMesh& mesh, const Surface& surface);

/// The number of edges among the spokes of v that `sharp` (by edge index; empty: none) marks.
int sharp_spokes(const HalfedgeMesh& mesh, Vertex v, const std::vector<std::uint8_t>& sharp);

/// The patch corners around v in sectors. A sector is the run of corners, counter-clockwise,
/// from one sharp spoke to the next (corner c lies between spokes edge(c) and edge(prev(c)), and
/// rotate_ccw(c) is the next corner). With fewer than two sharp spokes the whole fan is one
/// sector. Corners in holes make no patch and are left out: a hole's corner is a sector of its
/// own, between two boundary spokes, so no sector mixes the two.
std::vector<std::vector<Corner>> vertex_sectors(const HalfedgeMesh& mesh, Vertex v,
                                                const std::vector<std::uint8_t>& sharp);

}  // namespace stitch
