#include "stitch/topology/compare.hpp"

#include <vector>

#include "stitch/mesh/validate.hpp"

namespace stitch {

namespace {

/// Extends the correspondence a -> b from one root pair; false (and the map left dirty) on
/// any conflict.
bool match_from(const HalfedgeMesh& a, const HalfedgeMesh& b, Halfedge ra, Halfedge rb,
                std::vector<int>& map, std::vector<int>& used) {
  std::vector<std::pair<Halfedge, Halfedge>> stack{{ra, rb}};
  while (!stack.empty()) {
    const auto [x, y] = stack.back();
    stack.pop_back();
    if (map[x.idx] >= 0) {
      if (map[x.idx] != y.idx) return false;
      continue;
    }
    if (used[y.idx] || a.origin(x) != b.origin(y) || a.is_hole(x) != b.is_hole(y) ||
        a.sharpness(HalfedgeMesh::edge(x)) != b.sharpness(HalfedgeMesh::edge(y)))
      return false;
    map[x.idx] = y.idx;
    used[y.idx] = 1;
    stack.push_back({a.next(x), b.next(y)});
    stack.push_back({HalfedgeMesh::twin(x), HalfedgeMesh::twin(y)});
  }
  return true;
}

}  // namespace

bool same_up_to_renumbering(const HalfedgeMesh& a, const HalfedgeMesh& b) {
  if (a.num_vertices() != b.num_vertices() || a.num_edges() != b.num_edges() ||
      a.num_faces() != b.num_faces())
    return false;
  if (a.vertices() != b.vertices()) return false;
  for (Vertex v : a.vertices())
    if (a.position(v) != b.position(v) || a.sharpness(v) != b.sharpness(v)) return false;
  std::vector<int> map(a.halfedge_capacity(), -1), used(b.halfedge_capacity(), 0);
  for (Vertex v : a.vertices()) {
    const Halfedge ra = a.halfedge(v);
    if (map[ra.idx] >= 0) continue;  // its component is matched already
    bool matched = false;
    for (Halfedge rb : b.vertex_fan(v)) {
      std::vector<int> map_try = map, used_try = used;
      if (match_from(a, b, ra, rb, map_try, used_try)) {
        map = std::move(map_try);
        used = std::move(used_try);
        matched = true;
        break;
      }
    }
    if (!matched) return false;
  }
  return true;
}

}  // namespace stitch
