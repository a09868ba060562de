#include "stitch/modeler/session.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>

#include "sort_unique.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/limits.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/project/project_file.hpp"
#include "stitch/tess/bezier_json.hpp"
#include "stitch/tess/export.hpp"
#include "stitch/tess/patches.hpp"
#include "stitch/topology/primitives.hpp"

namespace stitch::modeler {

namespace {

/// The line without a `# comment` ('#' after a blank or at the start; V@F#k keeps its '#').
std::string_view strip_comment(std::string_view line) {
  for (size_t i = 0; i < line.size(); ++i)
    if (line[i] == '#' && (i == 0 || std::isspace(static_cast<unsigned char>(line[i - 1]))))
      return line.substr(0, i);
  return line;
}

double number(const std::string& text, std::string_view what) {
  double v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc{} || end != text.data() + text.size() || !std::isfinite(v))
    throw UsageError(
        fmt::format("{} must be a finite number, not '{}'", what, limits::quoted(text)));
  return v;
}

int integer(const std::string& text, const std::string& what) {
  int v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc{} || end != text.data() + text.size())
    throw UsageError(fmt::format("{} must be an integer, not '{}'", what, limits::quoted(text)));
  return v;
}

void expect(const std::vector<std::string>& w, size_t min, size_t max, const char* usage) {
  if (w.size() - 1 < min || w.size() - 1 > max) throw UsageError(fmt::format("usage: {}", usage));
}

bool on_off(const std::string& text) {
  if (text == "on") return true;
  if (text == "off") return false;
  throw UsageError(fmt::format("expected on or off, not '{}'", limits::quoted(text)));
}

Vertex vertex_number(const HalfedgeMesh& m, const std::string& text) {
  const int n = integer(text, "a vertex number");
  if (n < 1 || n > m.vertex_capacity() || m.is_deleted(Vertex(n - 1)))
    throw UsageError(fmt::format("there is no vertex {}", limits::quoted(text)));
  return Vertex(n - 1);
}

/// The text after the first word, trimmed: a path may contain blanks.
std::string rest_after_first_word(std::string_view line) {
  size_t i = line.find_first_not_of(" \t");
  i = line.find_first_of(" \t", i);
  if (i == std::string_view::npos) return {};
  i = line.find_first_not_of(" \t", i);
  if (i == std::string_view::npos) return {};
  const size_t end = line.find_last_not_of(" \t\r");
  return std::string(line.substr(i, end - i + 1));
}

