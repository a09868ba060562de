#include "raw_mesh.hpp"

#include <fmt/format.h>

#include "stitch/mesh/validate.hpp"

namespace stitch::topology_detail {

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
    throw MeshError(fmt::format("{} would not give a valid mesh: {}", what, problems.front()));
  return mesh;
}

HalfedgeMesh compacted(const HalfedgeMesh& mesh) {
  HalfedgeMesh copy = mesh;
  if (copy.has_garbage()) copy.garbage_collection();
  return copy;
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

void check_vertex(const HalfedgeMesh& mesh, Vertex v, const char* op) {
  if (v.idx < 0 || v.idx >= mesh.vertex_capacity() || mesh.is_deleted(v))
    throw MeshError(fmt::format("{}: there is no vertex {}", op, v.idx + 1));
}

void check_face(const HalfedgeMesh& mesh, Face f, const char* op) {
  if (f.idx < 0 || f.idx >= mesh.face_capacity() || mesh.is_deleted(f))
    throw MeshError(fmt::format("{}: there is no face {}", op, f.idx + 1));
}

void check_edge(const HalfedgeMesh& mesh, Edge e, const char* op) {
  if (e.idx < 0 || e.idx >= mesh.edge_capacity() || mesh.is_deleted(e))
    throw MeshError(fmt::format("{}: there is no edge {}", op, e.idx + 1));
}

void check_corner(const HalfedgeMesh& mesh, Corner c, const char* op) {
  if (c.idx < 0 || c.idx >= mesh.halfedge_capacity() || mesh.is_deleted(c))
    throw MeshError(fmt::format("{}: there is no corner (half-edge {})", op, c.idx));
}

}  // namespace stitch::topology_detail
