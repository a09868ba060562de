#include "panels.hpp"

#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "commands.hpp"
#include "file_dialog.hpp"
#include "stitch/topology/operation.hpp"
#include "stitch/topology/primitives.hpp"
#include "viewport.hpp"
#include "widgets.hpp"

namespace stitch::modeler::app {

namespace {

constexpr const char* kPickKinds[] = {"vertex", "edge", "face", "corner"};
constexpr const char* kDragTools[] = {"view plane", "x", "y", "z"};
constexpr const char* kKgonKinds[] = {"face", "vertex", "edge"};
constexpr const char* kOverlays[] = {"mesh", "kgons", "nets", "tess"};

/// A combo over the names of `table` showing the row of `current`; the row chosen, if one was.
template <class T>
const Choice<T>* choice_combo(Widgets& ui, const char* label, ChoiceTable<T> table,
                              const T& current) {
  // ImGui takes C strings; the table's names are views.
  std::vector<std::string> names;
  int index = 0;
  for (const Choice<T>& c : table) {
    if (c.value == current) index = int(names.size());
    names.emplace_back(c.name);
  }
  std::vector<const char*> items;
  for (const std::string& n : names) items.push_back(n.c_str());
  if (!ui.combo(label, &index, items.data(), int(items.size()))) return nullptr;
  return &table[index];
}

/// `command NAME`, for the row a combo chose.
template <class T>
std::string line_of(std::string_view command, const Choice<T>& row) {
  return fmt::format("{} {}", command, row.name);
}

void picking_section(App& app, Widgets& ui) {
  const Session& s = app.session;
  const HalfedgeMesh& m = s.document.mesh();
  ui.text("Pick (click in the view):");
  for (int k = 0; k < 4; ++k) {
    if (k) ImGui::SameLine();
    if (ui.radio(kPickKinds[k], app.picking.kind == PickKind(k))) app.picking.kind = PickKind(k);
  }
  ui.text("Selected: " + (s.selection ? describe(m, *s.selection) : std::string("nothing")));
  if (app.picking.previous) ui.text("Previous: " + describe(m, *app.picking.previous));
}

void operators_section(App& app, Widgets& ui) {
  Session& s = app.session;
  const HalfedgeMesh& m = s.document.mesh();
  const std::optional<Pick>& sel = s.selection;
  const std::optional<Pick>& prev = app.picking.previous;
  // The picks make typed operations; a button runs its operation's line (what the history and
  // scripts see). The local operators' can_* checks cost the degree of the elements, so they
  // enable the buttons every frame and give the refusal as a tooltip; delete-face, open-face and
  // the remeshings can take a pass over the mesh, so those are only tried when clicked (the
  // refusal then goes to the status bar).
  enum class Check { every_frame, on_click };
  auto op_button = [&](const char* label, const std::optional<Operation>& op, Check check) {
    const Verdict verdict = op && check == Check::every_frame ? can_apply(m, *op) : Verdict{};
    if (ui.button(label, op && verdict.applies())) run_line(app, format_operation(m, *op));
    if (!verdict.refusal().empty() && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
      ImGui::SetTooltip("%s", verdict.refusal().c_str());
  };
  auto row_label = [&](const char* text) {
    ImGui::AlignTextToFramePadding();
    ui.text(text);
    ImGui::SameLine(ems(4.5f));
  };
  auto picked = [&](const std::optional<Pick>& p, PickKind kind) { return p && p->kind == kind; };
  ui.text_disabled("Two picks: from the previous to the selected");
  std::optional<Operation> insert, connect;
  if (picked(sel, PickKind::corner) && picked(prev, PickKind::corner))
    insert = ops::InsertEdge{Corner(prev->index), Corner(sel->index)};
  if (picked(sel, PickKind::face) && picked(prev, PickKind::face)) {
    HandleOptions handle;
    if (!app.fields.connect_least_twist) handle.twist = app.fields.connect_twist;
    connect = ops::ConnectFaces{Face(prev->index), Face(sel->index), handle};
  }
  op_button("Insert edge", insert, Check::every_frame);
  ImGui::SameLine();
  op_button("Connect faces", connect, Check::every_frame);
  ImGui::SameLine();
  ui.checkbox("least twist", &app.fields.connect_least_twist);
  if (!app.fields.connect_least_twist) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ems(5.5f));
    ui.input_int("twist", &app.fields.connect_twist);
  }

