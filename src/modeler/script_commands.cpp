#include "stitch/modeler/script_commands.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>

#include "stitch/mesh/limits.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/modeler/session.hpp"
#include "stitch/output/output.hpp"
#include "stitch/project/project_file.hpp"
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

void expect(const std::vector<std::string>& w, size_t min, size_t max, std::string_view usage) {
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

Vec3 vector_at(const std::vector<std::string>& w, size_t first) {
  return Vec3(number(w[first], "x"), number(w[first + 1], "y"), number(w[first + 2], "z"));
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
  const Vec3 p = vector_at(parts, 0);
  limits::check_coordinates(p, "the offset");
  return p;
}

/// "NAME a|b|c": the synopsis of a line that takes one name of `table`.
template <class T>
std::string choice_synopsis(std::string_view name, ChoiceTable<T> table) {
  return std::string(name) + " " + choice_names(table, "|");
}

/// Prints `text` where the application shows reports, and returns it as the line's message.
ScriptResult printed(std::string text, const ScriptHooks& hooks) {
  if (hooks.print) hooks.print(text);
  return {false, std::move(text)};
}

const char* const overlay_words[] = {"mesh", "kgons", "nets", "tess"};

/// Zoom steps in one command: 0.9^100 is a factor of 4e-5, more than any view needs at once.
constexpr double kMostZoomSteps = 100;

/// An operation line: applied as one undo step, its report (and what the edit's tubes and the
/// health check found) printed.
ScriptResult run_operation(Session& s, std::string_view raw, const ScriptLine& line,
                           const ScriptHooks& hooks, bool merge = false) {
  OperationReport report;
  const Change c = s.document.apply_operation(raw, &report, merge);
  s.apply_edit(c);
  std::string_view text = line.text;
  text = text.substr(0, text.find_last_not_of(" \t\r") + 1);
  text = text.substr(std::min(text.size(), text.find_first_not_of(" \t")));
  ScriptResult result = printed(report.summary(text), hooks);
  if (const auto& u = s.tube_unfoldings(); !u.empty()) {
    const std::string unfolded = describe_unfoldings(s.document.mesh(), u);
    result.message += "; " + unfolded;
    if (hooks.print) hooks.print(unfolded);
  }
  if (const SurfaceProblems& p = s.surface_problems(); !p.empty()) {
    result.message += "; " + p.summary();
    if (hooks.print)
      hooks.print("warning: " + describe_problems(s.surface.mesh(s.document.mesh()), p));
  }
  return result;
}

// The handlers, one per command (aliases share theirs and read the name they were given).

ScriptResult run_primitive(Session& s, const ScriptLine& line, const ScriptHooks&) {
  const auto& w = line.words;
  expect(w, 1, 3, "primitive NAME [PARAMS]");
  std::vector<int> params;
  for (size_t i = 2; i < w.size(); ++i) params.push_back(integer(w[i], "a primitive parameter"));
  s.apply(s.document.replace({make_primitive(w[1], params), {}}, "primitive " + w[1]));
  s.view.set_standard(View::iso, s.mesh_bounds(), s.view_aspect());
  return {false, "new " + w[1]};
}

ScriptResult run_move_vertex(Session& s, const ScriptLine& line, const ScriptHooks&) {
  const auto& w = line.words;
  const HalfedgeMesh& mesh = s.document.mesh();
  expect(w, 4, 4, "move-vertex V X Y Z  or  translate-vertex V DX DY DZ");
  const Vertex v = vertex_number(mesh, w[1]);
  Vec3 p = vector_at(w, 2);
  if (w[0] == "translate-vertex") p += mesh.position(v);
  limits::check_coordinates(p, fmt::format("{}: vertex {}", w[0], v.idx + 1));
  s.apply(s.document.move_vertices({v}, {p}));
  return {false, fmt::format("vertex {} moved; {} of {} patches recomputed in {:.2f} ms", v.idx + 1,
                             s.last_update.recomputed_patches, s.surface.num_patches(),
                             s.last_update.milliseconds)};
}

/// The element `select KIND ...` names, as a pick.
Pick pick_of(const HalfedgeMesh& mesh, const std::vector<std::string>& w) {
  Pick p;
  p.kind = parse_pick_kind(w[1]);
  if (p.kind == PickKind::edge) {
    expect(w, 3, 3, "select edge V W[@F]");
    const Edge e = parse_edge(mesh, w[2], w[3]);
    // The half-edge running from V, so the selection reads back as given.
    Halfedge h = HalfedgeMesh::halfedge(e, 0);
    if (mesh.origin(h) != vertex_number(mesh, w[2])) h = HalfedgeMesh::twin(h);
    p.index = h.idx;
    return p;
  }
  expect(w, 2, 2, "select vertex V | face F | corner V@F");
  if (p.kind == PickKind::vertex) {
    p.index = vertex_number(mesh, w[2]).idx;
  } else if (p.kind == PickKind::corner) {
    p.index = parse_corner(mesh, w[2]).idx;
  } else {
    const int f = integer(w[2], "a face number");
    if (f < 1 || f > mesh.face_capacity() || mesh.is_deleted(Face(f - 1)))
      throw UsageError(fmt::format("there is no face {}", w[2]));
    p.index = f - 1;
  }
  return p;
}

/// The selected edge's crease or vertex's corner sharpness, as the operation line `crease` or
/// `corner` sets it (checked, one undo step, kept in the mesh and its project). A tag edit
/// renumbers nothing: the selection stays, so that a field can set it again and again; `drag`
/// extends the last step when it set the same element's sharpness (a slider's drag).
ScriptResult run_sharpness(Session& s, const ScriptLine& line, const ScriptHooks& hooks) {
  expect(line.words, 1, 2, "sharpness S [drag]");
  if (line.words.size() == 3 && line.words[2] != "drag")
    throw UsageError(
        fmt::format("usage: sharpness S [drag], not '{}'", limits::quoted(line.words[2])));
  const std::optional<Pick> kept = s.selection;
  if (!kept || (kept->kind != PickKind::edge && kept->kind != PickKind::vertex))
    throw UsageError("sharpness: select an edge (its crease) or a vertex (its corner) first");
  const double value = number(line.words[1], "sharpness");
  const Operation op =
      kept->kind == PickKind::edge
          ? Operation(ops::SetCrease{HalfedgeMesh::edge(Halfedge(kept->index)), value})
          : Operation(ops::SetCorner{Vertex(kept->index), value});
  const std::string op_line = format_operation(s.document.mesh(), op);
  ScriptResult result =
      run_operation(s, op_line, read_script_line(op_line), hooks, line.words.size() == 3);
  s.selection = kept;
  return result;
}

ScriptResult run_select(Session& s, const ScriptLine& line, const ScriptHooks&) {
  const auto& w = line.words;
  expect(w, 1, 3, "select vertex V | edge V W[@F] | face F | corner V@F | none");
  if (w[1] == "none") {
    expect(w, 1, 1, "select none");
    s.selection.reset();
    return {};
  }
  s.selection = pick_of(s.document.mesh(), w);
  return {false, "selected " + describe(s.document.mesh(), *s.selection)};
}

/// `c` changed as `kgon [global] WHAT VALUES` says, the words from w[i] = WHAT on.
KgonControl changed_kgon_control(KgonControl c, const std::vector<std::string>& w, size_t i) {
  const std::string what = w[i] == "regularise" ? "regularize" : w[i];
  const size_t args = w.size() - i - 1;
  auto need = [&](size_t n) {
    if (args != n)
      throw UsageError(fmt::format("kgon {} takes {} value{}", what, n, n == 1 ? "" : "s"));
  };
  const KgonControlField* field = find_kgon_control_field(what);
  if (what == "reset") {
    need(0);
    c = KgonControl{};
  } else if (what == "stretch" && args == 4) {  // the stretch and its direction in one line
    c.stretch = number(w[i + 1], field->description);
    c.stretch_along = vector_at(w, i + 2);
  } else if (field && field->kind == KgonControlField::Kind::number) {
    need(1);
    c.*field->number = number(w[i + 1], field->description);
  } else if (field && field->kind == KgonControlField::Kind::vector) {
    need(3);
    c.*field->vector = vector_at(w, i + 1);
  } else if (field) {
    need(1);
    c.*field->flag = on_off(w[i + 1]);
  } else {
    throw UsageError(
        fmt::format("unknown K-gon control '{}' ({}, reset)", what, kgon_control_field_names()));
  }
  return c;
}

ScriptResult run_kgon(Session& s, const ScriptLine& line, const ScriptHooks&) {
  const auto& w = line.words;
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
  const KgonControl c = changed_kgon_control(s.document.kgon_control(t), w, i);
  check_kgon_control(c);
  s.apply(s.document.set_kgon_control(t, c));
  return {false, fmt::format("K-gon control set; {} patches recomputed in {:.2f} ms",
                             s.last_update.recomputed_patches, s.last_update.milliseconds)};
}

ScriptResult run_undo_redo(Session& s, const ScriptLine& line, const ScriptHooks&) {
  expect(line.words, 0, 0, "undo  or  redo");
  const std::string& cmd = line.words[0];
  s.apply(cmd == "undo" ? s.document.undo() : s.document.redo());
  return {false, cmd + " done"};
}

ScriptResult run_method(Session& s, const ScriptLine& line, const ScriptHooks&) {
  expect(line.words, 1, 1, choice_synopsis("method", method_table()));
  const Method method = parse_method(line.words[1]);
  s.last_update = s.surface.set_method(s.document.mesh(), s.document.kgon_options(), method);
  s.display.method = method;
  s.check_surface_near({});  // the problems found, on the other method's patches
  return {};
}

ScriptResult run_resolution(Session& s, const ScriptLine& line, const ScriptHooks&) {
  expect(line.words, 1, 1, "resolution N");
  const int n = integer(line.words[1], "the resolution");
  limits::check_resolution(n, "the resolution");
  s.last_update = s.surface.set_resolution(s.document.mesh(), s.document.kgon_options(), n);
  s.display.resolution = n;
  return {};
}

ScriptResult run_mode(Session& s, const ScriptLine& line, const ScriptHooks&) {
  expect(line.words, 1, 1, choice_synopsis("mode", display_mode_table()));
  set_display_mode(s.display, parse_choice(display_mode_table(), line.words[1], "display mode"));
  return {};
}

ScriptResult run_overlay(Session& s, const ScriptLine& line, const ScriptHooks&) {
  const auto& w = line.words;
  expect(w, 2, 2, "overlay mesh|kgons|nets|tess|markers on|off");
  const bool on = on_off(w[2]);
  if (w[1] == "markers") {
    s.display.markers = on;
    return {};
  }
  const auto* it = std::find(std::begin(overlay_words), std::end(overlay_words), w[1]);
  if (it == std::end(overlay_words))
    throw UsageError(fmt::format("unknown overlay '{}' (mesh, kgons, nets, tess, markers)", w[1]));
  s.display.overlays[it - std::begin(overlay_words)] = on;
  return {};
}

ScriptResult run_split(Session& s, const ScriptLine& line, const ScriptHooks&) {
  expect(line.words, 1, 1, choice_synopsis("split", split_table()));
  s.display.split = parse_choice(split_table(), line.words[1], "split view");
  return {};
}

ScriptResult run_view(Session& s, const ScriptLine& line, const ScriptHooks&) {
  expect(line.words, 1, 1, "view front|back|left|right|top|bottom|iso");
  s.view.set_standard(parse_view(line.words[1]), s.mesh_bounds(), s.view_aspect());
  return {};
}

ScriptResult run_up(Session& s, const ScriptLine& line, const ScriptHooks&) {
  expect(line.words, 1, 1, choice_synopsis("up", up_axis_table()));
  s.view.up = parse_choice(up_axis_table(), line.words[1], "up axis");
  return {};
}

ScriptResult run_frame(Session& s, const ScriptLine& line, const ScriptHooks&) {
  expect(line.words, 1, 1, "frame all|selection");
  if (line.words[1] == "all") {
    const BoundingBox b = s.mesh_bounds();
    if (!b.empty()) s.view.frame(b.center(), b.radius(), s.view_aspect());
  } else if (line.words[1] == "selection") {
    if (!s.selection) throw UsageError("frame selection: nothing is selected");
    s.view.frame(s.selection->point, 0.25 * s.mesh_bounds().radius(), s.view_aspect());
  } else {
    throw UsageError("usage: frame all|selection");
  }
  return {};
}

ScriptResult run_orbit(Session& s, const ScriptLine& line, const ScriptHooks&) {
  expect(line.words, 2, 2, "orbit DYAW DPITCH");
  const double yaw = number(line.words[1], "the yaw"), pitch = number(line.words[2], "the pitch");
  limits::check_range(yaw, -limits::max_rotation_deg, limits::max_rotation_deg, "the yaw");
  limits::check_range(pitch, -limits::max_rotation_deg, limits::max_rotation_deg, "the pitch");
  // Kept to one turn, so that no number of orbits loses the angle's precision.
  s.view.yaw_deg = std::remainder(s.view.yaw_deg + yaw, 360.0);
  s.view.pitch_deg = std::clamp(s.view.pitch_deg + pitch, -90.0, 90.0);
  return {};
}

ScriptResult run_zoom(Session& s, const ScriptLine& line, const ScriptHooks&) {
  expect(line.words, 1, 1, "zoom STEPS");
  const double steps = number(line.words[1], "the zoom steps");
  limits::check_range(steps, -kMostZoomSteps, kMostZoomSteps, "the zoom steps");
  s.view.zoom(steps);
  return {};
}

ScriptResult run_screenshot(Session&, const ScriptLine& line, const ScriptHooks& hooks) {
  const std::string path = line.rest();
  if (path.empty()) throw UsageError("usage: screenshot PATH");
  if (!hooks.screenshot) throw UsageError("screenshot: not available here");
  hooks.screenshot(path);
  return {false, "wrote " + path};
}

ScriptResult run_save(Session& s, const ScriptLine& line, const ScriptHooks&) {
  std::string path = line.rest();
  if (path.empty()) path = s.path;
  if (path.empty()) throw UsageError("save: the document has no file yet; write save PATH");
  save_file(s, path);
  return {false, "saved " + path};
}

/// `export`'s help: the formats of the table of output formats.
std::string export_help() {
  return "the smooth surface as shown (method, resolution, K-gon controls), in the format its "
         "extension names: " +
         output_extensions();
}

ScriptResult run_export(Session& s, const ScriptLine& line, const ScriptHooks& hooks) {
  const std::string path = line.rest();
  if (path.empty()) throw UsageError("usage: export PATH: " + export_help());
  return {false, export_surface(s, path, hooks.print)};
}

ScriptResult run_append(Session& s, const ScriptLine& line, const ScriptHooks&) {
  std::string path = line.rest();
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
  return {false, append_file(s, path, offset)};
}

ScriptResult run_open(Session& s, const ScriptLine& line, const ScriptHooks& hooks) {
  const std::string path = line.rest();
  if (path.empty()) throw UsageError("usage: open PATH");
  ScriptResult result{false, open_file(s, path)};
  // What the tube policy chose, printed as an operation's unfoldings are.
  if (const auto& u = s.tube_unfoldings(); !u.empty() && hooks.print)
    hooks.print(describe_unfoldings(s.document.mesh(), u));
  return result;
}

ScriptResult run_info(Session& s, const ScriptLine& line, const ScriptHooks& hooks) {
  expect(line.words, 0, 0, "info");
  const TopologyStats t = topology_stats(s.document.mesh());
  return printed(
      fmt::format("V {} E {} F {}, Euler {}, genus {}, components {}; method {}, {} patches, last "
                  "update {:.2f} ms ({} patches)",
                  t.vertices, t.edges, t.faces, t.euler, t.genus, t.components,
                  to_string(s.display.method), s.surface.num_patches(), s.last_update.milliseconds,
                  s.last_update.recomputed_patches),
      hooks);
}

ScriptResult run_check(Session& s, const ScriptLine& line, const ScriptHooks& hooks) {
  expect(line.words, 0, 0, "check");
  if (s.surface.method() == Method::cc)
    throw UsageError("check: the Catmull-Clark surface has no patches of its own to check");
  s.check_surface_near(s.surface.corners());  // every patch: a pass over the whole surface
  const SurfaceProblems& p = s.surface_problems();
  if (!p.empty())
    return printed("check: " + describe_problems(s.surface.mesh(s.document.mesh()), p), hooks);
  return printed(fmt::format("check: no folds or self-intersections ({} patches, {} triangles at "
                             "resolution {}, {:.0f} ms)",
                             p.checked_patches, p.triangles, kHealthResolution, p.milliseconds),
                 hooks);
}

ScriptResult run_unfold_tubes(Session& s, const ScriptLine& line, const ScriptHooks&) {
  expect(line.words, 1, 1, "unfold-tubes on|off");
  s.unfold_folding_tubes = on_off(line.words[1]);
  return {false, fmt::format("unfolding of folding tubes {}", line.words[1])};
}

ScriptResult run_quit(Session&, const ScriptLine& line, const ScriptHooks&) {
  expect(line.words, 0, 0, "quit");
  return {true, ""};
}

/// The names of `table`'s rows, comma-separated.
std::string names_of(std::span<const ScriptCommand> table) {
  std::string out;
  for (const ScriptCommand& c : table) out += (out.empty() ? "" : ", ") + std::string(c.name);
  return out;
}

/// Every line there is, by name, for the messages about a name that is none of them.
std::string known_commands(const ScriptHooks& hooks) {
  std::string out = fmt::format("operations: {}; modeler: {}", operation_names(),
                                names_of(script_command_table()));
  if (!hooks.commands.empty()) out += "; application: " + names_of(hooks.commands);
  return out;
}

/// A row of the listing: the synopsis, then the help in a column (below it after a long one).
std::string help_line(std::string_view synopsis, std::string_view help) {
  constexpr size_t kColumn = 34;
  if (synopsis.size() + 2 > kColumn)
    return fmt::format("  {}\n  {:{}}{}", synopsis, "", kColumn - 2, help);
  return fmt::format("  {:{}}{}", synopsis, kColumn - 2, help);
}

/// `help NAME`: the row named NAME, from whichever table has it.
ScriptResult help_on(const std::string& name, const ScriptHooks& hooks) {
  auto answer = [&](std::string_view synopsis, std::string_view help) {
    return printed(fmt::format("{}: {}", synopsis, help), hooks);
  };
  if (const OperationInfo* op = find_operation(name)) return answer(op->synopsis, op->summary);
  for (std::span<const ScriptCommand> table : {script_command_table(), std::span(hooks.commands)})
    if (const ScriptCommand* c = find_script_command(table, name))
      return answer(c->synopsis, c->help);
  throw UsageError(
      fmt::format("help: no line is named '{}' ({})", limits::quoted(name), known_commands(hooks)));
}

ScriptResult run_help(Session&, const ScriptLine& line, const ScriptHooks& hooks) {
  expect(line.words, 0, 1, "help [NAME]");
  if (line.words.size() == 2) return help_on(line.words[1], hooks);
  auto print = [&](const std::string& text) {
    if (hooks.print) hooks.print(text);
  };
  print("operations (as `stitch edit --ops` takes them, docs/editing.md):");
  for (const OperationInfo& op : operation_table()) print(help_line(op.synopsis, op.summary));
  print("modeler:");
  for (const ScriptCommand& c : script_command_table()) print(help_line(c.synopsis, c.help));
  if (!hooks.commands.empty()) print("application:");
  for (const ScriptCommand& c : hooks.commands) print(help_line(c.synopsis, c.help));
  return {false, "help: the script lines are printed; help NAME shows one"};
}

}  // namespace

