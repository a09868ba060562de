#include "stitch/modeler/session.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>

#include "sort_unique.hpp"
#include "stitch/analysis/build_surface.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/output/output.hpp"
#include "stitch/project/project_file.hpp"

namespace stitch::modeler {

Session::Session(HalfedgeMesh mesh) {
  load({std::move(mesh), {}});
  view.set_standard(View::iso, mesh_bounds(), view_aspect());
}

void Session::load(DocumentState state) {
  // build_surface's recipe, so that a document shows the surface `stitch smooth` writes for it.
  // Tubes are looked for on the mesh as it is: with semi-sharp tags to refine for, the live
  // surface is built on the refined mesh, whose faces no face control names.
  const auto start = std::chrono::steady_clock::now();
  const SurfaceSpec spec{display.method, std::move(state.kgons), unfold_folding_tubes};
  SurfaceKgons chosen = semi_sharp_refinement(state.mesh, spec).levels > 0
                            ? SurfaceKgons{spec.kgons, {}}
                            : surface_kgons(state.mesh, spec);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  document = Document(std::move(state.mesh), std::move(chosen.kgons));
  selection.reset();
  rebuild();
  unfoldings_ = std::move(chosen.tubes);
  if (!unfoldings_.empty()) {
    unfold_ms_ = ms;
    last_update.milliseconds += ms;
  }
}

void Session::remember(Change change) {
  constexpr size_t kMostKept = 64;
  if (untaken_.size() >= kMostKept) {
    untaken_.clear();
    change = whole_change();
  }
  untaken_.push_back(std::move(change));
}

Change Session::take_changes() {
  Change c = combined(untaken_);
  untaken_.clear();
  return c;
}

const SurfaceUpdateStats& Session::apply(const Change& change) {
  unfoldings_.clear();
  unfold_ms_ = 0.0;
  update_surface(change);
  check_after(change, surface.recomputed());
  return last_update;
}

void Session::update_surface(const Change& change) {
  earlier_blocks_.clear();
  remember(change);
  if (change.kind == Change::Kind::topology) selection.reset();
  try {
    last_update = surface.update(document.mesh(), document.kgon_options(), change);
  } catch (const Error& e) {
    fall_back_from_cc(e.what());
  }
}

void Session::check_after(const Change& change, const std::vector<Corner>& recomputed) {
  // Checked where the edit changed the surface, so its cost follows the edit; a full update
  // would make that the whole mesh, which `check` does on request.
  if (last_update.full)
    problems_ = {};
  else if (change.kind == Change::Kind::topology)
    check_surface_near(recomputed);
  else if (!problems_.empty())
    check_surface_near({});
}

const SurfaceUpdateStats& Session::apply_edit(const Change& change) {
  unfoldings_.clear();
  unfold_ms_ = 0.0;
  update_surface(change);
  std::vector<Face> tubes;
  if (unfold_folding_tubes && change.kind == Change::Kind::topology && !last_update.full &&
      surface.method() != Method::cc && surface.refined() == nullptr)
    tubes = faces_with_two_openings(document.mesh(), document.kgon_options(), change.faces);
  if (tubes.empty()) {
    check_after(change, surface.recomputed());
    return last_update;
  }
  const auto start = std::chrono::steady_clock::now();
  KgonOptions kgons = document.kgon_options();
  unfoldings_ = unfold_live_tubes(document.mesh(), kgons, surface, tubes);
  unfold_ms_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  last_update.milliseconds += unfold_ms_;
  std::vector<std::pair<KgonTarget, KgonControl>> controls;
  for (const TubeUnfolding& u : unfoldings_) {
    if (!u.unfolded()) continue;
    controls.emplace_back(KgonTarget{KgonKind::face, u.face.idx}, u.face_control);
    controls.emplace_back(KgonTarget{KgonKind::edge, u.bridge.idx}, u.bridge_control);
  }
  if (controls.empty()) {
    check_after(change, surface.recomputed());
    return last_update;
  }
  // The edit's surface, then the controls' K-gons on it: the renderer and the health check need
  // what both updates changed.
  const SurfaceUpdateStats first = last_update;
  std::vector<Corner> recomputed = surface.recomputed();
  std::vector<int> blocks = changed_blocks();
  update_surface(document.set_kgon_controls_in_last_edit(controls));
  recomputed.insert(recomputed.end(), surface.recomputed().begin(), surface.recomputed().end());
  detail::sort_unique(recomputed);
  earlier_blocks_ = std::move(blocks);
  last_update.full = first.full || last_update.full;
  last_update.layout_changed = first.layout_changed || last_update.layout_changed;
  last_update.candidate_patches += first.candidate_patches;
  last_update.recomputed_patches = static_cast<int>(recomputed.size());
  last_update.milliseconds += first.milliseconds;
  check_after(change, recomputed);
  return last_update;
}

std::vector<int> changed_blocks(const IncrementalSurface& surface) {
  std::vector<int> blocks = surface.relaid();
  for (Corner c : surface.recomputed()) blocks.push_back(c.idx);
  return blocks;
}

std::vector<int> Session::changed_blocks() const {
  std::vector<int> blocks = earlier_blocks_;
  const std::vector<int> last = stitch::modeler::changed_blocks(surface);
  blocks.insert(blocks.end(), last.begin(), last.end());
  return blocks;
}

void Session::check_surface_near(const std::vector<Corner>& corners) {
  std::vector<Corner> all = corners;
  all.insert(all.end(), problems_.corners.begin(), problems_.corners.end());
  problems_ = check_live_surface(surface.mesh(document.mesh()), surface, all);
}

void Session::rebuild() {
  remember(whole_change());
  problems_ = {};
  unfoldings_.clear();
  unfold_ms_ = 0.0;
  earlier_blocks_.clear();
  try {
    last_update = surface.rebuild(document.mesh(), document.kgon_options(), display.method,
                                  display.resolution);
  } catch (const Error& e) {
    fall_back_from_cc(e.what());
  }
}

void Session::fall_back_from_cc(const std::string& why) {
  // Only the Catmull-Clark method can refuse a mesh (should OpenSubdiv reject its topology or
  // give a face no limit surface); the edit stands and the display switches to the paper's
  // method.
  if (display.method != Method::cc) throw UsageError(why);
  display.method = method_table().front().value;
  warning = fmt::format("{}; showing {} instead", why, to_string(display.method));
  last_update =
      surface.rebuild(document.mesh(), document.kgon_options(), display.method, display.resolution);
}

double Session::view_aspect() const {
  const double width = display.split ? viewport_width / 2 : viewport_width;
  return width / std::max(viewport_height, 1e-9);
}

BoundingBox Session::mesh_bounds() const {
  BoundingBox box;
  for (Vertex v : document.mesh().vertices()) box.extend(document.mesh().position(v));
  return box;
}

Project Session::project() const {
  return {document.state(), view, display};
}

std::string open_file(Session& session, const std::string& path) {
  const bool project = is_project_path(path);
  DocumentState state;
  BuildReport report;
  if (project) {
    Project p = load_project(path);
    state = std::move(p.state);
    session.view = p.view;
    session.display = p.display;  // the project's method is the request's
  } else {
    BuildOptions build;
    build.allow_two_gons = true;
    state.mesh = read_mesh(path, build, &report);
  }
  session.path = path;
  session.load(std::move(state));
  if (!project) session.view.set_standard(View::iso, session.mesh_bounds(), session.view_aspect());
  std::string message = "opened " + path;
  // What reading repaired (repair.hpp), one line per kind, as the command line warns.
  for (const std::string& line : report.repair.summary()) message += "; repaired: " + line;
  if (const auto& u = session.tube_unfoldings(); !u.empty())
    message += "; " + describe_unfoldings(session.document.mesh(), u);
  if (session.surface.refinement().levels > 0)
    message += "; " + session.surface.refinement().summary();
  return message;
}

void save_file(Session& session, const std::string& path) {
  bool lost = false;
  if (is_project_path(path)) {
    save_project(path, session.project());
  } else {
    write_mesh(path, session.document.mesh());
    const KgonOptions& k = session.document.kgon_options();
    lost = !k.face.empty() || !k.vertex.empty() || !k.edge.empty() || k.global != KgonControl{};
    if (lost)
      session.warning = fmt::format("K-gon controls are not stored in {}; save as {} to keep them",
                                    file_extension(path), kProjectExtensions.front());
  }
  session.path = path;
  // Unless the file holds everything: then the document still differs from every file.
  if (!lost) session.document.mark_saved();
}

std::string append_file(Session& session, const std::string& path, const Vec3& offset) {
  HalfedgeMesh mesh;
  KgonOptions kgons;
  if (is_project_path(path)) {
    ProjectFile p = read_project_file(path);
    mesh = std::move(p.mesh);
    kgons = std::move(p.kgons);
  } else {
    BuildOptions build;
    build.allow_two_gons = true;
    mesh = read_mesh(path, build);
  }
  const HalfedgeMesh& m = session.document.mesh();
  const int v0 = m.vertex_capacity(), f0 = m.face_capacity();
  session.apply_edit(session.document.append(mesh, kgons, offset, "append " + path));
  const int v1 = m.vertex_capacity(), f1 = m.face_capacity();
  std::string message =
      fmt::format("appended {}: vertices {} to {}, faces {} to {}", path, v0 + 1, v1, f0 + 1, f1);
  if (const auto& u = session.tube_unfoldings(); !u.empty())
    message += "; " + describe_unfoldings(m, u);
  return message;
}

std::string export_surface(const Session& session, const std::string& path,
                           const std::function<void(const std::string&)>& note) {
  OutputSpec spec;
  spec.resolution = session.display.resolution;
  spec.note = note;
  check_output(path, spec);  // an unknown extension before the surface is built for nothing
  const HalfedgeMesh& mesh = session.document.mesh();
  // The shown surface's recipe: the tubes' controls are the document's already.
  const BuiltSurface built =
      build_surface(mesh, {session.display.method, session.document.kgon_options(), false});
  return fmt::format("exported {} ({})", path, write_surface(path, mesh, built, spec).summary);
}

std::optional<KgonTarget> kgon_target(const Session& s) {
  if (!s.selection) return std::nullopt;
  const Pick& p = *s.selection;
  const HalfedgeMesh& m = s.document.mesh();
  switch (p.kind) {
    case PickKind::face:
      return KgonTarget{KgonKind::face, p.index};
    case PickKind::vertex:
      return KgonTarget{KgonKind::vertex, p.index};
    case PickKind::edge:
      return KgonTarget{KgonKind::edge, HalfedgeMesh::edge(Halfedge(p.index)).idx};
    case PickKind::corner:
      return KgonTarget{KgonKind::face, m.face(Halfedge(p.index)).idx};
  }
  return std::nullopt;
}

}  // namespace stitch::modeler
