#include "stitch/analysis/sectors.hpp"

namespace stitch {

std::vector<std::uint8_t> sharp_edges(const HalfedgeMesh& mesh, const Surface& surface) {
  std::vector<std::uint8_t> sharp(static_cast<size_t>(mesh.edge_capacity()), 0);
  if (!mesh.has_features()) return sharp;
  const KgonSet& kgons = surface.bezier().kgons;
  for (Edge e : mesh.edges())
    sharp[static_cast<size_t>(e.idx)] =
        surface.method() == Method::cc ? mesh.is_sharp(e) : kgons.sharp(e) || mesh.is_boundary(e);
  return sharp;
}

}  // namespace stitch
