#include "stitch/modeler/document.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "stitch/mesh/limits.hpp"

namespace stitch::modeler {

namespace {

template <class Pred>
void erase_if_key(std::unordered_map<int, KgonControl>& map, Pred dead) {
  std::erase_if(map, [&](const auto& entry) { return dead(entry.first); });
}

Change kgon_change(const KgonTarget& t) {
  Change c;
  c.kind = Change::Kind::kgons;
  if (t.global()) {
    c.all_kgons = true;
  } else if (t.kind == KgonKind::face) {
    c.faces.emplace_back(t.element);
  } else if (t.kind == KgonKind::vertex) {
    c.vertices.emplace_back(t.element);
  } else {
    c.edges.emplace_back(t.element);
  }
  return c;
}

template <class Options>  // KgonOptions, const or not
auto& controls_of(Options& o, KgonKind kind) {
  return kind == KgonKind::face ? o.face : kind == KgonKind::vertex ? o.vertex : o.edge;
}

/// Whether `next`, recorded right after `last`, touched exactly the elements `last` touched and
/// neither added nor deleted any: then `last`'s start and `next`'s end are one edit.
bool in_place_on_the_same_elements(const MeshDelta& last, const MeshDelta& next) {
  const auto same_counts = [](const MeshDelta::End& a, const MeshDelta::End& b) {
    return a.vertex_capacity == b.vertex_capacity && a.edge_capacity == b.edge_capacity &&
           a.face_capacity == b.face_capacity && a.deleted_vertices == b.deleted_vertices &&
           a.deleted_edges == b.deleted_edges && a.deleted_faces == b.deleted_faces;
  };
  return last.vertices == next.vertices && last.edges == next.edges && last.faces == next.faces &&
         same_counts(last.before, last.after) && same_counts(next.before, next.after) &&
         same_counts(last.after, next.before);
}

}  // namespace

void prune_kgon_controls(const HalfedgeMesh& mesh, KgonOptions& kgons, bool renumbered) {
  if (renumbered) {
    kgons.face.clear();
    kgons.vertex.clear();
    kgons.edge.clear();
    return;
  }
  erase_if_key(kgons.face,
               [&](int i) { return i >= mesh.face_capacity() || mesh.is_deleted(Face(i)); });
  erase_if_key(kgons.vertex,
               [&](int i) { return i >= mesh.vertex_capacity() || mesh.is_deleted(Vertex(i)); });
  erase_if_key(kgons.edge,
               [&](int i) { return i >= mesh.edge_capacity() || mesh.is_deleted(Edge(i)); });
}

Document::Document(HalfedgeMesh mesh, KgonOptions kgons)
    : state_{std::move(mesh), std::move(kgons)} {}

Change Document::apply_operation(std::string_view line, OperationReport* report, bool merge) {
  const std::optional<Operation> op = parse_operation(state_.mesh, line);
  if (!op) {
    if (report) *report = {};
    return {};
  }
  std::string label(line);
  label.erase(0, label.find_first_not_of(" \t"));
  return apply_operation(*op, std::move(label), report, merge);
}

Change Document::apply_operation(const Operation& op, OperationReport* report, bool merge) {
  return apply_operation(op, format_operation(state_.mesh, op), report, merge);
}

Change Document::apply_operation(const Operation& op, std::string label, OperationReport* report,
                                 bool merge) {
  if (operation_info(op).renumbers) {  // a new mesh, numbered afresh: keep both whole
    DocumentState before = state_;
    const OperationReport r = stitch::apply_operation(state_.mesh, op, Census::counts_only);
    if (report) *report = r;
    prune_kgon_controls(state_.mesh, state_.kgons, true);
    record(Command{std::move(label), Snapshot{std::move(before), state_}});
    return whole_change();
  }
  OperationReport r;
  MeshJournal journal(state_.mesh);
  try {
    r = stitch::apply_operation(state_.mesh, op, Census::counts_only);
  } catch (...) {
    // The library promises no change; the journal makes sure of it.
    apply_delta(state_.mesh, journal.finish(), false);
    throw;
  }
  MeshDelta delta = journal.finish();
  if (report) *report = r;
  if (r.what.empty()) return {};
  KgonOptions kgons_before = state_.kgons;
  prune_kgon_controls(state_.mesh, state_.kgons, false);
  Change c = topology_change(delta);
  TopologyEdit* last = nullptr;
  if (merge && !done_.empty() && undone_.empty())
    last = std::get_if<TopologyEdit>(&done_.back().edit);
  if (last && in_place_on_the_same_elements(last->mesh, delta)) {
    // The last step's start, this edit's end.
    last->mesh.after = std::move(delta.after);
    last->kgons_after = state_.kgons;
    done_.back().label = std::move(label);
    done_.back().revision_after = revision_ = next_revision_++;
    return c;
  }
  record(Command{std::move(label),
                 TopologyEdit{std::move(delta), std::move(kgons_before), state_.kgons}});
  return c;
}

Change Document::replace(DocumentState state, std::string label) {
  Command command{std::move(label), Snapshot{state_, std::move(state)}};
  state_ = std::get<Snapshot>(command.edit).after;
  record(std::move(command));
  return whole_change();
}

Change Document::append(const HalfedgeMesh& other, const KgonOptions& other_kgons,
                        const Vec3& offset, std::string label) {
  HalfedgeMesh& m = state_.mesh;
  // New numbers of other's live elements; for edges the new half-edge of side 0.
  std::vector<int> vertex_to(other.vertex_capacity(), -1), face_to(other.face_capacity(), -1),
      edge_to(other.edge_capacity(), -1);
  auto halfedge_to = [&](Halfedge h) {
    return Halfedge(edge_to[HalfedgeMesh::edge(h).idx] + (h.idx & 1));
  };
  MeshJournal journal(m);
  try {
    for (Vertex v : other.vertices()) {
      const Vec3 p = other.position(v) + offset;
      limits::check_coordinates(p, fmt::format("append: vertex {} moved by the offset", v.idx + 1));
      const Vertex n = m.add_vertex(p);
      vertex_to[v.idx] = n.idx;
      if (other.sharpness(v) > 0) m.set_sharpness(n, other.sharpness(v));
    }
    for (Face f : other.faces()) {
      const Face n = m.add_face();
      face_to[f.idx] = n.idx;
      if (other.is_hole(f)) m.set_hole(n, true);
    }
    for (Edge e : other.edges()) {
      const Halfedge h = HalfedgeMesh::halfedge(e, 0);
      const Halfedge n = m.add_edge(Vertex(vertex_to[other.origin(h).idx]),
                                    Vertex(vertex_to[other.target(h).idx]));
      edge_to[e.idx] = n.idx;
      if (other.sharpness(e) > 0) m.set_sharpness(HalfedgeMesh::edge(n), other.sharpness(e));
    }
    for (Halfedge h : other.halfedges()) {
      m.link(halfedge_to(h), halfedge_to(other.next(h)));
      m.set_face(halfedge_to(h), Face(face_to[other.face(h).idx]));
    }
    for (Vertex v : other.vertices())
      m.set_halfedge(Vertex(vertex_to[v.idx]), halfedge_to(other.halfedge(v)));
    for (Face f : other.faces())
      m.set_halfedge(Face(face_to[f.idx]), halfedge_to(other.halfedge(f)));
  } catch (...) {
    apply_delta(m, journal.finish(), false);
    throw;
  }
  MeshDelta delta = journal.finish();
  KgonOptions kgons_before = state_.kgons;
  for (const auto& [f, c] : other_kgons.face)
    if (f < other.face_capacity() && face_to[f] >= 0) state_.kgons.face[face_to[f]] = c;
  for (const auto& [v, c] : other_kgons.vertex)
    if (v < other.vertex_capacity() && vertex_to[v] >= 0) state_.kgons.vertex[vertex_to[v]] = c;
  for (const auto& [e, c] : other_kgons.edge)
    if (e < other.edge_capacity() && edge_to[e] >= 0)
      state_.kgons.edge[HalfedgeMesh::edge(Halfedge(edge_to[e])).idx] = c;
  Change c = topology_change(delta);
  record(Command{std::move(label),
                 TopologyEdit{std::move(delta), std::move(kgons_before), state_.kgons}});
  return c;
}

Change Document::move_vertices(const std::vector<Vertex>& vertices,
                               const std::vector<Vec3>& positions, bool merge) {
  if (vertices.size() != positions.size())
    throw UsageError("move_vertices: one position per vertex is needed");
  for (size_t i = 0; i < vertices.size(); ++i) {
    const Vertex v = vertices[i];
    if (v.idx < 0 || v.idx >= state_.mesh.vertex_capacity() || state_.mesh.is_deleted(v))
      throw UsageError(fmt::format("move: there is no vertex {}", v.idx + 1));
    if (!positions[i].allFinite())
      throw UsageError(fmt::format("move: vertex {} would get a non-finite position", v.idx + 1));
  }
  Change c;
  c.kind = Change::Kind::geometry;
  c.moved = vertices;
  MoveVertices* last = nullptr;
  if (merge && !done_.empty() && undone_.empty())
    last = std::get_if<MoveVertices>(&done_.back().edit);
  if (last && last->vertices == vertices) {
    last->after = positions;
    for (size_t i = 0; i < vertices.size(); ++i) state_.mesh.position(vertices[i]) = positions[i];
    done_.back().revision_after = revision_ = next_revision_++;
    return c;
  }
  MoveVertices move{vertices, {}, positions};
  for (Vertex v : vertices) move.before.push_back(state_.mesh.position(v));
  std::string label = vertices.size() == 1 ? fmt::format("move vertex {}", vertices[0].idx + 1)
                                           : fmt::format("move {} vertices", vertices.size());
  Command command{std::move(label), std::move(move)};
  apply(command, true);
  record(std::move(command));
  return c;
}

KgonControl Document::kgon_control(const KgonTarget& target) const {
  if (target.global()) return state_.kgons.global;
  const auto& map = controls_of(state_.kgons, target.kind);
  const auto it = map.find(target.element);
  return it == map.end() ? KgonControl{} : it->second;
}

void Document::check_control(const KgonTarget& target, const KgonControl& control) const {
  const HalfedgeMesh& m = state_.mesh;
  if (!target.global()) {
    const int i = target.element;
    const bool exists =
        target.kind == KgonKind::face     ? i < m.face_capacity() && !m.is_deleted(Face(i))
        : target.kind == KgonKind::vertex ? i < m.vertex_capacity() && !m.is_deleted(Vertex(i))
                                          : i < m.edge_capacity() && !m.is_deleted(Edge(i));
    if (!exists) throw UsageError(fmt::format("kgon: there is no such element ({})", i + 1));
  }
  check_kgon_control(control, "kgon: ");
}

Change Document::set_kgon_controls_in_last_edit(
    const std::vector<std::pair<KgonTarget, KgonControl>>& controls) {
  TopologyEdit* last = nullptr;
  if (!done_.empty() && undone_.empty()) last = std::get_if<TopologyEdit>(&done_.back().edit);
  if (!last) throw UsageError("K-gon controls: the last step is not a topology edit just made");
  for (const auto& [target, control] : controls) {
    if (target.global())
      throw UsageError("K-gon controls: the global control is not part of a topology edit");
    check_control(target, control);
  }
  Change c;
  c.kind = Change::Kind::kgons;
  for (const auto& [target, control] : controls) {
    // Kept as given, a default control too: an element's own control stands instead of the
    // global one (which reaches every K-gon but the 4-gons).
    controls_of(state_.kgons, target.kind)[target.element] = control;
    const Change one = kgon_change(target);
    c.faces.insert(c.faces.end(), one.faces.begin(), one.faces.end());
    c.vertices.insert(c.vertices.end(), one.vertices.begin(), one.vertices.end());
    c.edges.insert(c.edges.end(), one.edges.begin(), one.edges.end());
  }
  last->kgons_after = state_.kgons;
  // A new revision, as a merged drag gets: the document differs from anything saved meanwhile.
  done_.back().revision_after = revision_ = next_revision_++;
  return c;
}

Change Document::set_kgon_control(const KgonTarget& target, const KgonControl& control,
                                  bool merge) {
  check_control(target, control);
  KgonOptions after = state_.kgons;
  if (target.global()) {
    after.global = control;
  } else if (control == KgonControl{}) {
    controls_of(after, target.kind).erase(target.element);
  } else {
    controls_of(after, target.kind)[target.element] = control;
  }
  KgonEdit* last = nullptr;
  if (merge && !done_.empty() && undone_.empty()) last = std::get_if<KgonEdit>(&done_.back().edit);
  if (last && last->target == target) {
    last->after = after;
    state_.kgons = std::move(after);
    done_.back().revision_after = revision_ = next_revision_++;
    return kgon_change(target);
  }
  static constexpr const char* kind_names[] = {"face", "vertex", "edge"};
  std::string label = target.global()
                          ? std::string("global K-gon control")
                          : fmt::format("K-gon of {} {}", kind_names[static_cast<int>(target.kind)],
                                        target.element + 1);
  Command command{std::move(label), KgonEdit{target, state_.kgons, std::move(after)}};
  apply(command, true);
  record(std::move(command));
  return kgon_change(target);
}

Change Document::apply(const Command& command, bool forward) {
  Change c;
  if (const auto* move = std::get_if<MoveVertices>(&command.edit)) {
    const auto& to = forward ? move->after : move->before;
    for (size_t i = 0; i < move->vertices.size(); ++i)
      state_.mesh.position(move->vertices[i]) = to[i];
    c.kind = Change::Kind::geometry;
    c.moved = move->vertices;
  } else if (const auto* edit = std::get_if<KgonEdit>(&command.edit)) {
    state_.kgons = forward ? edit->after : edit->before;
    c = kgon_change(edit->target);
  } else if (const auto* topology = std::get_if<TopologyEdit>(&command.edit)) {
    apply_delta(state_.mesh, topology->mesh, forward);
    state_.kgons = forward ? topology->kgons_after : topology->kgons_before;
    c = topology_change(topology->mesh);
  } else {
    const auto& snapshot = std::get<Snapshot>(command.edit);
    state_ = forward ? snapshot.after : snapshot.before;
    c = whole_change();
  }
  return c;
}

void Document::record(Command command) {
  command.revision_before = revision_;
  command.revision_after = revision_ = next_revision_++;
  done_.push_back(std::move(command));
  undone_.clear();
}

Change Document::undo() {
  if (done_.empty()) throw UsageError("undo: there is nothing to undo");
  Command command = std::move(done_.back());
  done_.pop_back();
  Change c = apply(command, false);
  revision_ = command.revision_before;
  undone_.push_back(std::move(command));
  return c;
}

Change Document::redo() {
  if (undone_.empty()) throw UsageError("redo: there is nothing to redo");
  Command command = std::move(undone_.back());
  undone_.pop_back();
  Change c = apply(command, true);
  revision_ = command.revision_after;
  done_.push_back(std::move(command));
  return c;
}

std::vector<std::string> Document::undo_labels() const {
  std::vector<std::string> out;
  for (const Command& c : done_) out.push_back(c.label);
  return out;
}

std::vector<std::string> Document::redo_labels() const {
  std::vector<std::string> out;
  for (const Command& c : undone_) out.push_back(c.label);
  return out;
}

}  // namespace stitch::modeler
