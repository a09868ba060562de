// The modeler's editable document: the mesh and its K-gon controls, changed only through
// recorded commands so every change can be undone and redone without limit.
//
// Commands store what they need to go both ways exactly: a vertex move its positions before and
// after, a K-gon edit the controls before and after, a local topology operation the mesh's
// journal (the touched elements before and after, MeshDelta) and the K-gon controls
// before and after. Remeshings and replacing the document renumber everything, so those keep
// the whole document before and after.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "stitch/kgon/kgon.hpp"
#include "stitch/mesh/halfedge_mesh.hpp"
#include "stitch/mesh/mesh_journal.hpp"
#include "stitch/tess/surface_change.hpp"
#include "stitch/topology/operation.hpp"

namespace stitch::modeler {

/// Everything undo restores.
struct DocumentState {
  HalfedgeMesh mesh;
  KgonOptions kgons;
};

/// What an edit changed, so the surface can update only what depends on it (the library's
/// SurfaceChange, with combined() to merge several).
using Change = SurfaceChange;

/// An element whose K-gon a control applies to; element -1 = the global control.
struct KgonTarget {
  KgonKind kind = KgonKind::face;
  int element = -1;
  [[nodiscard]] bool global() const { return element < 0; }
  bool operator==(const KgonTarget&) const = default;
};

class Document {
 public:
  explicit Document(HalfedgeMesh mesh = {}, KgonOptions kgons = {});

  [[nodiscard]] const HalfedgeMesh& mesh() const { return state_.mesh; }
  [[nodiscard]] const KgonOptions& kgon_options() const { return state_.kgons; }
  [[nodiscard]] const DocumentState& state() const { return state_; }

  /// Applies one `stitch edit --ops` line (apply_operation, which counts V, E, F and the Euler
  /// characteristic for the report but not genus and components, whose count would need a pass
  /// over the whole mesh). Throws stitch::Error with the document unchanged when the line is
  /// refused. A blank line changes nothing and records nothing. With `merge`, an edit that
  /// touches exactly the elements the last step touched, in place (a crease's or corner's
  /// sharpness again), extends that step instead of making one (one undo step per slider drag).
  Change apply_operation(std::string_view line, OperationReport* report = nullptr,
                         bool merge = false);
  /// The same for a typed operation; its history label is format_operation's line.
  Change apply_operation(const Operation& op, OperationReport* report = nullptr,
                         bool merge = false);
  /// Replaces the whole document (new primitive, opened file) as one undoable step.
  Change replace(DocumentState state, std::string label);
  /// Adds `other` (a valid mesh) as one more component, moved by `offset`, with its
  /// per-element K-gon controls, as one undoable step. Its elements are numbered after this
  /// mesh's, in their order; nothing already here is renumbered, so the step is a journal entry
  /// like a local operation and the surface updates only the new patches. Throws stitch::Error with
  /// the document unchanged when the result would break a limit.
  Change append(const HalfedgeMesh& other, const KgonOptions& other_kgons, const Vec3& offset,
                std::string label);
  /// Moves vertices to `positions`. With `merge`, a move of the same vertices right after
  /// another one extends that command (one undo step per mouse drag).
  Change move_vertices(const std::vector<Vertex>& vertices, const std::vector<Vec3>& positions,
                       bool merge = false);
  /// Sets the control of one element's K-gon (or the global one). Throws stitch::Error for an
  /// element that does not exist.
  Change set_kgon_control(const KgonTarget& target, const KgonControl& control, bool merge = false);
  /// Sets per-element controls as part of the last step, a topology edit just made
  /// (apply_operation or append), so that one undo takes back the edit and the controls together:
  /// the controls the session chooses for the tubes an edit made (Session::apply_edit). Throws
  /// stitch::Error, with the document unchanged, when the last step is not such an edit or was
  /// undone, for a global target, or for an element that does not exist.
  Change set_kgon_controls_in_last_edit(
      const std::vector<std::pair<KgonTarget, KgonControl>>& controls);
  /// The control in effect for the target (the element's own, else the default).
  [[nodiscard]] KgonControl kgon_control(const KgonTarget& target) const;

  [[nodiscard]] bool can_undo() const { return !done_.empty(); }
  [[nodiscard]] bool can_redo() const { return !undone_.empty(); }
  /// Throw stitch::Error when there is nothing to undo / redo.
  Change undo();
  Change redo();
  /// Labels of the done commands, oldest first, and of the undone ones, next redo last.
  [[nodiscard]] std::vector<std::string> undo_labels() const;
  [[nodiscard]] std::vector<std::string> redo_labels() const;

  /// True when the document differs from the last mark_saved() (or from the start).
  [[nodiscard]] bool modified() const { return revision_ != saved_revision_; }
  void mark_saved() { saved_revision_ = revision_; }
  /// Marks the document as differing from its file (e.g. after recovering an autosave).
  void mark_modified() { saved_revision_ = -1; }

 private:
  Change apply_operation(const Operation& op, std::string label, OperationReport* report,
                         bool merge);
  struct MoveVertices {
    std::vector<Vertex> vertices;
    std::vector<Vec3> before, after;
  };
  struct KgonEdit {
    KgonTarget target;
    KgonOptions before, after;
  };
  struct TopologyEdit {
    MeshDelta mesh;
    KgonOptions kgons_before, kgons_after;
  };
  struct Snapshot {
    DocumentState before, after;
  };
  struct Command {
    std::string label;
    std::variant<MoveVertices, KgonEdit, TopologyEdit, Snapshot> edit;
    long revision_before = 0, revision_after = 0;  ///< for modified()
  };

  /// Throws stitch::Error when the target's element does not exist or the control's values are
  /// not finite.
  void check_control(const KgonTarget& target, const KgonControl& control) const;
  Change apply(const Command& command, bool forward);
  void record(Command command);

  DocumentState state_;
  std::vector<Command> done_, undone_;
  long revision_ = 0, next_revision_ = 1, saved_revision_ = 0;
};

/// Drops per-element K-gon controls whose element no longer exists (after a topology edit); all
/// of them after a remeshing, which renumbers every element.
void prune_kgon_controls(const HalfedgeMesh& mesh, KgonOptions& kgons, bool renumbered);

}  // namespace stitch::modeler
