#include "stitch/topology/delete_face.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>

#include "raw_mesh.hpp"
#include "stitch/mesh/validate.hpp"

namespace stitch {

namespace td = topology_detail;

void delete_face(HalfedgeMesh& mesh, Face f) {
  td::check_face(mesh, f, "delete-face");
  // Worked on a copy: the original changes only once the result is known to be valid, and then
  // only in the elements the copy's journal says were touched.
  HalfedgeMesh m = mesh;
  m.begin_journal();
  const int nh = m.halfedge_capacity();
  std::vector<std::uint8_t> gone(m.edge_capacity(), 0);
  for (Halfedge h : m.face_loop(f)) gone[HalfedgeMesh::edge(h).idx] = 1;

  // Removing a set of edges from a map: the successor of a kept half-edge x is found by turning
  // clockwise around target(x) past the removed edges. twin(x) is kept, so this terminates.
  std::vector<int> next(nh, -1);
  auto recompute = [&] {
    for (Halfedge x : m.halfedges()) {
      if (gone[HalfedgeMesh::edge(x).idx]) continue;
      Halfedge n = m.next(x);
      while (gone[HalfedgeMesh::edge(n).idx]) n = m.rotate_cw(n);
      next[x.idx] = n.idx;
    }
  };
  for (bool dangling = true; dangling;) {
    recompute();
    dangling = false;
    for (Halfedge x : m.halfedges())
      if (!gone[HalfedgeMesh::edge(x).idx] && next[x.idx] == HalfedgeMesh::twin(x).idx) {
        gone[HalfedgeMesh::edge(x).idx] = 1;
        dangling = true;
      }
  }
  std::vector<Halfedge> kept;
  for (Halfedge x : m.halfedges())
    if (!gone[HalfedgeMesh::edge(x).idx]) kept.push_back(x);
  if (kept.empty())
    throw MeshError(fmt::format("delete-face: deleting face {} would leave nothing", f.idx + 1));

  // Loops that changed: any kept half-edge whose successor changed, and everything on old faces
  // that lost a half-edge.
  std::set<int> touched_faces;
  for (Edge e : m.edges())
    if (gone[e.idx])
      for (int s = 0; s < 2; ++s) touched_faces.insert(m.face(HalfedgeMesh::halfedge(e, s)).idx);
  for (Halfedge x : kept) m.link(x, Halfedge(next[x.idx]));
  std::vector<std::uint8_t> visited(nh, 0);
  struct Loop {
    int min_face;
    Halfedge first;
  };
  std::vector<Loop> loops;
  for (Halfedge x : kept) {
    if (visited[x.idx] || !touched_faces.count(m.face(x).idx)) continue;
    int min_face = m.face(x).idx;
    for (Halfedge y : m.loop_from(x)) {
      visited[y.idx] = 1;
      min_face = std::min(min_face, m.face(y).idx);
    }
    loops.push_back({min_face, x});
  }
  std::stable_sort(loops.begin(), loops.end(),
                   [](const Loop& a, const Loop& b) { return a.min_face < b.min_face; });
  std::vector<int> free_numbers(touched_faces.begin(), touched_faces.end());
  std::vector<Halfedge> old_start(m.face_capacity());
  for (int fi : free_numbers) old_start[fi] = m.halfedge(Face(fi));
  size_t used = 0;
  for (const Loop& loop : loops) {
    const Face target = used < free_numbers.size() ? Face(free_numbers[used++]) : m.add_face();
    Halfedge start = loop.first;
    if (target.idx < static_cast<int>(old_start.size()) && old_start[target.idx].valid())
      for (Halfedge y : m.loop_from(loop.first))
        if (y == old_start[target.idx]) start = y;
    m.assign_loop(start, target);
  }
  for (; used < free_numbers.size(); ++used) m.delete_face(Face(free_numbers[used]));

  for (Edge e : m.edges())
    if (gone[e.idx]) m.delete_edge(e);
  std::vector<int> out_he(m.vertex_capacity(), -1);
  for (Halfedge x : kept)
    if (out_he[m.origin(x).idx] < 0) out_he[m.origin(x).idx] = x.idx;
  for (Vertex v : m.vertices()) {
    if (out_he[v.idx] < 0) {
      m.delete_vertex(v);
    } else if (m.is_deleted(m.halfedge(v))) {
      m.set_halfedge(v, Halfedge(out_he[v.idx]));
    }
  }
  const auto problems = find_problems(m);
  if (!problems.empty())
    throw MeshError(fmt::format("delete-face: deleting face {} would not give a valid mesh: {}",
                                f.idx + 1, problems.front()));
  mesh.apply(m.end_journal(), true);
}

}  // namespace stitch
