// Random operation lines for fuzz-style tests (fixed seeds in the tests that use them).
#pragma once

#include <fmt/format.h>

#include <random>
#include <string>

#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch::test {

/// A random operation line on the mesh (it may be refused: then the mesh is unchanged).
inline std::string random_operation(const HalfedgeMesh& m, std::mt19937& rng) {
  const auto faces = m.faces().to_vector();
  const Face f = faces[rng() % faces.size()];
  const auto loop = m.face_loop(f);
  const Halfedge h = loop[rng() % loop.size()];
  switch (rng() % 4) {
    case 0: {
      const Face g = faces[rng() % faces.size()];
      const auto other = m.face_loop(g);
      return fmt::format("insert-edge {}@{} {}@{}", m.origin(h).idx + 1, f.idx + 1,
                         m.origin(other[rng() % other.size()]).idx + 1, g.idx + 1);
    }
    case 1:
      return fmt::format("subdivide-edge {} {}", m.origin(h).idx + 1, m.target(h).idx + 1);
    case 2:
      return fmt::format("extrude-face {} 0.3", f.idx + 1);
    default:
      return fmt::format("delete-edge {} {}", m.origin(h).idx + 1, m.target(h).idx + 1);
  }
}

}  // namespace stitch::test
