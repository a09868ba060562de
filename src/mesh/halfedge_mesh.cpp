#include "stitch/mesh/halfedge_mesh.hpp"

#include <fmt/format.h>

#include <string>

#include "stitch/mesh/limits.hpp"

namespace stitch {

namespace {
/// Element numbers are `int`: refuse to grow past limits::max_halfedges rather than overflow.
void check_room(int capacity, int more, const char* what) {
  if (capacity > limits::max_halfedges - more)
    throw Error(
        fmt::format("the mesh would have more than {} {}; stitch numbers its elements "
                    "with 32-bit integers",
                    limits::max_halfedges, what));
}
}  // namespace

bool HalfedgeMesh::has_features() const {
  for (int f = 0; f < face_capacity(); ++f)
    if (!face_deleted_[f] && face_hole_[f]) return true;
  for (int e = 0; e < edge_capacity(); ++e)
    if (!edge_deleted_[e] && edge_sharpness_[e] != 0) return true;
  for (int v = 0; v < vertex_capacity(); ++v)
    if (!vertex_deleted_[v] && vertex_sharpness_[v] != 0) return true;
  return false;
}

std::vector<Corner> HalfedgeMesh::patch_corners() const {
  std::vector<Corner> out;
  out.reserve(halfedge_capacity());
  for (int h = 0; h < halfedge_capacity(); ++h)
    if (!edge_deleted_[h >> 1] && !face_hole_[he_face_[h]]) out.emplace_back(h);
  return out;
}

std::vector<Face> HalfedgeMesh::surface_faces() const {
  std::vector<Face> out;
  out.reserve(face_capacity());
  for (int f = 0; f < face_capacity(); ++f)
    if (!face_deleted_[f] && !face_hole_[f]) out.emplace_back(f);
  return out;
}

namespace {

/// The half-edges from `start` along `step` until it comes back, counted first so that the list
/// is allocated once (K-gon building lists every face loop and vertex fan: growing each list by
/// push_back made three allocations for a quad).
template <class Step>
int count_cycle(const HalfedgeMesh& m, Halfedge start, Step step, const char* what) {
  int count = 0;
  Halfedge h = start;
  do {
    ++count;
    h = step(h);
    if (count > m.halfedge_capacity())
      throw Error(std::string("internal error: ") + what + " does not close");
  } while (h != start);
  return count;
}

template <class Step>
std::vector<Halfedge> list_cycle(const HalfedgeMesh& m, Halfedge start, Step step,
                                 const char* what) {
  std::vector<Halfedge> out(static_cast<size_t>(count_cycle(m, start, step, what)));
  Halfedge h = start;
  for (Halfedge& slot : out) {
    slot = h;
    h = step(h);
  }
  return out;
}

}  // namespace

std::vector<Halfedge> HalfedgeMesh::loop_from(Halfedge start) const {
  return list_cycle(
      *this, start, [this](Halfedge h) { return next(h); }, "face loop");
}

std::vector<Halfedge> HalfedgeMesh::face_loop(Face f) const {
  return loop_from(halfedge(f));
}

std::vector<Halfedge> HalfedgeMesh::vertex_fan(Vertex v) const {
  const Halfedge start = halfedge(v);
  if (!start.valid()) return {};
  return list_cycle(
      *this, start, [this](Halfedge h) { return rotate_ccw(h); }, "vertex fan");
}

int HalfedgeMesh::degree(Face f) const {
  return count_cycle(
      *this, halfedge(f), [this](Halfedge h) { return next(h); }, "face loop");
}
int HalfedgeMesh::valence(Vertex v) const {
  const Halfedge start = halfedge(v);
  if (!start.valid()) return 0;
  return count_cycle(
      *this, start, [this](Halfedge h) { return rotate_ccw(h); }, "vertex fan");
}

int HalfedgeMesh::index_in_face(Halfedge h) const {
  int i = 0;
  for (Halfedge g = halfedge(face(h)); g != h; g = next(g)) ++i;
  return i;
}

Vertex HalfedgeMesh::add_vertex(const Vec3& p) {
  check_room(vertex_capacity(), 1, "vertices");
  positions_.push_back(p);
  vertex_he_.push_back(-1);
  vertex_deleted_.push_back(0);
  vertex_sharpness_.push_back(0);
  return Vertex(vertex_capacity() - 1);
}

Face HalfedgeMesh::add_face() {
  check_room(face_capacity(), 1, "faces");
  face_he_.push_back(-1);
  face_deleted_.push_back(0);
  face_hole_.push_back(0);
  return Face(face_capacity() - 1);
}

Halfedge HalfedgeMesh::add_edge(Vertex a, Vertex b) {
  check_room(halfedge_capacity(), 2, "half-edges");
  const int h = halfedge_capacity();
  for (int i = 0; i < 2; ++i) {
    he_next_.push_back(-1);
    he_prev_.push_back(-1);
    he_face_.push_back(-1);
  }
  he_origin_.push_back(a.idx);
  he_origin_.push_back(b.idx);
  edge_deleted_.push_back(0);
  edge_sharpness_.push_back(0);
  return Halfedge(h);
}

void HalfedgeMesh::assign_loop(Halfedge h, Face f) {
  for (Halfedge g : loop_from(h)) set_face(g, f);
  set_halfedge(f, h);
}

void HalfedgeMesh::delete_vertex(Vertex v) {
  note(v);
  if (!vertex_deleted_[v.idx]) {
    vertex_deleted_[v.idx] = 1;
    ++deleted_vertices_;
  }
}
void HalfedgeMesh::delete_edge(Edge e) {
  note(e);
  if (!edge_deleted_[e.idx]) {
    edge_deleted_[e.idx] = 1;
    ++deleted_edges_;
  }
}
void HalfedgeMesh::delete_face(Face f) {
  note(f);
  if (!face_deleted_[f.idx]) {
    face_deleted_[f.idx] = 1;
    ++deleted_faces_;
  }
}

HalfedgeMesh::Remap HalfedgeMesh::garbage_collection() {
  if (observed())
    throw std::logic_error(
        "garbage_collection renumbers everything: not while a journal observes the mesh");
  Remap map;
  auto build = [](const std::vector<std::uint8_t>& deleted, std::vector<int>& m) {
    m.assign(deleted.size(), -1);
    int n = 0;
    for (size_t i = 0; i < deleted.size(); ++i)
      if (!deleted[i]) m[i] = n++;
    return n;
  };
  const int nv = build(vertex_deleted_, map.vertex);
  const int ne = build(edge_deleted_, map.edge);
  const int nf = build(face_deleted_, map.face);
  auto he_map = [&](int h) { return h < 0 ? -1 : 2 * map.edge[h >> 1] + (h & 1); };
  auto map_or_invalid = [](const std::vector<int>& m, int i) { return i < 0 ? -1 : m[i]; };

  HalfedgeMesh out;
  out.positions_.resize(nv);
  out.vertex_he_.resize(nv);
  out.vertex_deleted_.assign(nv, 0);
  out.vertex_sharpness_.resize(nv);
  for (size_t v = 0; v < positions_.size(); ++v) {
    if (map.vertex[v] < 0) continue;
    out.positions_[map.vertex[v]] = positions_[v];
    out.vertex_sharpness_[map.vertex[v]] = vertex_sharpness_[v];
    out.vertex_he_[map.vertex[v]] = he_map(vertex_he_[v]);
  }
  out.he_next_.resize(2 * ne);
  out.he_prev_.resize(2 * ne);
  out.he_origin_.resize(2 * ne);
  out.he_face_.resize(2 * ne);
  out.edge_deleted_.assign(ne, 0);
  out.edge_sharpness_.resize(ne);
  for (size_t e = 0; e < edge_sharpness_.size(); ++e)
    if (map.edge[e] >= 0) out.edge_sharpness_[map.edge[e]] = edge_sharpness_[e];
  for (int h = 0; h < halfedge_capacity(); ++h) {
    const int nh = he_map(h);
    if (map.edge[h >> 1] < 0) continue;
    out.he_next_[nh] = he_map(he_next_[h]);
    out.he_prev_[nh] = he_map(he_prev_[h]);
    out.he_origin_[nh] = map_or_invalid(map.vertex, he_origin_[h]);
    out.he_face_[nh] = map_or_invalid(map.face, he_face_[h]);
  }
  out.face_he_.resize(nf);
  out.face_deleted_.assign(nf, 0);
  out.face_hole_.resize(nf);
  for (size_t f = 0; f < face_he_.size(); ++f)
    if (map.face[f] >= 0) {
      out.face_he_[map.face[f]] = he_map(face_he_[f]);
      out.face_hole_[map.face[f]] = face_hole_[f];
    }
  *this = std::move(out);
  return map;
}

}  // namespace stitch