/// "X,Y,Z", as the command line writes points.
Vec3 offset_from(const std::string& text) {
  std::vector<std::string> parts;
  for (size_t start = 0;;) {
    const size_t comma = text.find(',', start);
    parts.push_back(text.substr(start, comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (parts.size() != 3)
    throw UsageError(fmt::format("the offset must be X,Y,Z, not '{}'", limits::quoted(text)));
  const Vec3 p(number(parts[0], "x"), number(parts[1], "y"), number(parts[2], "z"));
  limits::check_coordinates(p, "the offset");
  return p;
}

const char* const overlay_words[] = {"mesh", "kgons", "nets", "tess"};

/// Zoom steps in one command: 0.9^100 is a factor of 4e-5, more than any view needs at once.
constexpr double kMostZoomSteps = 100;

}  // namespace

Session::Session(HalfedgeMesh mesh) : document(std::move(mesh)) {
  rebuild();
  view.set_standard(View::iso, mesh_bounds(), view_aspect());
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
      surface.method() != Method::cc)
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
  problems_ = check_live_surface(document.mesh(), surface, all);
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
  display.method = Method::mdc;
  warning = why + "; showing mdc instead";
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

void open_file(Session& session, const std::string& path) {
  if (is_project_path(path)) {
    Project p = load_project(path);
    session.document = Document(std::move(p.state.mesh), std::move(p.state.kgons));
    session.view = p.view;
    session.display = p.display;
  } else {
    BuildOptions build;
    build.allow_two_gons = true;
    session.document = Document(read_mesh(path, build));
    session.view.set_standard(View::iso, BoundingBox{});
  }
  session.path = path;
  session.selection.reset();
  session.rebuild();
  if (!is_project_path(path))
    session.view.set_standard(View::iso, session.mesh_bounds(), session.view_aspect());
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
      session.warning =
          fmt::format("K-gon controls are not stored in {}; save as .stitch to keep them",
                      file_extension(path));
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

/// Writes the smooth surface as the session shows it (method, resolution, K-gon controls): a
/// tessellated mesh by extension, or the Bézier patches as JSON (docs/formats.md).
std::string export_surface(const Session& session, const std::string& path) {
  const HalfedgeMesh& mesh = session.document.mesh();
  const Method method = session.display.method;
  const Surface surface(mesh, method, session.document.kgon_options());
  const std::string ext = file_extension(path);
  if (ext == ".json") {
    const PatchSet set = bezier_patches(mesh, surface);
    write_bezier_json(path, set);
    return fmt::format("exported {} ({} Bezier patches, depth {}, method {})", path,
                       set.patches.size(), set.depth, to_string(method));
  }
  const SurfaceFileCounts counts =
      write_smooth_surface(path, mesh, surface, session.display.resolution);
  return fmt::format("exported {} ({} vertices, {} quads, method {}, resolution {})", path,
                     counts.vertices, counts.quads, to_string(method), session.display.resolution);
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

ScriptResult run_script_line(Session& s, std::string_view raw, const ScriptHooks& hooks) {
  const auto words = split_words(strip_comment(raw));
  const std::vector<std::string> w(words.begin(), words.end());
  ScriptResult result;
  if (w.empty()) return result;
  const std::string& cmd = w[0];
  const HalfedgeMesh& mesh = s.document.mesh();
  s.warning.clear();

  if (find_operation(cmd)) {
    OperationReport report;
    const Change c = s.document.apply_operation(raw, &report);
    s.apply_edit(c);
    std::string_view text = strip_comment(raw);
    text = text.substr(0, text.find_last_not_of(" \t\r") + 1);
    text = text.substr(std::min(text.size(), text.find_first_not_of(" \t")));
    result.message = report.summary(text);
    if (hooks.print) hooks.print(result.message);
    if (const auto& u = s.tube_unfoldings(); !u.empty()) {
      const std::string unfolded = describe_unfoldings(s.document.mesh(), u);
      result.message += "; " + unfolded;
      if (hooks.print) hooks.print(unfolded);
    }
    if (const SurfaceProblems& p = s.surface_problems(); !p.empty()) {
      result.message += "; " + p.summary();
      if (hooks.print) hooks.print("warning: " + describe_problems(s.document.mesh(), p));
    }
  } else if (cmd == "primitive") {
    expect(w, 1, 3, "primitive NAME [PARAMS]");
    std::vector<int> params;
    for (size_t i = 2; i < w.size(); ++i) params.push_back(integer(w[i], "a primitive parameter"));
    s.apply(s.document.replace({make_primitive(w[1], params), {}}, "primitive " + w[1]));
    s.view.set_standard(View::iso, s.mesh_bounds(), s.view_aspect());
    result.message = "new " + w[1];
  } else if (cmd == "move-vertex" || cmd == "translate-vertex") {
    expect(w, 4, 4, "move-vertex V X Y Z  or  translate-vertex V DX DY DZ");
    const Vertex v = vertex_number(mesh, w[1]);
    Vec3 p(number(w[2], "x"), number(w[3], "y"), number(w[4], "z"));
    if (cmd == "translate-vertex") p += mesh.position(v);
    limits::check_coordinates(p, fmt::format("{}: vertex {}", cmd, v.idx + 1));
    s.apply(s.document.move_vertices({v}, {p}));
    result.message = fmt::format("vertex {} moved; {} of {} patches recomputed in {:.2f} ms",
                                 v.idx + 1, s.last_update.recomputed_patches,
                                 s.surface.num_patches(), s.last_update.milliseconds);
  } else if (cmd == "select") {
    expect(w, 1, 3, "select vertex V | edge V W[@F] | face F | corner V@F | none");
    if (w[1] == "none") {
      expect(w, 1, 1, "select none");
      s.selection.reset();
      return result;
    }
    const PickKind kind = parse_pick_kind(w[1]);
    Pick p;
    p.kind = kind;
    if (kind == PickKind::edge) {
      expect(w, 3, 3, "select edge V W[@F]");
      const Edge e = parse_edge(mesh, w[2], w[3]);
      // The half-edge running from V, so the selection reads back as given.
      Halfedge h = HalfedgeMesh::halfedge(e, 0);
      if (mesh.origin(h) != vertex_number(mesh, w[2])) h = HalfedgeMesh::twin(h);
      p.index = h.idx;
    } else {
      expect(w, 2, 2, "select vertex V | face F | corner V@F");
      if (kind == PickKind::vertex) {
        p.index = vertex_number(mesh, w[2]).idx;
      } else if (kind == PickKind::corner) {
        p.index = parse_corner(mesh, w[2]).idx;
      } else {
        const int f = integer(w[2], "a face number");
        if (f < 1 || f > mesh.face_capacity() || mesh.is_deleted(Face(f - 1)))
          throw UsageError(fmt::format("there is no face {}", w[2]));
        p.index = f - 1;
      }
    }
    s.selection = p;
    result.message = "selected " + describe(mesh, p);
  } else if (cmd == "kgon") {
    size_t i = 1;
    std::optional<KgonTarget> target = kgon_target(s);
    if (w.size() > 1 && w[1] == "global") {
      target.reset();
      ++i;
    }
    const KgonTarget t = target.value_or(KgonTarget{});
    if (w.size() <= i)
      throw UsageError(
          "usage: kgon [global] scale S | rotate DEG | offset X Y Z | stretch S [X Y Z] | "
          "stretch_along X Y Z | regularize on|off | reset");
    KgonControl c = s.document.kgon_control(t);
    const std::string what = w[i] == "regularise" ? "regularize" : w[i];
    const size_t args = w.size() - i - 1;
    auto need = [&](size_t n) {
      if (args != n)
        throw UsageError(fmt::format("kgon {} takes {} value{}", what, n, n == 1 ? "" : "s"));
    };
    auto vector_at = [&](size_t first) {
      return Vec3(number(w[first], "x"), number(w[first + 1], "y"), number(w[first + 2], "z"));
    };
    const KgonControlField* field = find_kgon_control_field(what);
    if (what == "reset") {
      need(0);
      c = KgonControl{};
    } else if (what == "stretch" && args == 4) {  // the stretch and its direction in one line
      c.stretch = number(w[i + 1], field->description);
      c.stretch_along = vector_at(i + 2);
    } else if (field && field->kind == KgonControlField::Kind::number) {
      need(1);
      c.*field->number = number(w[i + 1], field->description);
    } else if (field && field->kind == KgonControlField::Kind::vector) {
      need(3);
      c.*field->vector = vector_at(i + 1);
    } else if (field) {
      need(1);
      c.*field->flag = on_off(w[i + 1]);
    } else {
      throw UsageError(
          fmt::format("unknown K-gon control '{}' ({}, reset)", what, kgon_control_field_names()));
    }
    check_kgon_control(c);
    s.apply(s.document.set_kgon_control(t, c));
    result.message = fmt::format("K-gon control set; {} patches recomputed in {:.2f} ms",
                                 s.last_update.recomputed_patches, s.last_update.milliseconds);
  } else if (cmd == "undo" || cmd == "redo") {
    expect(w, 0, 0, "undo  or  redo");
    s.apply(cmd == "undo" ? s.document.undo() : s.document.redo());
    result.message = cmd + " done";
  } else if (cmd == "method") {
    expect(w, 1, 1, "method mdc|asc|cc");
    const Method method = parse_method(w[1]);
    s.last_update = s.surface.set_method(s.document.mesh(), s.document.kgon_options(), method);
    s.display.method = method;
    s.check_surface_near({});  // the problems found, on the other method's patches
  } else if (cmd == "resolution") {
    expect(w, 1, 1, "resolution N");
    const int n = integer(w[1], "the resolution");
    limits::check_resolution(n, "the resolution");
    s.last_update = s.surface.set_resolution(s.document.mesh(), s.document.kgon_options(), n);
    s.display.resolution = n;
  } else if (cmd == "mode") {
    expect(w, 1, 1, "mode shaded|zebra|isophote|levels|patches|input");
    if (w[1] == "input") {
      s.display.input_polygons = true;
    } else {
      try {
        s.display.mode = parse_shading_mode(w[1]);
      } catch (const UsageError& e) {
        throw UsageError(std::string(e.what()) + " (or input)");
      }
      s.display.input_polygons = false;
    }
  } else if (cmd == "overlay") {
    expect(w, 2, 2, "overlay mesh|kgons|nets|tess|markers on|off");
    const bool on = on_off(w[2]);
    if (w[1] == "markers") {
      s.display.markers = on;
    } else {
      const auto* it = std::find(std::begin(overlay_words), std::end(overlay_words), w[1]);
      if (it == std::end(overlay_words))
        throw UsageError(
            fmt::format("unknown overlay '{}' (mesh, kgons, nets, tess, markers)", w[1]));
      s.display.overlays[it - std::begin(overlay_words)] = on;
    }
  } else if (cmd == "split") {
    expect(w, 1, 1, "split off|mdc|asc|cc");
    if (w[1] == "off") {
      s.display.split.reset();
    } else {
      try {
        s.display.split = parse_method(w[1]);
      } catch (const UsageError& e) {
        throw UsageError(std::string(e.what()) + " (or off)");
      }
    }
  } else if (cmd == "view") {
    expect(w, 1, 1, "view front|back|left|right|top|bottom|iso");
    s.view.set_standard(parse_view(w[1]), s.mesh_bounds(), s.view_aspect());
  } else if (cmd == "frame") {
    expect(w, 1, 1, "frame all|selection");
    if (w[1] == "all") {
      const BoundingBox b = s.mesh_bounds();
      if (!b.empty()) s.view.frame(b.center(), b.radius(), s.view_aspect());
    } else if (w[1] == "selection") {
      if (!s.selection) throw UsageError("frame selection: nothing is selected");
      s.view.frame(s.selection->point, 0.25 * s.mesh_bounds().radius(), s.view_aspect());
    } else {
      throw UsageError("usage: frame all|selection");
    }
  } else if (cmd == "orbit") {
    expect(w, 2, 2, "orbit DYAW DPITCH");
    const double yaw = number(w[1], "the yaw"), pitch = number(w[2], "the pitch");
    limits::check_range(yaw, -limits::max_rotation_deg, limits::max_rotation_deg, "the yaw");
    limits::check_range(pitch, -limits::max_rotation_deg, limits::max_rotation_deg, "the pitch");
    // Kept to one turn, so that no number of orbits loses the angle's precision.
    s.view.yaw_deg = std::remainder(s.view.yaw_deg + yaw, 360.0);
    s.view.pitch_deg = std::clamp(s.view.pitch_deg + pitch, -90.0, 90.0);
  } else if (cmd == "zoom") {
    expect(w, 1, 1, "zoom STEPS");
    const double steps = number(w[1], "the zoom steps");
    limits::check_range(steps, -kMostZoomSteps, kMostZoomSteps, "the zoom steps");
    s.view.zoom(steps);
  } else if (cmd == "screenshot") {
    const std::string path = rest_after_first_word(strip_comment(raw));
    if (path.empty()) throw UsageError("usage: screenshot PATH");
    if (!hooks.screenshot) throw UsageError("screenshot: not available here");
    hooks.screenshot(path);
    result.message = "wrote " + path;
  } else if (cmd == "save") {
    std::string path = rest_after_first_word(strip_comment(raw));
    if (path.empty()) path = s.path;
    if (path.empty()) throw UsageError("save: the document has no file yet; write save PATH");
    save_file(s, path);
    result.message = "saved " + path;
  } else if (cmd == "export") {
    const std::string path = rest_after_first_word(strip_comment(raw));
    if (path.empty())
      throw UsageError(fmt::format(
          "usage: export PATH (the smooth surface: {}; or .json for the Bezier patches)",
          extension_list(kSurfaceMeshExtensions)));
    result.message = export_surface(s, path);
  } else if (cmd == "append") {
    std::string path = rest_after_first_word(strip_comment(raw));
    Vec3 offset = Vec3::Zero();
    // `--offset X,Y,Z` closes the line, so the path before it may contain blanks.
    const auto parts = split_words(path);
    if (!parts.empty() && parts.back() == "--offset")
      throw UsageError("usage: append PATH [--offset X,Y,Z]");
    if (parts.size() >= 2 && parts[parts.size() - 2] == "--offset") {
      offset = offset_from(std::string(parts.back()));
      path.erase(path.find_last_not_of(" \t", path.rfind("--offset") - 1) + 1);
    }
    if (path.empty()) throw UsageError("usage: append PATH [--offset X,Y,Z]");
    result.message = append_file(s, path, offset);
  } else if (cmd == "open") {
    const std::string path = rest_after_first_word(strip_comment(raw));
    if (path.empty()) throw UsageError("usage: open PATH");
    open_file(s, path);
    result.message = "opened " + path;
  } else if (cmd == "info") {
    expect(w, 0, 0, "info");
    const TopologyStats t = topology_stats(mesh);
    result.message = fmt::format(
        "V {} E {} F {}, Euler {}, genus {}, components {}; method {}, {} patches, last update "
        "{:.2f} ms ({} patches)",
        t.vertices, t.edges, t.faces, t.euler, t.genus, t.components, to_string(s.display.method),
        s.surface.num_patches(), s.last_update.milliseconds, s.last_update.recomputed_patches);
    if (hooks.print) hooks.print(result.message);
  } else if (cmd == "check") {
    expect(w, 0, 0, "check");
    if (s.surface.method() == Method::cc)
      throw UsageError("check: the Catmull-Clark surface has no patches of its own to check");
    s.check_surface_near(s.surface.corners());  // every patch: a pass over the whole surface
    const SurfaceProblems& p = s.surface_problems();
    if (p.empty())
      result.message = fmt::format(
          "check: no folds or self-intersections ({} patches, {} triangles at resolution {}, "
          "{:.0f} ms)",
          p.checked_patches, p.triangles, kHealthResolution, p.milliseconds);
    else
      result.message = "check: " + describe_problems(mesh, p);
    if (hooks.print) hooks.print(result.message);
  } else if (cmd == "unfold-tubes") {
    expect(w, 1, 1, "unfold-tubes on|off");
    s.unfold_folding_tubes = on_off(w[1]);
    result.message = fmt::format("unfolding of folding tubes {}", w[1]);
  } else if (cmd == "quit" || cmd == "exit") {
    expect(w, 0, 0, "quit");
    result.quit = true;
  } else {
    throw UsageError(fmt::format(
        "unknown command '{}' (operations: {}; modeler: primitive, move-vertex, "
        "translate-vertex, select, kgon, undo, redo, method, resolution, mode, overlay, split, "
        "view, frame, orbit, zoom, screenshot, save, export, open, append, info, check, "
        "unfold-tubes, quit)",
        cmd, operation_names()));
  }
  if (!s.warning.empty()) {
    result.message = result.message.empty() ? s.warning : result.message + "; " + s.warning;
    if (hooks.print) hooks.print("warning: " + s.warning);
  }
  return result;
}

std::optional<ScriptError> run_script(Session& session, const std::vector<std::string>& lines,
                                      const ScriptHooks& hooks, bool* quit) {
  if (quit) *quit = false;
  for (size_t i = 0; i < lines.size(); ++i) {
    try {
      const ScriptResult r =
          hooks.run_line ? hooks.run_line(lines[i]) : run_script_line(session, lines[i], hooks);
      if (r.quit) {
        if (quit) *quit = true;
        return std::nullopt;
      }
    } catch (const Error& e) {
      return ScriptError{static_cast<int>(i) + 1, e.what()};
    }
  }
  return std::nullopt;
}

}  // namespace stitch::modeler
