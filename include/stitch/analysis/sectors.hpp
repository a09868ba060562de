// A surface's sharp edges, for the sectors (topology/vertex_sectors.hpp) the analysis and the
// overlays check tangent planes in.
#pragma once

#include <cstdint>
#include <vector>

#include "stitch/eval/surface.hpp"
#include "stitch/topology/vertex_sectors.hpp"

namespace stitch {

/// Which edges are sharp (by edge index, 1 = sharp): where the surface is only C0 by design.
/// For mdc and asc, the construction's sharp edges (KgonSet::sharp: boundaries and creases from
/// KgonOptions::sharp_from on); for cc, OpenSubdiv's (boundaries and infinitely sharp creases:
/// it rounds semi-sharp creases, so its surface is smooth across them).
std::vector<std::uint8_t> sharp_edges(const HalfedgeMesh& mesh, const Surface& surface);

}  // namespace stitch
