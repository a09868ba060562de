// Samples of the surface along mesh edges, from every patch that has the edge on a side: how the
// tests see that pieces share a curve (boundaries of cut pieces, the sheets of a split edge).
#pragma once

#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "stitch/eval/surface.hpp"

namespace stitch::test {

/// (rounded position of the vertex a half edge starts at, of the edge's other end, k) -> the
/// points at t = k / 8 from the vertex to the edge's midpoint, one per patch that holds the half
/// on its side 0 (edge(c)) or side 3 (edge(prev(c))), each with the vertex it starts at; for the
/// edges `take(edge)` accepts.
template <class Take>
std::map<std::array<long long, 7>, std::vector<std::pair<Vec3, Vertex>>> edge_samples(
    const HalfedgeMesh& m, const Surface& s, Take take) {
  std::map<std::array<long long, 7>, std::vector<std::pair<Vec3, Vertex>>> out;
  auto key = [](const Vec3& p) {
    return std::array<long long, 3>{std::llround(p.x() * 1e6), std::llround(p.y() * 1e6),
                                    std::llround(p.z() * 1e6)};
  };
  for (Corner c : s.corners()) {
    const auto a = key(m.position(m.origin(c)));
    if (take(HalfedgeMesh::edge(c))) {
      const auto b = key(m.position(m.target(c)));
      for (int k = 0; k <= 8; ++k)
        out[{a[0], a[1], a[2], b[0], b[1], b[2], k}].emplace_back(
            s.evaluate(c, k / 8.0, 0).position, m.origin(c));
    }
    if (take(HalfedgeMesh::edge(m.prev(c)))) {
      const auto b = key(m.position(m.origin(m.prev(c))));
      for (int k = 0; k <= 8; ++k)
        out[{a[0], a[1], a[2], b[0], b[1], b[2], k}].emplace_back(
            s.evaluate(c, 0, k / 8.0).position, m.origin(c));
    }
  }
  return out;
}

}  // namespace stitch::test
