#include "panels.hpp"

#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "commands.hpp"
#include "file_dialog.hpp"
#include "stitch/topology/primitives.hpp"
#include "viewport.hpp"

namespace stitch::modeler::app {

namespace {

constexpr const char* kPickKinds[] = {"vertex", "edge", "face", "corner"};
constexpr const char* kDragTools[] = {"view plane", "x", "y", "z"};
constexpr const char* kKgonKinds[] = {"face", "vertex", "edge"};
constexpr const char* kMethods[] = {"mdc", "asc", "cc"};
constexpr const char* kSplits[] = {"off", "mdc", "asc", "cc"};
constexpr const char* kModes[] = {"shaded", "zebra", "isophote", "levels", "patches", "input"};
constexpr const char* kOverlays[] = {"mesh", "kgons", "nets", "tess"};
constexpr const char* kViews[] = {"front", "back", "left", "right", "top", "bottom", "iso"};

/// ImGui's widgets, each recording its label in the layout as it is drawn.
class Widgets {
 public:
  explicit Widgets(ScreenLayout& layout) : layout_(layout) {}
  bool button(const char* label, bool enabled = true) {
    if (!enabled) ImGui::BeginDisabled();
    const bool pressed = ImGui::Button(label);
    if (!enabled) ImGui::EndDisabled();
    record_label(layout_, label);
    return pressed;
  }
  bool radio(const char* label, bool active) {
    const bool pressed = ImGui::RadioButton(label, active);
    record_label(layout_, label);
    return pressed;
  }
  bool checkbox(const char* label, bool* value) {
    const bool changed = ImGui::Checkbox(label, value);
    record_label(layout_, label);
    return changed;
  }
  void text(const std::string& text) {
    ImGui::TextUnformatted(text.c_str());
    record_label(layout_, text);
  }
  void text_disabled(const std::string& text) {
    ImGui::TextDisabled("%s", text.c_str());
    record_label(layout_, text);
  }
  bool header(const char* label, ImGuiTreeNodeFlags flags = 0) {
    const bool open = ImGui::CollapsingHeader(label, flags);
    // The text follows the arrow: a frame padding, the arrow (a font size), a padding.
    const ImGuiStyle& style = ImGui::GetStyle();
    record_label(layout_, label, ImGui::GetFontSize() + 2 * style.FramePadding.x);
    return open;
  }
  bool combo(const char* label, int* current, const char* const items[], int count) {
    const bool changed = ImGui::Combo(label, current, items, count);
    record_label(layout_, label);
    return changed;
  }
  bool slider(const char* label, float* value, float low, float high) {
    const bool changed = ImGui::SliderFloat(label, value, low, high);
    record_label(layout_, label);
    return changed;
  }
  bool slider(const char* label, int* value, int low, int high) {
    const bool changed = ImGui::SliderInt(label, value, low, high);
    record_label(layout_, label);
    return changed;
  }
  bool drag3(const char* label, float* values, float speed) {
    const bool changed = ImGui::DragFloat3(label, values, speed);
    record_label(layout_, label);
    return changed;
  }
  bool input_int(const char* label, int* value) {
    const bool changed = ImGui::InputInt(label, value);
    record_label(layout_, label);
    return changed;
  }

