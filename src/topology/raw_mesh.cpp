#include "topology/raw_mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

#include "stitch/mesh/validate.hpp"

namespace stitch::detail {

HalfedgeMesh build_raw(const RawMesh& raw, const std::string& what) {
  HalfedgeMesh mesh;
  for (const Vec3& p : raw.positions) mesh.add_vertex(p);
  for (int f = 0; f < raw.num_faces; ++f) mesh.add_face();
  const int nh = static_cast<int>(raw.origin.size());
  for (int h = 0; h < nh; h += 2) mesh.add_edge(Vertex(raw.origin[h]), Vertex(raw.origin[h + 1]));
  for (int h = 0; h < nh; ++h) {
    const Halfedge he(h);
    mesh.link(he, Halfedge(raw.next[h]));
    mesh.set_face(he, Face(raw.face[h]));
    // The first half-edge met is each element's start, so numbering decides it, not chance.
    if (!mesh.halfedge(Face(raw.face[h])).valid()) mesh.set_halfedge(Face(raw.face[h]), he);
    if (!mesh.halfedge(Vertex(raw.origin[h])).valid()) mesh.set_halfedge(Vertex(raw.origin[h]), he);
  }
  const auto problems = find_problems(mesh);
  if (!problems.empty())
    throw TopologyError(fmt::format("{} would not give a valid mesh: {}", what, problems.front()));
  return mesh;
}

HalfedgeMesh compacted(const HalfedgeMesh& mesh) {
  HalfedgeMesh copy = mesh;
  if (copy.has_garbage()) copy.garbage_collection();
  return copy;
}

Vertex vertex_visited_twice(const HalfedgeMesh& mesh, Face f) {
  const std::vector<Halfedge> loop = mesh.face_loop(f);
  for (size_t i = 0; i < loop.size(); ++i)
    for (size_t j = i + 1; j < loop.size(); ++j)
      if (mesh.origin(loop[i]) == mesh.origin(loop[j])) return mesh.origin(loop[i]);
  return Vertex();
}

Vec3 face_centroid(const HalfedgeMesh& mesh, Face f) {
  Vec3 sum = Vec3::Zero();
  int n = 0;
  for (Halfedge h : mesh.face_loop(f)) {
    sum += mesh.position(mesh.origin(h));
    ++n;
  }
  return sum / n;
}

std::vector<Edge> edges_between(const HalfedgeMesh& mesh, Vertex a, Vertex b) {
  std::vector<Edge> out;
  for (Halfedge h : mesh.vertex_fan(a))
    if (mesh.target(h) == b) out.push_back(HalfedgeMesh::edge(h));
  return out;
}

EdgeRemoval plan_edge_removal(const HalfedgeMesh& m, std::vector<std::uint8_t> gone) {
  EdgeRemoval plan;
  plan.gone = std::move(gone);
  auto removed = [&](Halfedge x) { return plan.gone[HalfedgeMesh::edge(x).idx] != 0; };
  // The successor of a kept half-edge x is found by turning clockwise around target(x) past the
  // removed edges. twin(x) is kept, so this terminates.
  plan.next.assign(m.halfedge_capacity(), -1);
  const std::vector<Halfedge> halfedges = m.halfedges().to_vector();
  auto recompute = [&] {
    for (Halfedge x : halfedges) {
      if (removed(x)) continue;
      Halfedge n = m.next(x);
      while (removed(n)) n = m.rotate_cw(n);
      plan.next[x.idx] = n.idx;
    }
  };
  for (bool dangling = true; dangling;) {
    recompute();
    dangling = false;
    for (Halfedge x : halfedges)
      if (!removed(x) && plan.next[x.idx] == HalfedgeMesh::twin(x).idx) {
        plan.gone[HalfedgeMesh::edge(x).idx] = 1;
        dangling = true;
      }
  }
  for (Halfedge x : halfedges)
    if (!removed(x)) plan.kept.push_back(x);
  for (Edge e : m.edges())
    if (plan.gone[e.idx])
      for (int s = 0; s < 2; ++s)
        plan.touched_faces.insert(m.face(HalfedgeMesh::halfedge(e, s)).idx);
  return plan;
}

std::vector<Face> remove_edges(HalfedgeMesh& m, const EdgeRemoval& plan) {
  const int nh = m.halfedge_capacity();
  for (Halfedge x : plan.kept) m.link(x, Halfedge(plan.next[x.idx]));
  std::vector<std::uint8_t> visited(nh, 0);
  struct Loop {
    int min_face;
    Halfedge first;
  };
  std::vector<Loop> loops;
  for (Halfedge x : plan.kept) {
    if (visited[x.idx] || !plan.touched_faces.count(m.face(x).idx)) continue;
    int min_face = m.face(x).idx;
    for (Halfedge y : m.loop_from(x)) {
      visited[y.idx] = 1;
      min_face = std::min(min_face, m.face(y).idx);
    }
    loops.push_back({min_face, x});
  }
  std::stable_sort(loops.begin(), loops.end(),
                   [](const Loop& a, const Loop& b) { return a.min_face < b.min_face; });
  const std::vector<int> free_numbers(plan.touched_faces.begin(), plan.touched_faces.end());
  std::vector<Halfedge> old_start(m.face_capacity());
  for (int fi : free_numbers) old_start[fi] = m.halfedge(Face(fi));
  size_t used = 0;
  std::vector<Face> result;
  for (const Loop& loop : loops) {
    const Face target = used < free_numbers.size() ? Face(free_numbers[used++]) : m.add_face();
    Halfedge start = loop.first;
    if (target.idx < static_cast<int>(old_start.size()) && old_start[target.idx].valid())
      for (Halfedge y : m.loop_from(loop.first))
        if (y == old_start[target.idx]) start = y;
    m.assign_loop(start, target);
    result.push_back(target);
  }
  for (; used < free_numbers.size(); ++used) m.delete_face(Face(free_numbers[used]));

  for (Edge e : m.edges())
    if (plan.gone[e.idx]) m.delete_edge(e);
  std::vector<int> out_he(m.vertex_capacity(), -1);
  for (Halfedge x : plan.kept)
    if (out_he[m.origin(x).idx] < 0) out_he[m.origin(x).idx] = x.idx;
  for (Vertex v : m.vertices()) {
    if (out_he[v.idx] < 0) {
      m.delete_vertex(v);
    } else if (m.is_deleted(m.halfedge(v))) {
      m.set_halfedge(v, Halfedge(out_he[v.idx]));
    }
  }
  return result;
}

Verdict exists(const HalfedgeMesh& mesh, Vertex v, const char* op) {
  if (v.idx < 0 || v.idx >= mesh.vertex_capacity() || mesh.is_deleted(v))
    return Verdict::refused(fmt::format("{}: there is no vertex {}", op, v.idx + 1));
  return {};
}

Verdict exists(const HalfedgeMesh& mesh, Face f, const char* op) {
  if (f.idx < 0 || f.idx >= mesh.face_capacity() || mesh.is_deleted(f))
    return Verdict::refused(fmt::format("{}: there is no face {}", op, f.idx + 1));
  return {};
}

Verdict exists(const HalfedgeMesh& mesh, Edge e, const char* op) {
  if (e.idx < 0 || e.idx >= mesh.edge_capacity() || mesh.is_deleted(e))
    return Verdict::refused(fmt::format("{}: there is no edge {}", op, e.idx + 1));
  return {};
}

Verdict exists(const HalfedgeMesh& mesh, Corner c, const char* op) {
  if (c.idx < 0 || c.idx >= mesh.halfedge_capacity() || mesh.is_deleted(c))
    return Verdict::refused(fmt::format("{}: there is no corner (half-edge {})", op, c.idx));
  return {};
}

}  // namespace stitch::detail
