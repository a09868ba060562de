// The mesh's journal: the states of touched elements before and after a sequence of edits.
#include <algorithm>
#include <unordered_set>

#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch {

// Elements below the capacities at begin_journal() get their state recorded the first time an
// editing call touches them; elements added since are all touched, so they need no record.
struct HalfedgeMesh::Journal {
  Delta delta;
  std::unordered_set<int> seen_vertices, seen_edges, seen_faces;
};

HalfedgeMesh::JournalSlot::JournalSlot() = default;
HalfedgeMesh::JournalSlot::JournalSlot(const JournalSlot& /*other*/) {}
HalfedgeMesh::JournalSlot& HalfedgeMesh::JournalSlot::operator=(const JournalSlot& /*other*/) {
  state.reset();
  return *this;
}
HalfedgeMesh::JournalSlot::JournalSlot(JournalSlot&& other) noexcept = default;
HalfedgeMesh::JournalSlot& HalfedgeMesh::JournalSlot::operator=(JournalSlot&& other) noexcept =
    default;
HalfedgeMesh::JournalSlot::~JournalSlot() = default;

HalfedgeMesh::VertexState HalfedgeMesh::state_of(Vertex v) const {
  return {positions_[v.idx], vertex_he_[v.idx], vertex_deleted_[v.idx], vertex_sharpness_[v.idx]};
}

HalfedgeMesh::EdgeState HalfedgeMesh::state_of(Edge e) const {
  EdgeState s;
  for (int side = 0; side < 2; ++side) {
    const int h = 2 * e.idx + side;
    s.next[side] = he_next_[h];
    s.prev[side] = he_prev_[h];
    s.origin[side] = he_origin_[h];
    s.face[side] = he_face_[h];
  }
  s.deleted = edge_deleted_[e.idx];
  s.sharpness = edge_sharpness_[e.idx];
  return s;
}

HalfedgeMesh::FaceState HalfedgeMesh::state_of(Face f) const {
  return {face_he_[f.idx], face_deleted_[f.idx], face_hole_[f.idx]};
}

HalfedgeMesh::DeltaEnd HalfedgeMesh::end_state() const {
  DeltaEnd end;
  end.vertex_capacity = vertex_capacity();
  end.edge_capacity = edge_capacity();
  end.face_capacity = face_capacity();
  end.deleted_vertices = deleted_vertices_;
  end.deleted_edges = deleted_edges_;
  end.deleted_faces = deleted_faces_;
  return end;
}

void HalfedgeMesh::record(Vertex v) {
  Journal& j = *journal_.state;
  if (v.idx < j.delta.before.vertex_capacity && j.seen_vertices.insert(v.idx).second)
    j.delta.before.vertices.emplace_back(v.idx, state_of(v));
}

void HalfedgeMesh::record(Edge e) {
  Journal& j = *journal_.state;
  if (e.idx < j.delta.before.edge_capacity && j.seen_edges.insert(e.idx).second)
    j.delta.before.edges.emplace_back(e.idx, state_of(e));
}

void HalfedgeMesh::record(Face f) {
  Journal& j = *journal_.state;
  if (f.idx < j.delta.before.face_capacity && j.seen_faces.insert(f.idx).second)
    j.delta.before.faces.emplace_back(f.idx, state_of(f));
}

void HalfedgeMesh::begin_journal() {
  if (journal_open()) throw std::logic_error("begin_journal: a journal is already open");
  journal_.state = std::make_unique<Journal>();
  journal_.state->delta.before = end_state();
}

namespace {

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

HalfedgeMesh::Delta HalfedgeMesh::end_journal() {
  if (!journal_open()) throw std::logic_error("end_journal: no journal is open");
  Delta d = std::move(journal_.state->delta);
  journal_.state.reset();
  d.vertices = touched<Vertex>(d.before.vertices, d.before.vertex_capacity, vertex_capacity());
  d.edges = touched<Edge>(d.before.edges, d.before.edge_capacity, edge_capacity());
  d.faces = touched<Face>(d.before.faces, d.before.face_capacity, face_capacity());
  d.after = end_state();
  for (Vertex v : d.vertices) d.after.vertices.emplace_back(v.idx, state_of(v));
  for (Edge e : d.edges) d.after.edges.emplace_back(e.idx, state_of(e));
  for (Face f : d.faces) d.after.faces.emplace_back(f.idx, state_of(f));
  return d;
}

void HalfedgeMesh::apply(const Delta& delta, bool forward) {
  const DeltaEnd& from = forward ? delta.before : delta.after;
  const DeltaEnd& to = forward ? delta.after : delta.before;
  if (vertex_capacity() != from.vertex_capacity || edge_capacity() != from.edge_capacity ||
      face_capacity() != from.face_capacity)
    throw std::logic_error("apply: the mesh is not at the delta's starting end");
  // An open journal records what this changes like any other edit; removing elements would take
  // them out of its reach, so only growth is allowed then.
  if (journal_open() &&
      (to.vertex_capacity < from.vertex_capacity || to.edge_capacity < from.edge_capacity ||
       to.face_capacity < from.face_capacity))
    throw std::logic_error("apply: cannot remove elements while a journal is open");
  for (const auto& entry : to.vertices)
    if (entry.first < from.vertex_capacity) note(Vertex(entry.first));
  for (const auto& entry : to.edges)
    if (entry.first < from.edge_capacity) note(Edge(entry.first));
  for (const auto& entry : to.faces)
    if (entry.first < from.face_capacity) note(Face(entry.first));
  const auto nv = static_cast<size_t>(to.vertex_capacity);
  positions_.resize(nv, Vec3::Zero());
  vertex_he_.resize(nv, -1);
  vertex_deleted_.resize(nv, 0);
  vertex_sharpness_.resize(nv, 0);
  const auto nh = 2 * static_cast<size_t>(to.edge_capacity);
  he_next_.resize(nh, -1);
  he_prev_.resize(nh, -1);
  he_origin_.resize(nh, -1);
  he_face_.resize(nh, -1);
  edge_deleted_.resize(static_cast<size_t>(to.edge_capacity), 0);
  edge_sharpness_.resize(static_cast<size_t>(to.edge_capacity), 0);
  face_he_.resize(static_cast<size_t>(to.face_capacity), -1);
  face_deleted_.resize(static_cast<size_t>(to.face_capacity), 0);
  face_hole_.resize(static_cast<size_t>(to.face_capacity), 0);
  for (const auto& [i, s] : to.vertices) {
    positions_[i] = s.position;
    vertex_he_[i] = s.halfedge;
    vertex_deleted_[i] = s.deleted;
    vertex_sharpness_[i] = s.sharpness;
  }
  for (const auto& [i, s] : to.edges) {
    for (int side = 0; side < 2; ++side) {
      const int h = 2 * i + side;
      he_next_[h] = s.next[side];
      he_prev_[h] = s.prev[side];
      he_origin_[h] = s.origin[side];
      he_face_[h] = s.face[side];
    }
    edge_deleted_[i] = s.deleted;
    edge_sharpness_[i] = s.sharpness;
  }
  for (const auto& [i, s] : to.faces) {
    face_he_[i] = s.halfedge;
    face_deleted_[i] = s.deleted;
    face_hole_[i] = s.hole;
  }
  deleted_vertices_ = to.deleted_vertices;
  deleted_edges_ = to.deleted_edges;
  deleted_faces_ = to.deleted_faces;
}

}  // namespace stitch