 private:
  ScreenLayout& layout_;
};

/// "edge 1 5@2" -> "1 5@2": an element's numbers as operation lines take them.
std::string numbers_of(const std::string& description) {
  return description.substr(description.find(' ') + 1);
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
  auto op_button = [&](const char* label, const std::string& line, bool enabled) {
    if (ui.button(label, enabled)) run_line(app, line);
  };
  const bool two_corners =
      sel && prev && sel->kind == PickKind::corner && prev->kind == PickKind::corner;
  op_button("Insert edge (previous corner -> selected corner)",
            two_corners ? "insert-edge " + numbers_of(describe(m, *prev)) + " " +
                              numbers_of(describe(m, *sel))
                        : "",
            two_corners);
  const bool edge = sel && sel->kind == PickKind::edge;
  const std::string e = edge ? numbers_of(describe(m, *sel)) : "";
  op_button("Delete edge", "delete-edge " + e, edge);
  ImGui::SameLine();
  op_button("Subdivide", "subdivide-edge " + e, edge);
  ImGui::SameLine();
  op_button("Collapse", "collapse-edge " + e, edge);
  // Sharp features: an infinitely sharp crease (OpenSubdiv's 10) or none; a vertex corner.
  const bool sharp_edge = edge && m.sharpness(HalfedgeMesh::edge(Halfedge(sel->index))) > 0;
  op_button(sharp_edge ? "Smooth edge" : "Crease edge",
            fmt::format("crease {} {}", e, sharp_edge ? 0.0 : infinitely_sharp), edge);
  const bool vertex = sel && sel->kind == PickKind::vertex;
  const bool corner_vertex = vertex && m.sharpness(Vertex(sel->index)) > 0;
  ImGui::SameLine();
  op_button(
      corner_vertex ? "Smooth vertex" : "Corner vertex",
      vertex ? fmt::format("corner {} {}", sel->index + 1, corner_vertex ? 0.0 : infinitely_sharp)
             : "",
      vertex);
  const bool face = sel && sel->kind == PickKind::face;
  const std::string f = face ? std::to_string(sel->index + 1) : "";
  ImGui::SetNextItemWidth(80);
  ImGui::InputFloat("##distance", &app.fields.extrude_distance, 0.1f, 0.5f, "%.2f");
  ImGui::SameLine();
  op_button("Extrude face", fmt::format("extrude-face {} {}", f, app.fields.extrude_distance),
            face);
  ImGui::SameLine();
  op_button("Delete face", "delete-face " + f, face);
  const bool hole = face && m.is_hole(Face(sel->index));
  ImGui::SameLine();
  op_button(hole ? "Fill hole" : "Open face", (hole ? "fill-hole " : "open-face ") + f, face);
  const bool two_faces = face && prev && prev->kind == PickKind::face;
  ImGui::SetNextItemWidth(80);
  ui.input_int("twist", &app.fields.connect_twist);
  ImGui::SameLine();
  op_button("Connect faces (previous, selected)",
            two_faces ? fmt::format("connect-faces {} {} {}", prev->index + 1, sel->index + 1,
                                    app.fields.connect_twist)
                      : "",
            two_faces);
  ui.text("Remesh:");
  for (const char* op : {"doo-sabin", "vertex-insertion", "catmull-clark", "dual"}) {
    ImGui::SameLine();
    op_button(op, op, true);
  }
  const auto names = primitive_names();
  int& chosen = app.fields.primitive_index;
  chosen = std::clamp(chosen, 0, int(names.size()) - 1);
  ImGui::SetNextItemWidth(150);
  if (ImGui::BeginCombo("##primitive", names[chosen].c_str())) {
    for (int i = 0; i < int(names.size()); ++i)
      if (ImGui::Selectable(names[i].c_str(), i == chosen)) chosen = i;
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  op_button("New from primitive", "primitive " + names[chosen], true);
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
  float scale = float(c.scale), rotate = float(c.rotate_deg);
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
  changed |= ui.checkbox("regularise", &regular);
  if (ui.button("Reset")) {
    scale = 1, rotate = 0, offset[0] = offset[1] = offset[2] = 0, regular = false;
    changed = true;
  }
  if (!changed) return;
  const KgonControl n{scale, rotate, Vec3(offset[0], offset[1], offset[2]), regular};
  try {
    s.apply(s.document.set_kgon_control(t, n, merge));
    app.status = fmt::format("K-gon updated: {} patches in {:.2f} ms",
                             s.last_update.recomputed_patches, s.last_update.milliseconds);
    after_change(app, s.last_update.full);
  } catch (const std::exception& e) {
    app.status = e.what();
  }
}

void edit_panel(App& app, Widgets& ui) {
  ImGui::SetNextWindowPos(ImVec2(10, 30), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(330, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("Edit");
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

void display_panel(App& app, Widgets& ui) {
  const Session& s = app.session;
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(vp->Size.x - 290, 30), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(280, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("Display");
  int method = int(s.display.method);
  if (ui.combo("method", &method, kMethods, 3))
    run_line(app, std::string("method ") + kMethods[method]);
  int split = s.display.split ? int(*s.display.split) + 1 : 0;
  if (ui.combo("split with", &split, kSplits, 4))
    run_line(app, std::string("split ") + kSplits[split]);
  int resolution = s.display.resolution;
  if (ui.slider("resolution", &resolution, 1, 32) && resolution != s.display.resolution)
    run_line(app, fmt::format("resolution {}", resolution));
  int mode = s.display.input_polygons ? 5 : int(s.display.mode);
  if (ui.combo("mode", &mode, kModes, 6)) run_line(app, std::string("mode ") + kModes[mode]);
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
  for (const char* v : kViews) {
    if (ui.button(v)) run_line(app, std::string("view ") + v);
    ImGui::SameLine();
  }
  ImGui::NewLine();
  if (ui.button("Frame all")) run_line(app, "frame all");
  ImGui::SameLine();
  if (ui.button("Frame selection")) run_line(app, "frame selection");
  ImGui::Separator();
  if (ui.header("History")) {
    for (const std::string& l : s.document.undo_labels()) {
      ImGui::BulletText("%s", l.c_str());
      record_label(app.layout, l);
    }
    const auto redo = s.document.redo_labels();
    for (auto it = redo.rbegin(); it != redo.rend(); ++it) ui.text_disabled("  " + *it);
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
  ui.text_disabled((s.path.empty() ? "untitled" : s.path) + (s.document.modified() ? " *" : ""));
  ImGui::EndMainMenuBar();
}

void status_bar(App& app, Widgets& ui) {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const float h = ImGui::GetFrameHeight() + 6;
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x, vp->Pos.y + vp->Size.y - h));
  ImGui::SetNextWindowSize(ImVec2(vp->Size.x, h));
  ImGui::Begin("##status", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoNav);
  const Session& s = app.session;
  ui.text(fmt::format("update {:.2f} ms ({} of {} patches{}) | {:.0f} fps | {} | {}",
                      s.last_update.milliseconds, s.last_update.recomputed_patches,
                      s.surface.num_patches(), s.last_update.full ? ", full" : "", app.frames.fps(),
                      to_string(s.display.method), app.status));
  if (const SurfaceProblems& p = s.surface_problems(); !p.empty()) {
    ImGui::SameLine();
    const std::string text = "| " + p.summary();
    ImGui::TextColored(ImVec4(problem_colour.x(), problem_colour.y(), problem_colour.z(), 1.0f),
                       "%s", text.c_str());
    record_label(app.layout, text);
  }
  record_panel(app.layout);
  ImGui::End();
}

}  // namespace

void draw_panels(App& app) {
  Widgets ui(app.layout);
  menu_bar(app, ui);
  edit_panel(app, ui);
  display_panel(app, ui);
  status_bar(app, ui);
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
