// The journal: the states of touched elements before and after a sequence of edits.
#include "stitch/mesh/mesh_journal.hpp"

#include <algorithm>
#include <stdexcept>

namespace stitch {

namespace {

// The states read through the mesh's const interface, so that reading them records nothing.
MeshDelta::VertexState state_of(const HalfedgeMesh& m, Vertex v) {
  return {m.position(v), m.halfedge(v).idx, static_cast<std::uint8_t>(m.is_deleted(v)),
          m.sharpness(v)};
}

MeshDelta::EdgeState state_of(const HalfedgeMesh& m, Edge e) {
  MeshDelta::EdgeState s;
  for (int side = 0; side < 2; ++side) {
    const Halfedge h = HalfedgeMesh::halfedge(e, side);
    s.next[side] = m.next(h).idx;
    s.prev[side] = m.prev(h).idx;
    s.origin[side] = m.origin(h).idx;
    s.face[side] = m.face(h).idx;
  }
  s.deleted = static_cast<std::uint8_t>(m.is_deleted(e));
  s.sharpness = m.sharpness(e);
  return s;
}

MeshDelta::FaceState state_of(const HalfedgeMesh& m, Face f) {
  return {m.halfedge(f).idx, static_cast<std::uint8_t>(m.is_deleted(f)),
          static_cast<std::uint8_t>(m.is_hole(f))};
}

/// Capacities and counts only.
MeshDelta::End end_state(const HalfedgeMesh& m) {
  MeshDelta::End end;
  end.vertex_capacity = m.vertex_capacity();
  end.edge_capacity = m.edge_capacity();
  end.face_capacity = m.face_capacity();
  end.deleted_vertices = m.vertex_capacity() - m.num_vertices();
  end.deleted_edges = m.edge_capacity() - m.num_edges();
  end.deleted_faces = m.face_capacity() - m.num_faces();
  return end;
}

// The touched handles: the recorded old elements and every element added since, in order.
template <class H, class State>
std::vector<H> touched(std::vector<std::pair<int, State>>& recorded, int old_capacity,
                       int capacity) {
  std::sort(recorded.begin(), recorded.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<H> out;
  out.reserve(recorded.size() + static_cast<size_t>(capacity - old_capacity));
  for (const auto& r : recorded) out.emplace_back(r.first);
  for (int i = old_capacity; i < capacity; ++i) out.emplace_back(i);
  return out;
}

}  // namespace

void HalfedgeMesh::ObserverSlot::lose() noexcept {
  if (journal) journal->lose();
  journal = nullptr;
}

void HalfedgeMesh::report(Vertex v) {
  observer_.journal->record(v);
}
void HalfedgeMesh::report(Edge e) {
  observer_.journal->record(e);
}
void HalfedgeMesh::report(Face f) {
  observer_.journal->record(f);
}

MeshJournal::MeshJournal(HalfedgeMesh& mesh) : mesh_(&mesh) {
  if (mesh.observed())
    throw std::logic_error("MeshJournal: the mesh is observed by another journal already");
  delta_.before = end_state(mesh);
  mesh.observer_.journal = this;
}

MeshJournal::~MeshJournal() {
  if (mesh_) mesh_->observer_.journal = nullptr;
}

void MeshJournal::record(Vertex v) {
  if (v.idx < delta_.before.vertex_capacity && seen_vertices_.insert(v.idx).second)
    delta_.before.vertices.emplace_back(v.idx, state_of(*mesh_, v));
}

void MeshJournal::record(Edge e) {
  if (e.idx < delta_.before.edge_capacity && seen_edges_.insert(e.idx).second)
    delta_.before.edges.emplace_back(e.idx, state_of(*mesh_, e));
}

void MeshJournal::record(Face f) {
  if (f.idx < delta_.before.face_capacity && seen_faces_.insert(f.idx).second)
    delta_.before.faces.emplace_back(f.idx, state_of(*mesh_, f));
}

MeshDelta MeshJournal::finish() {
  if (!mesh_)
    throw std::logic_error(
        "MeshJournal::finish: not attached (finished already, or the mesh was destroyed, "
        "assigned to or moved from while observed)");
  const HalfedgeMesh& m = *mesh_;
  mesh_->observer_.journal = nullptr;
  mesh_ = nullptr;
  MeshDelta d = std::move(delta_);
  d.vertices = touched<Vertex>(d.before.vertices, d.before.vertex_capacity, m.vertex_capacity());
  d.edges = touched<Edge>(d.before.edges, d.before.edge_capacity, m.edge_capacity());
  d.faces = touched<Face>(d.before.faces, d.before.face_capacity, m.face_capacity());
  d.after = end_state(m);
  for (Vertex v : d.vertices) d.after.vertices.emplace_back(v.idx, state_of(m, v));
  for (Edge e : d.edges) d.after.edges.emplace_back(e.idx, state_of(m, e));
  for (Face f : d.faces) d.after.faces.emplace_back(f.idx, state_of(m, f));
  return d;
}

void apply_delta(HalfedgeMesh& mesh, const MeshDelta& delta, bool forward) {
  const MeshDelta::End& from = forward ? delta.before : delta.after;
  const MeshDelta::End& to = forward ? delta.after : delta.before;
  if (mesh.vertex_capacity() != from.vertex_capacity ||
      mesh.edge_capacity() != from.edge_capacity || mesh.face_capacity() != from.face_capacity)
    throw std::logic_error("apply_delta: the mesh is not at the delta's starting end");
  // An observing journal records what this changes like any other edit; removing elements would
  // take them out of its reach, so only growth is allowed then.
  if (mesh.observed() &&
      (to.vertex_capacity < from.vertex_capacity || to.edge_capacity < from.edge_capacity ||
       to.face_capacity < from.face_capacity))
    throw std::logic_error("apply_delta: cannot remove elements while a journal observes the mesh");
  for (const auto& entry : to.vertices)
    if (entry.first < from.vertex_capacity) mesh.note(Vertex(entry.first));
  for (const auto& entry : to.edges)
    if (entry.first < from.edge_capacity) mesh.note(Edge(entry.first));
  for (const auto& entry : to.faces)
    if (entry.first < from.face_capacity) mesh.note(Face(entry.first));
  const auto nv = static_cast<size_t>(to.vertex_capacity);
  mesh.positions_.resize(nv, Vec3::Zero());
  mesh.vertex_he_.resize(nv, -1);
  mesh.vertex_deleted_.resize(nv, 0);
  mesh.vertex_sharpness_.resize(nv, 0);
  const auto nh = 2 * static_cast<size_t>(to.edge_capacity);
  mesh.he_next_.resize(nh, -1);
  mesh.he_prev_.resize(nh, -1);
  mesh.he_origin_.resize(nh, -1);
  mesh.he_face_.resize(nh, -1);
  mesh.edge_deleted_.resize(static_cast<size_t>(to.edge_capacity), 0);
  mesh.edge_sharpness_.resize(static_cast<size_t>(to.edge_capacity), 0);
  mesh.face_he_.resize(static_cast<size_t>(to.face_capacity), -1);
  mesh.face_deleted_.resize(static_cast<size_t>(to.face_capacity), 0);
  mesh.face_hole_.resize(static_cast<size_t>(to.face_capacity), 0);
  for (const auto& [i, s] : to.vertices) {
    mesh.positions_[i] = s.position;
    mesh.vertex_he_[i] = s.halfedge;
    mesh.vertex_deleted_[i] = s.deleted;
    mesh.vertex_sharpness_[i] = s.sharpness;
  }
  for (const auto& [i, s] : to.edges) {
    for (int side = 0; side < 2; ++side) {
      const int h = 2 * i + side;
      mesh.he_next_[h] = s.next[side];
      mesh.he_prev_[h] = s.prev[side];
      mesh.he_origin_[h] = s.origin[side];
      mesh.he_face_[h] = s.face[side];
    }
    mesh.edge_deleted_[i] = s.deleted;
    mesh.edge_sharpness_[i] = s.sharpness;
  }
  for (const auto& [i, s] : to.faces) {
    mesh.face_he_[i] = s.halfedge;
    mesh.face_deleted_[i] = s.deleted;
    mesh.face_hole_[i] = s.hole;
  }
  mesh.deleted_vertices_ = to.deleted_vertices;
  mesh.deleted_edges_ = to.deleted_edges;
  mesh.deleted_faces_ = to.deleted_faces;
}

}  // namespace stitch
