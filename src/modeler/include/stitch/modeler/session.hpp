// A modeler session without a window: the document, its file, the view, the display settings,
// the selection and the live surface; and the script language that drives it (`--script`), which
// the GUI's buttons also use, so both do exactly the same thing. The script lines are the rows of
// script_command_table() and the operation table (script_commands.hpp); `help` lists them.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "stitch/modeler/document.hpp"
#include "stitch/modeler/navigation.hpp"
#include "stitch/modeler/project.hpp"
#include "stitch/modeler/script_commands.hpp"
#include "stitch/modeler/surface_health.hpp"
#include "stitch/tess/incremental_surface.hpp"

namespace stitch::modeler {

/// The tessellation blocks (slots) the surface's last update changed, for a renderer to upload
/// again: its relaid() slots and its recomputed() patches.
std::vector<int> changed_blocks(const IncrementalSurface& surface);

struct Session {
  Document document;
  std::string path;  ///< the document's file; empty when untitled
  OrbitView view;
  DisplaySettings display;
  std::optional<Pick> selection;
  IncrementalSurface surface;
  SurfaceUpdateStats last_update;
  /// Set when the last line could not show its method (cc refused the mesh), else empty.
  std::string warning;
  /// The size of the area the model is drawn in (the application keeps it current), so that
  /// framing fits the model between the panels.
  double viewport_width = 1.0, viewport_height = 1.0;
  /// Width / height of one view: the viewport, or half of it in a split view.
  [[nodiscard]] double view_aspect() const;

  /// A session on `mesh` (load), framed in the iso view.
  explicit Session(HalfedgeMesh mesh = {});
  /// Whether a document loaded (load) or a new topology edit (apply_edit) unfolds its tubes whose
  /// fitted K-gons fold (`unfold-tubes on|off`): build_surface's SurfaceSpec::unfold_tubes.
  bool unfold_folding_tubes = true;

  /// Makes `state` the document, with a fresh history and nothing selected, and builds its
  /// surface as build_surface builds the request (display.method, the state's K-gon controls,
  /// unfold_folding_tubes): the controls surface_kgons chooses for tubes whose fitted K-gons fold
  /// join the document's controls, since they are what is shown (a project saved then keeps them,
  /// and `stitch smooth` on it builds the same surface), and tube_unfoldings() tells what was
  /// chosen. The document counts as unmodified: its file gives it again.
  void load(DocumentState state);

  /// Brings the surface up to date after a document change; returns (and keeps) the stats.
  const SurfaceUpdateStats& apply(const Change& change);
  /// The same after a topology edit just made (an operation or an append, not an undo or redo,
  /// which bring back what the step holds): with unfold_folding_tubes, where the faces it touched
  /// include tubes whose surface folds, chooses K-gon controls for them (unfold_live_tubes) and
  /// adds them to the edit's undo step, so the surface shown and checked is the unfolded one.
  /// The stats cover both updates of the surface then.
  const SurfaceUpdateStats& apply_edit(const Change& change);
  /// What the last load or apply_edit found for the folding tubes (empty after any other
  /// update).
  [[nodiscard]] const std::vector<TubeUnfolding>& tube_unfoldings() const { return unfoldings_; }
  /// The wall time of the last load's or apply_edit's search for tube controls (0 when it had no
  /// tube).
  [[nodiscard]] double unfold_milliseconds() const { return unfold_ms_; }
  /// The tessellation blocks (slots, as the surface numbers them) the last update changed, for a
  /// renderer to upload again: the surface's relaid() and recomputed() ones, and after an edit
  /// whose tubes were unfolded, which updates the surface twice, those of the first update too.
  [[nodiscard]] std::vector<int> changed_blocks() const;
  /// The document changes since the last call, for a second surface that follows the document
  /// (the split view): combined() of them, or whole after a rebuild. Kind none if there were
  /// none.
  Change take_changes();
  /// Rebuilds the surface from scratch (after replacing the document or the method).
  void rebuild();
  /// The bounding box of the live input vertices.
  [[nodiscard]] BoundingBox mesh_bounds() const;
  /// The project as it stands (for saving and autosaving).
  [[nodiscard]] Project project() const;
  /// Folds and self-intersections of the surface near the edits (surface_health.hpp): checked
  /// after every topology edit on the patches it recomputed; a move or K-gon edit re-checks only
  /// the patches already found; a rebuild (remeshing, new document) clears it, as `check` finds
  /// them on the whole surface again.
  [[nodiscard]] const SurfaceProblems& surface_problems() const { return problems_; }
  /// Checks `corners` and the patches of the problems found before, with their neighbours, and
  /// keeps the result as surface_problems().
  void check_surface_near(const std::vector<Corner>& corners);

 private:
  void fall_back_from_cc(const std::string& why);
  /// apply() up to the health check.
  void update_surface(const Change& change);
  /// The health check after `change` (apply), on the patches `recomputed`.
  void check_after(const Change& change, const std::vector<Corner>& recomputed);
  SurfaceProblems problems_;
  std::vector<TubeUnfolding> unfoldings_;
  double unfold_ms_ = 0.0;
  std::vector<int> earlier_blocks_;  ///< the first update's changed blocks (changed_blocks)
  /// Changes not yet taken; after many, one whole change stands for them all.
  std::vector<Change> untaken_;
  void remember(Change change);
};

/// Opens a mesh (OBJ/OFF/PLY) or project file into the session (Session::load, with the
/// project's display settings): a fresh history, the view framed (or the project's). Returns what
/// was opened and the tubes the policy unfolded (describe_unfoldings). Throws stitch::Error.
std::string open_file(Session& session, const std::string& path);
/// Saves the project (.stitch/.json) or the mesh (.obj/.off/.ply/.stl), atomically; the path
/// becomes the document's. Throws stitch::Error. A mesh file has no place for K-gon controls: with
/// any set, session.warning says so and the document stays modified (its autosave keeps them).
void save_file(Session& session, const std::string& path);
/// Adds the mesh or project at `path` to the document as one more component moved by `offset`
/// (Document::append), one undo step. Returns what was added. Throws stitch::Error.
std::string append_file(Session& session, const std::string& path, const Vec3& offset);
/// Writes the smooth surface as the session shows it (method, resolution, K-gon controls) through
/// write_surface, in the format of the table of output formats that the extension names
/// (tessellated meshes, Bézier JSON, STEP, IGES). `note` gets the writer's notes (an exact
/// format's depth and deviations). Returns what was written. Throws stitch::Error, the table's
/// message for an unknown extension or an exact format of the cc surface.
std::string export_surface(const Session& session, const std::string& path,
                           const std::function<void(const std::string&)>& note = {});

/// The selected K-gon, if the selection has one (a corner selects its face's).
std::optional<KgonTarget> kgon_target(const Session& session);

}  // namespace stitch::modeler