std::string ScriptLine::rest() const {
  size_t i = text.find_first_not_of(" \t");
  i = text.find_first_of(" \t", i);
  if (i == std::string_view::npos) return {};
  i = text.find_first_not_of(" \t", i);
  if (i == std::string_view::npos) return {};
  const size_t end = text.find_last_not_of(" \t\r");
  return std::string(text.substr(i, end - i + 1));
}

ScriptLine read_script_line(std::string_view line) {
  ScriptLine l;
  l.text = strip_comment(line);
  for (std::string_view w : split_words(l.text)) l.words.emplace_back(w);
  return l;
}

std::span<const ScriptCommand> script_command_table() {
  // The order of `help` and of the unknown-command message; docs/modeler.md describes each row.
  // Built once: some synopses and helps read the library's tables.
  static const std::array<ScriptCommand, 29> table{{
      {"primitive", "primitive NAME [PARAMS]",
       "a new document from a primitive (cube, torus 8 6, ...); undoable", run_primitive},
      {"move-vertex", "move-vertex V X Y Z", "sets vertex V's position", run_move_vertex},
      {"translate-vertex", "translate-vertex V DX DY DZ", "moves vertex V by (DX, DY, DZ)",
       run_move_vertex},
      {"select", "select vertex V | edge V W[@F] | face F | corner V@F[#k] | none",
       "the selection, numbered as in operation lines", run_select},
      {"sharpness", "sharpness S [drag]",
       fmt::format("the selected edge's crease or vertex's corner sharpness: 0 smooth, {:g} or "
                   "more infinitely sharp, between semi-sharp (the operation crease or corner); "
                   "drag: part of the last undo step if that set this element's sharpness",
                   infinitely_sharp),
       run_sharpness},
      {"kgon",
       "kgon [global] scale S | rotate DEG | offset X Y Z | stretch S [X Y Z] | "
       "stretch_along X Y Z | regularize on|off | reset",
       "the K-gon control of the selection (a corner: its face's), or the global one with "
       "`global` or when nothing is selected",
       run_kgon},
      {"undo", "undo", "takes the last edit back", run_undo_redo},
      {"redo", "redo", "makes the edit undone last again", run_undo_redo},
      {"method", choice_synopsis("method", method_table()), "the surface's method", run_method},
      {"resolution", "resolution N", "segments per patch side", run_resolution},
      {"mode", choice_synopsis("mode", display_mode_table()), "the shading, or the input polygons",
       run_mode},
      {"overlay", "overlay mesh|kgons|nets|tess|markers on|off", "shows or hides an overlay",
       run_overlay},
      {"split", choice_synopsis("split", split_table()), "a side-by-side view with a second method",
       run_split},
      {"view", "view front|back|left|right|top|bottom|iso", "a standard view, the model framed",
       run_view},
      {"up", choice_synopsis("up", up_axis_table()),
       "the world axis shown up: the orbit turns about it and the views are its (saved in the "
       "project)",
       run_up},
      {"frame", "frame all|selection", "fits the model or the selection into the view", run_frame},
      {"orbit", "orbit DYAW DPITCH", "turns the camera by degrees", run_orbit},
      {"zoom", "zoom STEPS", "zooms in by steps (out when negative)", run_zoom},
      {"screenshot", "screenshot PATH", "the view as a PNG (where the application renders one)",
       run_screenshot},
      {"save", "save [PATH]",
       fmt::format("saves the project ({}) or the mesh, to PATH or to the document's file",
                   kProjectExtensions.front()),
       run_save},
      {"export", "export PATH", export_help(), run_export},
      {"open", "open PATH", "opens a mesh or a project", run_open},
      {"append", "append PATH [--offset X,Y,Z]",
       "adds a mesh or project as one more component, moved by the offset (one undo step)",
       run_append},
      {"info", "info", "prints the counts, genus, method and last update time", run_info},
      {"check", "check", "checks every patch for folds and self-intersections and prints them",
       run_check},
      {"unfold-tubes", "unfold-tubes on|off",
       "whether an edit that makes a folding tube chooses K-gon controls for it (on by default)",
       run_unfold_tubes},
      {"quit", "quit", "ends the script (and the application)", run_quit},
      {"exit", "exit", "the same as quit", run_quit},
      {"help", "help [NAME]", "lists the script lines, or the one named NAME", run_help},
  }};
  return table;
}

const ScriptCommand* find_script_command(std::span<const ScriptCommand> table,
                                         std::string_view name) {
  for (const ScriptCommand& c : table)
    if (c.name == name) return &c;
  return nullptr;
}

ScriptResult run_script_line(Session& s, std::string_view raw, const ScriptHooks& hooks) {
  const ScriptLine line = read_script_line(raw);
  if (line.words.empty()) return {};
  const std::string& name = line.words[0];
  s.warning.clear();
  ScriptResult result;
  if (find_operation(name))
    result = run_operation(s, raw, line, hooks);
  else if (const ScriptCommand* session_line = find_script_command(script_command_table(), name))
    result = session_line->run(s, line, hooks);
  else if (const ScriptCommand* app_line = find_script_command(hooks.commands, name))
    result = app_line->run(s, line, hooks);
  else
    throw UsageError(fmt::format("unknown command '{}' ({})", name, known_commands(hooks)));
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
