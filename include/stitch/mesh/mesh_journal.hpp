// What a sequence of edits changed in a mesh: an optional observer, apart from the mesh.
//
// A MeshJournal attached to a mesh records, at every editing call, the element the call is about
// to change, so a sequence of edits yields a MeshDelta: the touched elements with their state
// before and after. Applying it backward or forward (apply_delta) undoes or redoes the edits
// exactly, at a cost proportional to what they touched, and its element lists tell whatever
// depends on the mesh where to update (topology_change, patches_touched).
//
// The mesh knows only whether a journal watches it (one pointer, tested by every setter); a mesh
// nobody observes pays nothing else. A journal belongs to one mesh object, the way a lock guard
// belongs to one mutex:
// - a mesh takes at most one journal at a time (a second is refused with std::logic_error);
// - copies and moves of a mesh are never observed, whatever their source was;
// - a mesh that is destroyed, assigned to or moved from while observed loses its journal: the
//   journal cannot describe a wholesale replacement, so finish() then throws std::logic_error
//   instead of returning a delta that would not undo the edits.
// The journal detaches itself when it is destroyed, recorded changes and all (the edits stay).
#pragma once

#include <array>
#include <cstdint>
#include <unordered_set>
#include <utility>
#include <vector>

#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch {

/// The touched elements of a sequence of edits, with their states at both ends.
struct MeshDelta {
  struct VertexState {
    Vec3 position;
    int halfedge = -1;
    std::uint8_t deleted = 0;
    double sharpness = 0;
    bool operator==(const VertexState&) const = default;
  };
  struct EdgeState {  ///< both half-edges, side 0 first
    std::array<int, 2> next{}, prev{}, origin{}, face{};
    std::uint8_t deleted = 0;
    double sharpness = 0;
    bool operator==(const EdgeState&) const = default;
  };
  struct FaceState {
    int halfedge = -1;
    std::uint8_t deleted = 0;
    std::uint8_t hole = 0;
    bool operator==(const FaceState&) const = default;
  };
  /// The mesh at one end: capacities, deletion counts, and the states of the touched elements
  /// that exist at that end (index, state).
  struct End {
    int vertex_capacity = 0, edge_capacity = 0, face_capacity = 0;
    int deleted_vertices = 0, deleted_edges = 0, deleted_faces = 0;
    std::vector<std::pair<int, VertexState>> vertices;
    std::vector<std::pair<int, EdgeState>> edges;
    std::vector<std::pair<int, FaceState>> faces;
  };

  /// Every element an editing call touched, new ones included, in increasing order (a superset
  /// of those whose state differs: a touched element may end as it began).
  std::vector<Vertex> vertices;
  std::vector<Edge> edges;
  std::vector<Face> faces;
  End before, after;
};

/// Records what the edits of one mesh change, from construction to finish().
class MeshJournal {
 public:
  /// Starts observing `mesh`. Throws std::logic_error if a journal observes it already.
  explicit MeshJournal(HalfedgeMesh& mesh);
  /// Detaches (if still attached), dropping what was recorded.
  ~MeshJournal();
  // The mesh points at this object: it stays where it was made.
  MeshJournal(const MeshJournal&) = delete;
  MeshJournal& operator=(const MeshJournal&) = delete;
  MeshJournal(MeshJournal&&) = delete;
  MeshJournal& operator=(MeshJournal&&) = delete;

  /// Whether the journal still observes its mesh (not finished, and the mesh not destroyed,
  /// assigned to or moved from since).
  [[nodiscard]] bool attached() const { return mesh_ != nullptr; }
  /// Stops observing and returns what changed since construction. Throws std::logic_error if
  /// the journal is no longer attached (finished already, or its mesh was destroyed, assigned
  /// to or moved from).
  MeshDelta finish();

 private:
  friend class HalfedgeMesh;  // reports the elements it is about to change, and its own end
  void record(Vertex v);
  void record(Edge e);
  void record(Face f);
  void lose() noexcept { mesh_ = nullptr; }

  HalfedgeMesh* mesh_;  ///< read through const references only: reading records nothing
  MeshDelta delta_;
  // Elements below the capacities at construction get their state recorded the first time an
  // editing call touches them; elements added since are all touched, so they need no record.
  std::unordered_set<int> seen_vertices_, seen_edges_, seen_faces_;
};

/// Brings `mesh` from one end of the delta to the other: from `before` to `after` when
/// `forward`, else back. The mesh must be in the state of the end it starts from (e.g. a copy of
/// the mesh the delta was recorded on); otherwise std::logic_error. A journal observing the mesh
/// records the change, which may then not remove elements (std::logic_error).
void apply_delta(HalfedgeMesh& mesh, const MeshDelta& delta, bool forward);

}  // namespace stitch