  row_label("Edge:");
  const bool edge = picked(sel, PickKind::edge);
  const Halfedge h = edge ? Halfedge(sel->index) : Halfedge();
  const Edge e = edge ? HalfedgeMesh::edge(h) : Edge();
  auto on_edge = [&](auto op) { return edge ? std::optional<Operation>(op) : std::nullopt; };
  op_button("Delete##edge", on_edge(ops::DeleteEdge{e}), Check::every_frame);
  ImGui::SameLine();
  op_button("Subdivide", on_edge(ops::SubdivideEdge{e}), Check::every_frame);
  ImGui::SameLine();
  op_button("Collapse", on_edge(ops::CollapseEdge{e, edge ? m.origin(h) : Vertex()}),
            Check::every_frame);
  ImGui::SameLine();
  // Sharp features: an infinitely sharp crease (OpenSubdiv's 10) or none; a vertex corner.
  const bool sharp_edge = edge && m.sharpness(e) > 0;
  op_button(sharp_edge ? "Smooth##edge" : "Crease",
            on_edge(ops::SetCrease{e, sharp_edge ? 0.0 : infinitely_sharp}), Check::every_frame);
  // Any sharpness, live, on a row of its own (the panel keeps its width): the script line
  // `sharpness S`, which keeps the edge selected.
  row_label("Crease:");
  ImGui::SetNextItemWidth(ems(12.0f));
  ImGui::BeginDisabled(!edge);
  float sharpness = edge ? static_cast<float>(m.sharpness(e)) : 0.0f;
  if (ui.slider("##edge sharpness", &sharpness, 0.0f, static_cast<float>(infinitely_sharp)) &&
      edge) {
    // One undo step per drag: the drag's first change makes it, the others extend it.
    const bool drag = ImGui::IsItemActive() && !ImGui::IsItemActivated();
    run_line(app, fmt::format("sharpness {:g}{}", sharpness, drag ? " drag" : ""));
  }
  ImGui::EndDisabled();

  row_label("Vertex:");
  const bool vertex = picked(sel, PickKind::vertex);
  const bool corner_vertex = vertex && m.sharpness(Vertex(sel->index)) > 0;
  op_button(corner_vertex ? "Smooth##vertex" : "Corner",
            vertex ? std::optional<Operation>(
                         ops::SetCorner{Vertex(sel->index), corner_vertex ? 0.0 : infinitely_sharp})
                   : std::nullopt,
            Check::every_frame);

  row_label("Face:");
  const bool face = picked(sel, PickKind::face);
  const Face f = face ? Face(sel->index) : Face();
  auto on_face = [&](auto op) { return face ? std::optional<Operation>(op) : std::nullopt; };
  op_button("Extrude", on_face(ops::ExtrudeFace{f, app.fields.extrude_distance, 1.0}),
            Check::every_frame);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(ems(6.5f));
  ImGui::InputDouble("##distance", &app.fields.extrude_distance, 0.1, 0.5, "%.2f");
  ImGui::SameLine();
  op_button("Delete##face", on_face(ops::DeleteFace{f}), Check::on_click);
  const bool hole = face && m.is_hole(f);
  ImGui::SameLine();
  if (hole)
    op_button("Fill hole", on_face(ops::FillHole{f}), Check::every_frame);
  else
    op_button("Open", on_face(ops::OpenFace{f}), Check::on_click);

  row_label("Remesh:");
  auto remesh_button = [&](Remeshing scheme) {
    op_button(remeshing_name(scheme), ops::Remesh{scheme}, Check::on_click);
  };
  remesh_button(Remeshing::doo_sabin);
  ImGui::SameLine();
  remesh_button(Remeshing::vertex_insertion);
  ImGui::SetCursorPosX(ems(4.5f));  // under the row's first button
  remesh_button(Remeshing::catmull_clark);
  ImGui::SameLine();
  remesh_button(Remeshing::dual);

