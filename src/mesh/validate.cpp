#include "stitch/mesh/validate.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numeric>
#include <utility>

namespace stitch {

std::vector<std::string> find_problems(const HalfedgeMesh& m) {
  std::vector<std::string> problems;
  auto bad = [&](std::string s) { problems.push_back(std::move(s)); };
  const int nh = m.halfedge_capacity();
  auto live_he = [&](Halfedge h) { return h.idx >= 0 && h.idx < nh && !m.is_deleted(h); };
  auto live_v = [&](Vertex v) {
    return v.idx >= 0 && v.idx < m.vertex_capacity() && !m.is_deleted(v);
  };
  auto live_f = [&](Face f) { return f.idx >= 0 && f.idx < m.face_capacity() && !m.is_deleted(f); };

  for (Halfedge h : m.halfedges()) {
    const Halfedge n = m.next(h), p = m.prev(h);
    if (!live_he(n) || !live_he(p)) {
      bad(fmt::format("half-edge {} links to a missing half-edge", h.idx));
      continue;
    }
    if (m.prev(n) != h || m.next(p) != h)
      bad(fmt::format("half-edge {}: next/prev links disagree", h.idx));
    if (!live_v(m.origin(h))) bad(fmt::format("half-edge {} starts at a missing vertex", h.idx));
    if (!live_f(m.face(h))) bad(fmt::format("half-edge {} has no face (a boundary)", h.idx));
    if (m.origin(n) != m.target(h))
      bad(fmt::format("half-edge {} ends at vertex {} but its successor starts at {}", h.idx,
                      m.target(h).idx + 1, m.origin(n).idx + 1));
    if (m.origin(h) == m.target(h))
      bad(fmt::format("edge {} is a loop at vertex {}", HalfedgeMesh::edge(h).idx + 1,
                      m.origin(h).idx + 1));
    if (problems.size() > 20) return problems;
  }
  if (!problems.empty()) return problems;

  std::vector<int> seen(nh, 0);
  for (Face f : m.faces()) {
    const Halfedge start = m.halfedge(f);
    if (!live_he(start) || m.face(start) != f) {
      bad(fmt::format("face {} does not own its start half-edge", f.idx + 1));
      continue;
    }
    int degree = 0;
    for (Halfedge h : m.face_loop(f)) {
      if (m.face(h) != f) bad(fmt::format("face {}: its loop runs into another face", f.idx + 1));
      ++seen[h.idx];
      ++degree;
    }
    if (degree < 2) bad(fmt::format("face {} has degree {}", f.idx + 1, degree));
  }
  for (Edge e : m.edges()) {
    if (m.is_hole(HalfedgeMesh::halfedge(e, 0)) && m.is_hole(HalfedgeMesh::halfedge(e, 1)))
      bad(fmt::format("edge {} has a hole on both sides (no surface touches it)", e.idx + 1));
    const double s = m.sharpness(e);
    if (!(s >= 0) || !std::isfinite(s))
      bad(fmt::format("edge {} has sharpness {} (it must be finite and >= 0)", e.idx + 1, s));
  }
  for (Halfedge h : m.halfedges())
    if (seen[h.idx] != 1)
      bad(fmt::format("half-edge {} lies on {} face loops", h.idx, seen[h.idx]));

  std::vector<int> outgoing(m.vertex_capacity(), 0);
  for (Halfedge h : m.halfedges()) ++outgoing[m.origin(h).idx];
  for (Vertex v : m.vertices()) {
    const Halfedge h = m.halfedge(v);
    if (!live_he(h) || m.origin(h) != v) {
      bad(fmt::format("vertex {} has no outgoing edge (isolated vertex)", v.idx + 1));
      continue;
    }
    const int fan = static_cast<int>(m.vertex_fan(v).size());
    if (fan != outgoing[v.idx])
      bad(fmt::format("vertex {} is non-manifold: one fan holds {} of its {} corners", v.idx + 1,
                      fan, outgoing[v.idx]));
    if (fan < 2) bad(fmt::format("vertex {} has valence {}", v.idx + 1, fan));
    int holes = 0;
    for (Halfedge c : m.vertex_fan(v)) holes += m.is_hole(c);
    if (holes > 1)
      bad(fmt::format("vertex {} is non-manifold: {} boundary loops touch there", v.idx + 1,
                      holes));
    if (holes == fan) bad(fmt::format("vertex {} lies in holes only", v.idx + 1));
    const double s = m.sharpness(v);
    if (!(s >= 0) || !std::isfinite(s))
      bad(fmt::format("vertex {} has sharpness {} (it must be finite and >= 0)", v.idx + 1, s));
  }
  return problems;
}

void validate(const HalfedgeMesh& mesh) {
  const auto problems = find_problems(mesh);
  if (problems.empty()) return;
  std::string msg = "invalid mesh: " + problems[0];
  for (size_t i = 1; i < problems.size() && i < 5; ++i) msg += "; " + problems[i];
  if (problems.size() > 5) msg += fmt::format("; and {} more", problems.size() - 5);
  throw InputError(msg);
}

std::vector<int> connected_components(const HalfedgeMesh& mesh, int* count) {
  // Union-find with union by size and path halving.
  std::vector<int> parent(mesh.vertex_capacity()), size(mesh.vertex_capacity(), 1);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (int e = 0; e < mesh.edge_capacity(); ++e) {
    if (mesh.is_deleted(Edge(e))) continue;
    const Halfedge h = HalfedgeMesh::halfedge(Edge(e), 0);
    int a = find(mesh.origin(h).idx), b = find(mesh.target(h).idx);
    if (a == b) continue;
    if (size[a] < size[b]) std::swap(a, b);
    parent[b] = a;
    size[a] += size[b];
  }
  std::vector<int> id(mesh.vertex_capacity(), -1), root_id(mesh.vertex_capacity(), -1);
  int n = 0;
  for (int v = 0; v < mesh.vertex_capacity(); ++v) {
    if (mesh.is_deleted(Vertex(v))) continue;
    const int r = find(v);
    if (root_id[r] < 0) root_id[r] = n++;
    id[v] = root_id[r];
  }
  if (count) *count = n;
  return id;
}

TopologyStats topology_stats(const HalfedgeMesh& mesh) {
  TopologyStats s;
  s.vertices = mesh.num_vertices();
  s.edges = mesh.num_edges();
  for (Face f : mesh.faces()) (mesh.is_hole(f) ? s.boundary_loops : s.faces) += 1;
  for (Edge e : mesh.edges())
    if (!mesh.is_boundary(e) && mesh.sharpness(e) > 0) ++s.crease_edges;
  for (Vertex v : mesh.vertices())
    if (mesh.sharpness(v) > 0) ++s.corner_vertices;
  connected_components(mesh, &s.components);
  // Euler characteristic of the surface with its boundary; each boundary loop is a disc short of
  // the closed surface of the same genus.
  s.euler = s.vertices - s.edges + s.faces;
  s.genus = (2 * s.components - s.euler - s.boundary_loops) / 2;
  // On a valid mesh a vertex's valence is its number of outgoing half-edges and a face's degree
  // its number of half-edges; counting them avoids walking every fan and loop.
  std::vector<int> valence(mesh.vertex_capacity(), 0), degree(mesh.face_capacity(), 0);
  for (int h = 0; h < mesh.halfedge_capacity(); ++h) {
    if (mesh.is_deleted(Halfedge(h))) continue;
    ++valence[mesh.origin(Halfedge(h)).idx];
    if (!mesh.is_hole(Halfedge(h))) ++degree[mesh.face(Halfedge(h)).idx];
  }
  // Histograms are counted in arrays first: a map insertion per element costs more than the
  // rest of this function together.
  auto histogram = [](const std::vector<int>& counts, auto live, std::map<int, int>& out) {
    std::vector<int> n;
    int irregular = 0;
    for (size_t i = 0; i < counts.size(); ++i) {
      if (!live(static_cast<int>(i))) continue;
      const int k = counts[i];
      if (k >= static_cast<int>(n.size())) n.resize(k + 1, 0);
      ++n[k];
      if (k != 4) ++irregular;
    }
    for (size_t k = 0; k < n.size(); ++k)
      if (n[k] > 0) out[static_cast<int>(k)] = n[k];
    return irregular;
  };
  s.extraordinary_vertices = histogram(
      valence, [&](int v) { return !mesh.is_deleted(Vertex(v)); }, s.valence_histogram);
  s.extraordinary_faces = histogram(
      degree, [&](int f) { return !mesh.is_deleted(Face(f)) && !mesh.is_hole(Face(f)); },
      s.degree_histogram);
  return s;
}

}  // namespace stitch