  const auto names = primitive_names();
  int& chosen = app.fields.primitive_index;
  chosen = std::clamp(chosen, 0, int(names.size()) - 1);
  ImGui::SetNextItemWidth(ems(8));
  if (ImGui::BeginCombo("##primitive", names[chosen].c_str())) {
    for (int i = 0; i < int(names.size()); ++i)
      if (ImGui::Selectable(names[i].c_str(), i == chosen)) chosen = i;
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  if (ui.button("New from primitive")) run_line(app, "primitive " + names[chosen]);
}

void kgon_section(App& app, Widgets& ui) {
  Session& s = app.session;
  const auto target = kgon_target(s);
  ui.checkbox("global (all extraordinary K-gons)", &app.fields.kgon_global);
  const bool use_global = app.fields.kgon_global || !target;
  const KgonTarget t = use_global ? KgonTarget{} : *target;
  ui.text("Editing: " +
          (use_global ? std::string("global control")
                      : fmt::format("K-gon of {} {}", kKgonKinds[int(t.kind)], t.element + 1)));
  KgonControl c = s.document.kgon_control(t);
  float scale = float(c.scale), rotate = float(c.rotate_deg), stretch = float(c.stretch);
  float offset[3] = {float(c.offset.x()), float(c.offset.y()), float(c.offset.z())};
  bool regular = c.regularize;
  bool changed = false, merge = false;
  // A drag that goes on extends the undo step it started.
  changed |= ui.slider("size", &scale, 0.05f, 2.0f);
  merge |= ImGui::IsItemActive() && !ImGui::IsItemActivated();
  changed |= ui.slider("rotation", &rotate, -180.0f, 180.0f);
  merge |= ImGui::IsItemActive() && !ImGui::IsItemActivated();
  changed |= ui.drag3("offset", offset, 0.01f);
  merge |= ImGui::IsItemActive() && !ImGui::IsItemActivated();
  // The stretch's direction is set by script (`kgon stretch S X Y Z`) or by the tube search;
  // the slider only changes its amount.
  if (c.stretch_along != Vec3::Zero()) {
    changed |= ui.slider("stretch", &stretch, 0.25f, 4.0f);
    merge |= ImGui::IsItemActive() && !ImGui::IsItemActivated();
  }
  changed |= ui.checkbox("regularise", &regular);
  if (ui.button("Reset")) {
    scale = 1, rotate = 0, stretch = 1, offset[0] = offset[1] = offset[2] = 0, regular = false;
    c.stretch_along = Vec3::Zero();
    changed = true;
  }
  bool unfold = s.unfold_folding_tubes;
  if (ui.checkbox("unfold folding tubes", &unfold))
    run_line(app, fmt::format("unfold-tubes {}", unfold ? "on" : "off"));
  if (!changed) return;
  KgonControl n = c;
  n.scale = scale;
  n.rotate_deg = rotate;
  n.offset = Vec3(offset[0], offset[1], offset[2]);
  n.regularize = regular;
  n.stretch = stretch;
  try {
    s.apply(s.document.set_kgon_control(t, n, merge));
    app.status = fmt::format("K-gon updated: {} patches in {:.2f} ms",
                             s.last_update.recomputed_patches, s.last_update.milliseconds);
    after_change(app, s.last_update.full);
  } catch (const std::exception& e) {
    app.status = e.what();
  }
}

/// The panels' flags: each sized to its content, in its place beside the 3D view.
constexpr ImGuiWindowFlags kPanelFlags = ImGuiWindowFlags_AlwaysAutoResize |
                                         ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                         ImGuiWindowFlags_NoSavedSettings;

/// Places the next panel at the top of the area between the menu bar and the status bar, at
/// the left (pivot 0) or the right (pivot 1), no taller than that area (it scrolls then).
void place_panel(const ScreenRect& area, float pivot_x) {
  ImGui::SetNextWindowPos(ImVec2(pivot_x > 0 ? area.x1 : area.x0, area.y0), ImGuiCond_Always,
                          ImVec2(pivot_x, 0));
  ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(area.width(), area.height()));
}

void edit_panel(App& app, Widgets& ui, const ScreenRect& area) {
  place_panel(area, 0);
  ImGui::Begin("Edit", nullptr, kPanelFlags);
  picking_section(app, ui);
  if (ui.header("Operators", ImGuiTreeNodeFlags_DefaultOpen)) operators_section(app, ui);
  if (ui.header("Move vertices", ImGuiTreeNodeFlags_DefaultOpen)) {
    ui.text("Ctrl + left drag moves the selected vertex");
    for (int t = 0; t < 4; ++t) {
      if (t) ImGui::SameLine();
      if (ui.radio(kDragTools[t], app.mouse.tool == DragTool(t))) app.mouse.tool = DragTool(t);
    }
  }
  if (ui.header("K-gons", ImGuiTreeNodeFlags_DefaultOpen)) kgon_section(app, ui);
  if (ui.header("Command line")) {
    ui.text("Any script line (stitch edit --ops lines too):");
    auto& line = app.fields.command_line;
    if (ImGui::InputText("##command", line.data(), line.size(),
                         ImGuiInputTextFlags_EnterReturnsTrue)) {
      run_line(app, line.data());
      line[0] = '\0';
    }
  }
  record_panel(app.layout);
  ImGui::End();
}

void display_panel(App& app, Widgets& ui, const ScreenRect& area) {
  const Session& s = app.session;
  place_panel(area, 1);
  ImGui::Begin("Display", nullptr, kPanelFlags);
  if (const auto* row = choice_combo(ui, "method", method_table(), s.display.method))
    run_line(app, line_of("method", *row));
  if (const auto* row = choice_combo(ui, "split with", split_table(), s.display.split))
    run_line(app, line_of("split", *row));
  int resolution = s.display.resolution;
  if (ui.slider("resolution", &resolution, 1, 32) && resolution != s.display.resolution)
    run_line(app, fmt::format("resolution {}", resolution));
  if (const auto* row = choice_combo(ui, "mode", display_mode_table(), display_mode(s.display)))
    run_line(app, line_of("mode", *row));
  for (int o = 0; o < num_overlays; ++o) {
    bool on = s.display.overlays[o];
    if (o) ImGui::SameLine();
    if (ui.checkbox(kOverlays[o], &on))
      run_line(app, fmt::format("overlay {} {}", kOverlays[o], on ? "on" : "off"));
  }
  bool markers = s.display.markers;
  if (ui.checkbox("extraordinary points", &markers))
    run_line(app, fmt::format("overlay markers {}", markers ? "on" : "off"));
  ImGui::Separator();
  if (const auto* row = choice_combo(ui, "up axis", up_axis_table(), s.view.up))
    run_line(app, line_of("up", *row));
  for (int v = 0; v <= static_cast<int>(View::iso); ++v) {
    if (v != 0 && v != 4) ImGui::SameLine();  // two rows: the sides, then top, bottom, iso
    const std::string name = to_string(static_cast<View>(v));
    if (ui.button(name.c_str())) run_line(app, "view " + name);
  }
  if (ui.button("Frame all")) run_line(app, "frame all");
  ImGui::SameLine();
  if (ui.button("Frame selection")) run_line(app, "frame selection");
  ImGui::Separator();
  if (ui.header("History")) {
    // Steps name their files, which may be long: shortened to the panel's usual width.
    const float width = ems(20);
    for (const std::string& l : s.document.undo_labels()) {
      const std::string shown = elided(l, width);
      ImGui::BulletText("%s", shown.c_str());
      record_label(app.layout, shown);
    }
    const auto redo = s.document.redo_labels();
    for (auto it = redo.rbegin(); it != redo.rend(); ++it)
      ui.text_disabled("  " + elided(*it, width));
  }
  record_panel(app.layout);
  ImGui::End();
}

void menu_bar(App& app, Widgets& ui) {
  Session& s = app.session;
  if (!ImGui::BeginMainMenuBar()) return;
  if (ImGui::BeginMenu("File")) {
    if (ImGui::MenuItem("Open...")) request_file_dialog(app, FileAction::open);
    if (ImGui::MenuItem("Append...")) request_file_dialog(app, FileAction::append);
    if (ImGui::MenuItem("Save", nullptr, false, !s.path.empty())) run_line(app, "save");
    if (ImGui::MenuItem("Save as...")) request_file_dialog(app, FileAction::save_as);
    if (ImGui::MenuItem("Export smooth surface..."))
      request_file_dialog(app, FileAction::export_surface);
    if (ImGui::MenuItem("Quit")) glfwSetWindowShouldClose(app.window, GLFW_TRUE);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Edit")) {
    if (ImGui::MenuItem("Undo", "Ctrl+Z", false, s.document.can_undo())) run_line(app, "undo");
    if (ImGui::MenuItem("Redo", "Ctrl+Y", false, s.document.can_redo())) run_line(app, "redo");
    ImGui::EndMenu();
  }
  const std::string file = s.path.empty() ? "untitled" : s.path;
  ui.text_disabled(elided(file, ImGui::GetContentRegionAvail().x - ems(2)) +
                   (s.document.modified() ? " *" : ""));
  record_panel(app.layout);
  ImGui::EndMainMenuBar();
}

/// The status bar along the window's bottom; returns its height.
float status_bar(App& app, Widgets& ui) {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const ImGuiStyle& style = ImGui::GetStyle();
  // No shorter than ImGui lets a window be, or it would reach below the window's edge.
  const float h =
      std::max(ImGui::GetTextLineHeight() + 2 * style.WindowPadding.y, style.WindowMinSize.y);
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x, vp->Pos.y + vp->Size.y - h));
  ImGui::SetNextWindowSize(ImVec2(vp->Size.x, h));
  ImGui::Begin("##status", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoNav);
  const Session& s = app.session;
  const std::string stats = fmt::format(
      "update {:.2f} ms ({} of {} patches{}) | {:.0f} fps | {} | ", s.last_update.milliseconds,
      s.last_update.recomputed_patches, s.surface.num_patches(), s.last_update.full ? ", full" : "",
      app.frames.fps(), to_string(s.display.method));
  const SurfaceProblems& problems = s.surface_problems();
  const std::string warning = problems.empty() ? "" : " | " + problems.summary();
  // The message takes the room left, shortened when longer (the full text in a tooltip).
  const float room = ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize(stats.c_str()).x -
                     ImGui::CalcTextSize(warning.c_str()).x;
  const std::string message = elided(app.status, std::max(room, ems(4)));
  ui.text(stats + message);
  if (message != app.status && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", app.status.c_str());
  if (!warning.empty()) {
    ImGui::SameLine(0, 0);
    ImGui::TextColored(ImVec4(problem_colour.x(), problem_colour.y(), problem_colour.z(), 1.0f),
                       "%s", warning.c_str());
    record_label(app.layout, warning);
  }
  record_panel(app.layout);
  ImGui::End();
  return h;
}

}  // namespace

void draw_panels(App& app) {
  Widgets ui(app.layout);
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  menu_bar(app, ui);
  const float menu_h = app.layout.panels.empty() ? 0.0f : app.layout.panels.back().box.y1;
  const float status_h = status_bar(app, ui);
  const ScreenRect between{vp->Pos.x, vp->Pos.y + menu_h, vp->Pos.x + vp->Size.x,
                           vp->Pos.y + vp->Size.y - status_h};
  edit_panel(app, ui, between);
  const float left = app.layout.panels.back().box.x1;
  display_panel(app, ui, between);
  const float right = app.layout.panels.back().box.x0;
  // The 3D view: what the panels leave between them (at least a pixel wide).
  app.layout.viewport = {left, between.y0, std::max(right, left + 1), between.y1};
}

void recover_dialog(App& app) {
  Autosave& a = app.autosave;
  if (a.offer_pending && ImGui::GetFrameCount() > 2) {
    ImGui::OpenPopup("Recover autosave?");
    a.offer_pending = false;
  }
  if (!ImGui::BeginPopupModal("Recover autosave?", nullptr, ImGuiWindowFlags_AlwaysAutoResize))
    return;
  ImGui::Text("An autosave newer than the document exists:\n%s", a.offered_path.c_str());
  if (ImGui::Button("Recover")) {
    Session& s = app.session;
    const std::string path = s.path;
    run_line(app, "open " + a.offered_path);
    s.path = path;  // saving goes to the document, not over the autosave
    s.document.mark_modified();
    ImGui::CloseCurrentPopup();
  }
  ImGui::SameLine();
  if (ImGui::Button("Discard")) {
    std::error_code ec;
    std::filesystem::remove(a.offered_path, ec);
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

}  // namespace stitch::modeler::app
