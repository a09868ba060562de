// stitch-modeler: the interactive modeler. A thin GLFW + Dear ImGui layer: every edit is a
// script line run by the window-free session (include/stitch/modeler/session.hpp), the surface is
// kept up to date incrementally by LiveSurface, and the renderer re-uploads only the patches an
// edit changed.
#include <epoxy/gl.h>  // before GLFW, which must not include GL headers itself
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <fmt/format.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "stitch/mesh/io.hpp"
#include "stitch/modeler/session.hpp"
#include "stitch/render/gl_context.hpp"
#include "stitch/render/image.hpp"
#include "stitch/render/options.hpp"
#include "stitch/render/scene.hpp"
#include "stitch/topology/primitives.hpp"

namespace {

using namespace stitch;
using namespace stitch::modeler;
using Clock = std::chrono::steady_clock;

constexpr double autosave_interval_s = 180.0;

/// A colour + depth framebuffer for one half of the split view.
struct HalfTarget {
  GLuint fbo = 0, colour = 0, depth = 0;
  int width = 0, height = 0;

  void resize(int w, int h) {
    if (w == width && h == height && fbo) return;
    release();
    width = w;
    height = h;
    glGenFramebuffers(1, &fbo);
    glGenRenderbuffers(1, &colour);
    glGenRenderbuffers(1, &depth);
    glBindRenderbuffer(GL_RENDERBUFFER, colour);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, w, h);
    glBindRenderbuffer(GL_RENDERBUFFER, depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, w, h);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw RenderError("the split view's framebuffer is incomplete");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }
  void release() {
    if (fbo) glDeleteFramebuffers(1, &fbo);
    if (colour) glDeleteRenderbuffers(1, &colour);
    if (depth) glDeleteRenderbuffers(1, &depth);
    fbo = colour = depth = 0;
  }
};

/// What a Renderer shows and whether its buffers are current.
struct View3D {
  std::unique_ptr<Renderer> renderer;
  bool input_uploaded = false;  ///< the input polygons are uploaded instead of the surface
  bool geometry_dirty = true;   ///< everything must be uploaded again
};

enum class DragTool { view_plane, axis_x, axis_y, axis_z };

struct App {
  Session session;
  GLFWwindow* window = nullptr;
  View3D main_view, split_view;
  LiveSurface split_surface;  ///< the second method of the split view
  KgonOptions split_kgons;    ///< the controls split_surface was built with
  bool split_current = false;
  bool overlays_dirty = true;
  HalfTarget half;

  PickKind pick_kind = PickKind::vertex;
  std::optional<Pick> previous_pick;  ///< for two-element operations (insert edge, connect)
  DragTool drag_tool = DragTool::view_plane;
  std::string status = "ready";
  double fps = 0.0;
  bool autosave_enabled = true;
  Clock::time_point last_autosave = Clock::now();
  bool show_ui = true;  ///< the panels (`ui off` in a script hides them, e.g. for pictures)
  bool show_recover_dialog = false;
  bool open_popup_requested = false, save_popup_requested = false, export_popup_requested = false;
  bool append_popup_requested = false;
  std::string recover_path;

  // Mouse state.
  bool dragging_vertex = false, mouse_moved = false;
  bool drag_has_moved = false;  ///< the current vertex drag has recorded its move
  int drag_button = -1;
  double press_x = 0, press_y = 0, last_x = 0, last_y = 0;
  Vec3 drag_origin = Vec3::Zero();

  // Text fields.
  char open_path[512] = "";
  char save_path[512] = "";
  char export_path[512] = "smooth.ply";
  char command_line[512] = "";
  float extrude_distance = 0.5f;
  int connect_twist = 0;
  int primitive_index = 1;
};

int framebuffer_width(GLFWwindow* w) {
  int fw = 0, fh = 0;
  glfwGetFramebufferSize(w, &fw, &fh);
  return fw;
}
int framebuffer_height(GLFWwindow* w) {
  int fw = 0, fh = 0;
  glfwGetFramebufferSize(w, &fw, &fh);
  return fh;
}

/// The camera for the current view; the clipping planes contain the input mesh's box, enlarged
/// since the surface and the K-gons may reach a little beyond it.
Camera current_camera(const App& app) {
  BoundingBox box = app.session.mesh_bounds();
  if (!box.empty()) {
    const Vec3 c = box.center(), half = 0.75 * (box.max - box.min) + Vec3::Constant(1e-6);
    box.extend(c + half);
    box.extend(c - half);
  }
  return app.session.view.camera(box);
}

/// Highlight of the selection (and the first element of a two-element operation).
void add_highlight(const HalfedgeMesh& m, const Pick& p, const Colour& colour, LineSet& lines,
                   MarkerSet& markers) {
  auto mark = [&](const Vec3& x) {
    markers.positions.push_back(x);
    markers.colours.push_back(colour);
  };
  switch (p.kind) {
    case PickKind::vertex:
      if (p.index < m.vertex_capacity() && !m.is_deleted(Vertex(p.index)))
        mark(m.position(Vertex(p.index)));
      break;
    case PickKind::edge: {
      const Halfedge h(p.index);
      if (h.idx < m.halfedge_capacity() && !m.is_deleted(h))
        lines.add(m.position(m.origin(h)), m.position(m.target(h)), colour);
      break;
    }
    case PickKind::face:
      if (p.index < m.face_capacity() && !m.is_deleted(Face(p.index))) {
        std::vector<Vec3> loop;
        for (Halfedge h : m.face_loop(Face(p.index))) loop.push_back(m.position(m.origin(h)));
        lines.add_loop(loop, colour);
      }
      break;
    case PickKind::corner: {
      const Halfedge h(p.index);
      if (h.idx < m.halfedge_capacity() && !m.is_deleted(h)) {
        // A point inside the face next to the vertex, and the two sides meeting there.
        const Vec3 v = m.position(m.origin(h));
        const Vec3 a = m.position(m.target(h)), b = m.position(m.origin(m.prev(h)));
        lines.add(v, v + 0.3 * (a - v), colour);
        lines.add(v, v + 0.3 * (b - v), colour);
        mark(v + 0.15 * (a - v) + 0.15 * (b - v));
      }
      break;
    }
  }
}

RenderStyle style_for(const App& app) {
  const DisplaySettings& d = app.session.display;
  RenderStyle style;
  style.mode = d.mode;
  style.overlays = d.overlays;
  style.markers = d.markers;
  // The selection is drawn in the mesh overlay and the markers, so those are on when needed.
  if (app.session.selection || app.previous_pick) {
    style.show(Overlay::mesh);
    style.markers = true;
  }
  if (!app.session.surface_problems().empty()) style.markers = true;  // their outlines
  style.background = Colour(0.96f, 0.96f, 0.97f);
  return style;
}

void upload_overlays(App& app, View3D& view, const LiveSurface& surface) {
  const Session& s = app.session;
  const HalfedgeMesh& m = s.document.mesh();
  const DisplaySettings& d = s.display;
  // Overlays are rebuilt only when shown: they cost time proportional to the mesh.
  LineSet mesh_set = d.overlays[int(Overlay::mesh)] ? mesh_lines(m) : LineSet{};
  MarkerSet markers;
  if (d.markers) markers = extraordinary_markers(extraordinary_points(m, surface.kgons()));
  if (app.previous_pick)
    add_highlight(m, *app.previous_pick, Colour(0.1f, 0.7f, 0.2f), mesh_set, markers);
  if (s.selection) add_highlight(m, *s.selection, Colour(1.0f, 0.45f, 0.0f), mesh_set, markers);
  // Patches that fold or cross, outlined on the main view's own tessellation.
  if (&surface == &s.surface)
    add_problem_outlines(surface, s.surface_problems().corners, markers.curves);
  view.renderer->set_overlay(Overlay::mesh, mesh_set);
  view.renderer->set_overlay(
      Overlay::kgons, d.overlays[int(Overlay::kgons)] ? kgon_lines(surface.kgons()) : LineSet{});
  view.renderer->set_overlay(Overlay::nets,
                             d.overlays[int(Overlay::nets)]
                                 ? control_net_lines(surface.nets(), surface.corners())
                                 : LineSet{});
  view.renderer->set_overlay(Overlay::tessellation, d.overlays[int(Overlay::tessellation)]
                                                        ? surface_mesh_lines(surface.tessellation())
                                                        : LineSet{});
  view.renderer->set_markers(markers);
}

/// Uploads what changed: the recomputed patches' vertex blocks, or everything.
void sync_view(App& app, View3D& view, const LiveSurface& surface, bool full) {
  const Session& s = app.session;
  if (s.display.input_polygons) {
    if (full || view.geometry_dirty || !view.input_uploaded)
      view.renderer->set_surface(input_faces(s.document.mesh()));
    view.input_uploaded = true;
  } else if (full || view.geometry_dirty || view.input_uploaded) {
    view.renderer->set_block_surface(surface.tessellation(), surface.vertices_per_patch(),
                                     surface.quads_per_patch());
    view.input_uploaded = false;
  } else {
    // The blocks (indexed by corner) of recomputed patches and of slots laid out again.
    std::vector<int> blocks = surface.relaid();
    for (Corner c : surface.recomputed()) blocks.push_back(c.idx);
    view.renderer->update_surface_blocks(surface.tessellation(), std::move(blocks));
  }
  view.geometry_dirty = false;
}

/// After any session change: bring the split surface along and upload to the GPU.
bool same_controls(const KgonOptions& a, const KgonOptions& b) {
  return a.construction == b.construction && a.global == b.global && a.face == b.face &&
         a.vertex == b.vertex && a.edge == b.edge;
}

/// After any session change: upload what the main surface recomputed, and bring the split
/// view's surface along with every document change since the last call (Session::take_changes,
/// which covers moves and topology edits alike); a K-gon control change rebuilds it.
void after_change(App& app, bool full) {
  Session& s = app.session;
  const Change missed = s.take_changes();
  sync_view(app, app.main_view, s.surface, full);
  if (s.display.split) {
    UpdateStats stats;
    if (!app.split_current || app.split_surface.method() != *s.display.split ||
        app.split_surface.resolution() != s.display.resolution || full ||
        !same_controls(app.split_kgons, s.document.kgon_options())) {
      stats = app.split_surface.rebuild(s.document.mesh(), s.document.kgon_options(),
                                        *s.display.split, s.display.resolution);
      app.split_current = true;
      app.split_kgons = s.document.kgon_options();
    } else {
      stats = app.split_surface.update(s.document.mesh(), s.document.kgon_options(), missed);
    }
    if (!app.split_view.renderer) app.split_view.renderer = std::make_unique<Renderer>();
    sync_view(app, app.split_view, app.split_surface, stats.full);
  } else {
    app.split_current = false;
  }
  app.overlays_dirty = true;
}

void write_autosave(App& app) {
  if (!app.autosave_enabled || !app.session.document.modified()) return;
  const std::string path = autosave_path(app.session.path);
  try {
    if (const auto folder = std::filesystem::path(path).parent_path(); !folder.empty())
      std::filesystem::create_directories(folder);
    save_project(path, app.session.project());
  } catch (const std::exception& e) {
    app.status = fmt::format("autosave failed: {}", e.what());
    std::cerr << "stitch-modeler: " << app.status << "\n";
  }
  app.last_autosave = Clock::now();
}

void remove_autosave(const App& app) {
  std::error_code ec;
  std::filesystem::remove(autosave_path(app.session.path), ec);
}

/// `ui on|off`: the one script line about the window itself rather than the session.
bool run_ui_line(App& app, const std::string& line) {
  std::istringstream in(line);
  std::string word, value, extra;
  if (!(in >> word) || word != "ui") return false;
  if (!(in >> value) || (value != "on" && value != "off") || (in >> extra && extra[0] != '#'))
    throw MeshError("usage: ui on|off");
  app.show_ui = value == "on";
  return true;
}

/// Runs one line the way the GUI does: errors go to the status bar.
void run_line(App& app, const std::string& line, const ScriptHooks& hooks) {
  const DisplaySettings before = app.session.display;
  const std::string path_before = app.session.path;
  const bool was_modified = app.session.document.modified();
  try {
    if (run_ui_line(app, line)) return;
    const ScriptResult r = run_script_line(app.session, line, hooks);
    if (!r.message.empty()) app.status = r.message;
    if (r.quit) glfwSetWindowShouldClose(app.window, GLFW_TRUE);
  } catch (const std::exception& e) {
    app.status = e.what();
    return;
  }
  const DisplaySettings& now = app.session.display;
  const bool full = now.method != before.method || now.resolution != before.resolution ||
                    now.input_polygons != before.input_polygons || now.split != before.split ||
                    app.session.path != path_before || app.session.last_update.full;
  // A save leaves nothing to recover.
  if (was_modified && !app.session.document.modified() && line.rfind("save", 0) == 0)
    remove_autosave(app);
  // run_script_line kept the surface current; what changed is in session.surface.recomputed().
  after_change(app, full);
}

void draw_scene(App& app) {
  const int w = framebuffer_width(app.window), h = framebuffer_height(app.window);
  if (w <= 0 || h <= 0) return;
  if (app.overlays_dirty) {
    upload_overlays(app, app.main_view, app.session.surface);
    if (app.session.display.split && app.split_view.renderer)
      upload_overlays(app, app.split_view, app.split_surface);
    app.overlays_dirty = false;
  }
  const RenderStyle style = style_for(app);
  const Camera camera = current_camera(app);
  if (!app.session.display.split || !app.split_view.renderer) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    app.main_view.renderer->draw(camera, style, w, h);
    return;
  }
  const int half_w = std::max(1, w / 2);
  app.half.resize(half_w, h);
  const View3D* views[2] = {&app.main_view, &app.split_view};
  for (int side = 0; side < 2; ++side) {
    glBindFramebuffer(GL_FRAMEBUFFER, app.half.fbo);
    views[side]->renderer->draw(camera, style, half_w, h);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, app.half.fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, half_w, h, side * half_w, 0, side * half_w + half_w, h,
                      GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, w, h);
}

// --- the panels ---------------------------------------------------------------------------

void panel_tools(App& app, const ScriptHooks& hooks) {
  Session& s = app.session;
  const HalfedgeMesh& m = s.document.mesh();
  ImGui::SetNextWindowPos(ImVec2(10, 30), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(330, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("Edit");

  ImGui::TextUnformatted("Pick (click in the view):");
  static constexpr const char* kinds[] = {"vertex", "edge", "face", "corner"};
  for (int k = 0; k < 4; ++k) {
    if (k) ImGui::SameLine();
    if (ImGui::RadioButton(kinds[k], app.pick_kind == PickKind(k))) app.pick_kind = PickKind(k);
  }
  ImGui::Text("Selected: %s", s.selection ? describe(m, *s.selection).c_str() : "nothing");
  if (app.previous_pick) ImGui::Text("Previous: %s", describe(m, *app.previous_pick).c_str());

  auto op_button = [&](const char* label, const std::string& line, bool enabled) {
    if (!enabled) ImGui::BeginDisabled();
    if (ImGui::Button(label)) run_line(app, line, hooks);
    if (!enabled) ImGui::EndDisabled();
  };
  auto strip = [](const std::string& d) {
    return d.substr(d.find(' ') + 1);
  };  // "edge 1 5@2" -> "1 5@2"

  if (ImGui::CollapsingHeader("Operators", ImGuiTreeNodeFlags_DefaultOpen)) {
    const bool two_corners = s.selection && app.previous_pick &&
                             s.selection->kind == PickKind::corner &&
                             app.previous_pick->kind == PickKind::corner;
    op_button("Insert edge (previous corner -> selected corner)",
              two_corners ? "insert-edge " + strip(describe(m, *app.previous_pick)) + " " +
                                strip(describe(m, *s.selection))
                          : "",
              two_corners);
    const bool edge = s.selection && s.selection->kind == PickKind::edge;
    const std::string e = edge ? strip(describe(m, *s.selection)) : "";
    op_button("Delete edge", "delete-edge " + e, edge);
    ImGui::SameLine();
    op_button("Subdivide", "subdivide-edge " + e, edge);
    ImGui::SameLine();
    op_button("Collapse", "collapse-edge " + e, edge);
    // Sharp features: an infinitely sharp crease (OpenSubdiv's 10) or none; a vertex corner.
    const bool sharp_edge =
        edge && m.sharpness(HalfedgeMesh::edge(Halfedge(s.selection->index))) > 0;
    op_button(sharp_edge ? "Smooth edge" : "Crease edge",
              fmt::format("crease {} {}", e, sharp_edge ? 0.0 : infinitely_sharp), edge);
    const bool vertex = s.selection && s.selection->kind == PickKind::vertex;
    const bool corner_vertex = vertex && m.sharpness(Vertex(s.selection->index)) > 0;
    ImGui::SameLine();
    op_button(corner_vertex ? "Smooth vertex" : "Corner vertex",
              vertex ? fmt::format("corner {} {}", s.selection->index + 1,
                                   corner_vertex ? 0.0 : infinitely_sharp)
                     : "",
              vertex);
    const bool face = s.selection && s.selection->kind == PickKind::face;
    const std::string f = face ? std::to_string(s.selection->index + 1) : "";
    ImGui::SetNextItemWidth(80);
    ImGui::InputFloat("##distance", &app.extrude_distance, 0.1f, 0.5f, "%.2f");
    ImGui::SameLine();
    op_button("Extrude face", fmt::format("extrude-face {} {}", f, app.extrude_distance), face);
    ImGui::SameLine();
    op_button("Delete face", "delete-face " + f, face);
    const bool hole = face && m.is_hole(Face(s.selection->index));
    ImGui::SameLine();
    op_button(hole ? "Fill hole" : "Open face", (hole ? "fill-hole " : "open-face ") + f, face);
    const bool two_faces = face && app.previous_pick && app.previous_pick->kind == PickKind::face;
    ImGui::SetNextItemWidth(80);
    ImGui::InputInt("twist", &app.connect_twist);
    ImGui::SameLine();
    op_button("Connect faces (previous, selected)",
              two_faces ? fmt::format("connect-faces {} {} {}", app.previous_pick->index + 1,
                                      s.selection->index + 1, app.connect_twist)
                        : "",
              two_faces);
    ImGui::TextUnformatted("Remesh:");
    for (const char* op : {"doo-sabin", "vertex-insertion", "catmull-clark", "dual"}) {
      ImGui::SameLine();
      op_button(op, op, true);
    }
    const auto names = primitive_names();
    ImGui::SetNextItemWidth(150);
    if (ImGui::BeginCombo(
            "##primitive",
            names[std::clamp(app.primitive_index, 0, int(names.size()) - 1)].c_str())) {
      for (int i = 0; i < int(names.size()); ++i)
        if (ImGui::Selectable(names[i].c_str(), i == app.primitive_index)) app.primitive_index = i;
      ImGui::EndCombo();
    }
    ImGui::SameLine();
    op_button("New from primitive",
              "primitive " + names[std::clamp(app.primitive_index, 0, int(names.size()) - 1)],
              true);
  }

  if (ImGui::CollapsingHeader("Move vertices", ImGuiTreeNodeFlags_DefaultOpen)) {
    ImGui::TextUnformatted("Ctrl + left drag moves the selected vertex");
    static constexpr const char* tools[] = {"view plane", "x", "y", "z"};
    for (int t = 0; t < 4; ++t) {
      if (t) ImGui::SameLine();
      if (ImGui::RadioButton(tools[t], app.drag_tool == DragTool(t))) app.drag_tool = DragTool(t);
    }
  }

  if (ImGui::CollapsingHeader("K-gons", ImGuiTreeNodeFlags_DefaultOpen)) {
    static bool global = false;
    const auto target = kgon_target(s);
    ImGui::Checkbox("global (all extraordinary K-gons)", &global);
    const bool use_global = global || !target;
    const KgonTarget t = use_global ? KgonTarget{} : *target;
    static constexpr const char* kind_names[] = {"face", "vertex", "edge"};
    ImGui::Text(
        "Editing: %s",
        use_global ? "global control"
                   : fmt::format("K-gon of {} {}", kind_names[int(t.kind)], t.element + 1).c_str());
    KgonControl c = s.document.kgon_control(t);
    float scale = float(c.scale), rotate = float(c.rotate_deg);
    float offset[3] = {float(c.offset.x()), float(c.offset.y()), float(c.offset.z())};
    bool regular = c.regularize;
    bool changed = false, merge = false;
    changed |= ImGui::SliderFloat("size", &scale, 0.05f, 2.0f);
    merge |= ImGui::IsItemActive() && !ImGui::IsItemActivated();
    changed |= ImGui::SliderFloat("rotation", &rotate, -180.0f, 180.0f);
    merge |= ImGui::IsItemActive() && !ImGui::IsItemActivated();
    changed |= ImGui::DragFloat3("offset", offset, 0.01f);
    merge |= ImGui::IsItemActive() && !ImGui::IsItemActivated();
    changed |= ImGui::Checkbox("regularise", &regular);
    if (ImGui::Button("Reset")) {
      scale = 1, rotate = 0, offset[0] = offset[1] = offset[2] = 0, regular = false;
      changed = true;
    }
    if (changed) {
      KgonControl n{scale, rotate, Vec3(offset[0], offset[1], offset[2]), regular};
      try {
        s.apply(s.document.set_kgon_control(t, n, merge));
        app.status = fmt::format("K-gon updated: {} patches in {:.2f} ms",
                                 s.last_update.recomputed_patches, s.last_update.milliseconds);
        after_change(app, s.last_update.full);
      } catch (const std::exception& e) {
        app.status = e.what();
      }
    }
  }

  if (ImGui::CollapsingHeader("Command line")) {
    ImGui::TextUnformatted("Any script line (stitch edit --ops lines too):");
    if (ImGui::InputText("##command", app.command_line, sizeof app.command_line,
                         ImGuiInputTextFlags_EnterReturnsTrue)) {
      run_line(app, app.command_line, hooks);
      app.command_line[0] = '\0';
    }
  }
  ImGui::End();
}

void panel_display(App& app, const ScriptHooks& hooks) {
  Session& s = app.session;
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(vp->Size.x - 290, 30), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(280, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("Display");
  static constexpr const char* methods[] = {"mdc", "asc", "cc"};
  int method = int(s.display.method);
  if (ImGui::Combo("method", &method, methods, 3))
    run_line(app, std::string("method ") + methods[method], hooks);
  int split = s.display.split ? int(*s.display.split) + 1 : 0;
  static constexpr const char* splits[] = {"off", "mdc", "asc", "cc"};
  if (ImGui::Combo("split with", &split, splits, 4))
    run_line(app, std::string("split ") + splits[split], hooks);
  int resolution = s.display.resolution;
  if (ImGui::SliderInt("resolution", &resolution, 1, 32) && resolution != s.display.resolution)
    run_line(app, fmt::format("resolution {}", resolution), hooks);
  static constexpr const char* modes[] = {"shaded", "zebra",   "isophote",
                                          "levels", "patches", "input"};
  int mode = s.display.input_polygons ? 5 : int(s.display.mode);
  if (ImGui::Combo("mode", &mode, modes, 6))
    run_line(app, std::string("mode ") + modes[mode], hooks);
  static constexpr const char* overlays[] = {"mesh", "kgons", "nets", "tess"};
  for (int o = 0; o < num_overlays; ++o) {
    bool on = s.display.overlays[o];
    if (o) ImGui::SameLine();
    if (ImGui::Checkbox(overlays[o], &on))
      run_line(app, fmt::format("overlay {} {}", overlays[o], on ? "on" : "off"), hooks);
  }
  bool markers = s.display.markers;
  if (ImGui::Checkbox("extraordinary points", &markers))
    run_line(app, fmt::format("overlay markers {}", markers ? "on" : "off"), hooks);
  ImGui::Separator();
  for (const char* v : {"front", "back", "left", "right", "top", "bottom", "iso"}) {
    if (ImGui::Button(v)) run_line(app, std::string("view ") + v, hooks);
    ImGui::SameLine();
  }
  ImGui::NewLine();
  if (ImGui::Button("Frame all")) run_line(app, "frame all", hooks);
  ImGui::SameLine();
  if (ImGui::Button("Frame selection")) run_line(app, "frame selection", hooks);
  ImGui::Separator();
  if (ImGui::CollapsingHeader("History")) {
    for (const std::string& l : s.document.undo_labels()) ImGui::BulletText("%s", l.c_str());
    const auto redo = s.document.redo_labels();
    for (auto it = redo.rbegin(); it != redo.rend(); ++it) ImGui::TextDisabled("  %s", it->c_str());
  }
  ImGui::End();
}

void menu_bar(App& app, const ScriptHooks& hooks) {
  Session& s = app.session;
  bool open_popup = false, save_popup = false;
  if (ImGui::BeginMainMenuBar()) {
    if (ImGui::BeginMenu("File")) {
      if (ImGui::MenuItem("Open...")) open_popup = true;
      if (ImGui::MenuItem("Append...")) app.append_popup_requested = true;
      if (ImGui::MenuItem("Save", nullptr, false, !s.path.empty())) run_line(app, "save", hooks);
      if (ImGui::MenuItem("Save as...")) save_popup = true;
      if (ImGui::MenuItem("Export smooth surface...")) app.export_popup_requested = true;
      if (ImGui::MenuItem("Quit")) glfwSetWindowShouldClose(app.window, GLFW_TRUE);
      ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit")) {
      if (ImGui::MenuItem("Undo", "Ctrl+Z", false, s.document.can_undo()))
        run_line(app, "undo", hooks);
      if (ImGui::MenuItem("Redo", "Ctrl+Y", false, s.document.can_redo()))
        run_line(app, "redo", hooks);
      ImGui::EndMenu();
    }
    ImGui::TextDisabled("%s%s", s.path.empty() ? "untitled" : s.path.c_str(),
                        s.document.modified() ? " *" : "");
    ImGui::EndMainMenuBar();
  }
  if (open_popup) app.open_popup_requested = true;
  if (save_popup) {
    std::snprintf(app.save_path, sizeof app.save_path, "%s", s.path.c_str());
    app.save_popup_requested = true;
  }
}

/// A modal asking for a path, which runs the script line `command PATH` on `button`.
template <size_t N>
void path_dialog(App& app, const ScriptHooks& hooks, const char* title, const char* label,
                 char (&path)[N], const char* button, const char* command) {
  if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ImGui::InputText(label, path, N);
  if (ImGui::Button(button)) {
    run_line(app, std::string(command) + " " + path, hooks);
    ImGui::CloseCurrentPopup();
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

/// Modal dialogs, begun after every other window (ImGui wants modals above what appears).
void dialogs(App& app, const ScriptHooks& hooks) {
  Session& s = app.session;
  if (app.open_popup_requested) ImGui::OpenPopup("Open file");
  if (app.save_popup_requested) ImGui::OpenPopup("Save as");
  if (app.export_popup_requested) ImGui::OpenPopup("Export smooth surface");
  if (app.append_popup_requested) ImGui::OpenPopup("Append file");
  app.open_popup_requested = app.save_popup_requested = app.export_popup_requested = false;
  app.append_popup_requested = false;
  path_dialog(app, hooks, "Open file", "path (.obj .off .ply .stl .glb .gltf .stitch)",
              app.open_path, "Open", "open");
  // Shares Open's path: the second mesh is usually beside the first.
  path_dialog(app, hooks, "Append file",
              "path (.obj .off .ply .stl .glb .gltf .stitch; may end in --offset X,Y,Z)",
              app.open_path, "Append", "append");
  path_dialog(app, hooks, "Save as", "path (.stitch keeps K-gons and view)", app.save_path, "Save",
              "save");
  path_dialog(app, hooks, "Export smooth surface",
              "path (.ply .obj .off .stl .glb .gltf; .json: Bezier patches)", app.export_path,
              "Export", "export");
  if (app.show_recover_dialog && ImGui::GetFrameCount() > 2) {
    ImGui::OpenPopup("Recover autosave?");
    app.show_recover_dialog = false;
  }
  if (ImGui::BeginPopupModal("Recover autosave?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("An autosave newer than the document exists:\n%s", app.recover_path.c_str());
    if (ImGui::Button("Recover")) {
      const std::string path = s.path;
      run_line(app, "open " + app.recover_path, hooks);
      s.path = path;  // saving goes to the document, not over the autosave
      s.document.mark_modified();
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard")) {
      std::error_code ec;
      std::filesystem::remove(app.recover_path, ec);
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
}

void status_bar(App& app) {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const float h = ImGui::GetFrameHeight() + 6;
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x, vp->Pos.y + vp->Size.y - h));
  ImGui::SetNextWindowSize(ImVec2(vp->Size.x, h));
  ImGui::Begin("##status", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoNav);
  const Session& s = app.session;
  ImGui::Text("update %.2f ms (%d of %d patches%s) | %.0f fps | %s | %s",
              s.last_update.milliseconds, s.last_update.recomputed_patches, s.surface.num_patches(),
              s.last_update.full ? ", full" : "", app.fps, to_string(s.display.method).c_str(),
              app.status.c_str());
  if (const SurfaceProblems& p = s.surface_problems(); !p.empty()) {
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(problem_colour.x(), problem_colour.y(), problem_colour.z(), 1.0f),
                       "| %s", p.summary().c_str());
  }
  ImGui::End();
}

// --- mouse ----------------------------------------------------------------------------------

Ray mouse_ray(const App& app, double x, double y) {
  int ww = 0, wh = 0;
  glfwGetWindowSize(app.window, &ww, &wh);
  Camera camera = current_camera(app);
  int w = ww;
  if (app.session.display.split) {  // both halves show the same camera at half width
    w = ww / 2;
    if (x >= w) x -= w;
  }
  return pixel_ray(camera, x, y, w, wh);
}

void handle_mouse(App& app) {
  ImGuiIO& io = ImGui::GetIO();
  Session& s = app.session;
  double x = 0, y = 0;
  glfwGetCursorPos(app.window, &x, &y);
  const bool ctrl = io.KeyCtrl;
  if (!io.WantCaptureMouse) {
    if (io.MouseWheel != 0.0f) s.view.zoom(io.MouseWheel);
    for (int b = 0; b < 3; ++b)
      if (ImGui::IsMouseClicked(b)) {
        app.drag_button = b;
        app.press_x = app.last_x = x;
        app.press_y = app.last_y = y;
        app.mouse_moved = false;
        app.drag_has_moved = false;
        app.dragging_vertex =
            b == 0 && ctrl && s.selection && s.selection->kind == PickKind::vertex;
        if (app.dragging_vertex)
          app.drag_origin = s.document.mesh().position(Vertex(s.selection->index));
      }
  }
  if (app.drag_button < 0) return;
  const double dx = x - app.last_x, dy = y - app.last_y;
  if (std::abs(x - app.press_x) + std::abs(y - app.press_y) > 3) app.mouse_moved = true;
  if ((dx != 0 || dy != 0) && app.mouse_moved) {
    int ww = 0, wh = 0;
    glfwGetWindowSize(app.window, &ww, &wh);
    if (app.dragging_vertex) {
      const Ray r = mouse_ray(app, x, y);
      const Vec3 p0 = app.drag_origin;
      Vec3 p = p0;
      if (app.drag_tool == DragTool::view_plane) {
        const Vec3 n = (s.view.target - s.view.eye()).normalized();
        const double denom = r.direction.dot(n);
        if (std::abs(denom) > 1e-9) p = r.origin + ((p0 - r.origin).dot(n) / denom) * r.direction;
      } else {
        // The point of the axis line through p0 closest to the ray.
        const Vec3 a = app.drag_tool == DragTool::axis_x   ? Vec3::UnitX()
                       : app.drag_tool == DragTool::axis_y ? Vec3::UnitY()
                                                           : Vec3::UnitZ();
        const Vec3 w0 = p0 - r.origin;
        const double b = a.dot(r.direction), d = a.dot(w0), e = r.direction.dot(w0);
        const double denom = 1 - b * b;
        if (denom > 1e-9) p = p0 + ((b * e - d) / denom) * a;
      }
      try {
        // The first motion of a drag starts an undo step; the rest extend it.
        s.apply(s.document.move_vertices({Vertex(s.selection->index)}, {p}, app.drag_has_moved));
        app.drag_has_moved = true;
        app.status = fmt::format("vertex {} at {:.3f} {:.3f} {:.3f}", s.selection->index + 1, p.x(),
                                 p.y(), p.z());
        after_change(app, false);
      } catch (const std::exception& ex) {
        app.status = ex.what();
      }
    } else if (app.drag_button == 0) {
      s.view.orbit(dx, dy);
    } else {
      s.view.pan(dx, dy, wh);
    }
    app.last_x = x;
    app.last_y = y;
  }
  if (!ImGui::IsMouseDown(app.drag_button)) {
    if (!app.mouse_moved && app.drag_button == 0 && !io.WantCaptureMouse) {
      const auto p = pick(s.document.mesh(), mouse_ray(app, x, y), app.pick_kind);
      if (s.selection && (!p || !(*p == *s.selection))) app.previous_pick = s.selection;
      s.selection = p;
      if (p) app.status = "selected " + describe(s.document.mesh(), *p);
      app.overlays_dirty = true;
    }
    app.drag_button = -1;
    app.dragging_vertex = false;
  }
}

void handle_keys(App& app, const ScriptHooks& hooks) {
  ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureKeyboard) return;
  if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_Z)) run_line(app, "undo", hooks);
  if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_Y)) run_line(app, "redo", hooks);
  if (!io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_F))
    run_line(app, app.session.selection ? "frame selection" : "frame all", hooks);
  if (!io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_A)) run_line(app, "frame all", hooks);
}

void render_frame(App& app, const ScriptHooks& hooks, bool interactive) {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  if (interactive) {
    handle_mouse(app);
    handle_keys(app, hooks);
  }
  if (app.show_ui) {
    menu_bar(app, hooks);
    panel_tools(app, hooks);
    panel_display(app, hooks);
    status_bar(app);
  }
  dialogs(app, hooks);
  ImGui::Render();
  draw_scene(app);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

/// Renders a frame and writes the window's pixels (what the user sees) as a PNG.
void screenshot(App& app, const ScriptHooks& hooks, const std::string& path) {
  // Two frames: ImGui sizes new windows in the first.
  for (int i = 0; i < 2; ++i) render_frame(app, hooks, false);
  const int w = framebuffer_width(app.window), h = framebuffer_height(app.window);
  Image image(w, h);
  std::vector<std::uint8_t> bottom_up(image.rgba.size());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.data());
  const size_t row = static_cast<size_t>(w) * 4;
  for (int y = 0; y < h; ++y) std::memcpy(&image.rgba[y * row], &bottom_up[(h - 1 - y) * row], row);
  for (size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 255;
  write_png(path, image);
  glfwSwapBuffers(app.window);
}

std::vector<std::string> read_lines(const std::string& path) {
  std::istringstream in(read_regular_file(path));
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{"stitch-modeler: interactive smooth modeling with topology changes"};
  std::string file, script, shot, size_text = "1280x800";
  bool exit_after = false, recover = false, no_autosave = false;
  cli.add_option("FILE", file,
                 "mesh (.obj .off .ply) or project (.stitch) to open; default: a cube");
  cli.add_option("--script", script, "run the lines of this file (see docs/modeler.md)");
  cli.add_option("--screenshot", shot, "after the script, write the window to this PNG");
  cli.add_flag("--exit", exit_after, "quit after the script and screenshot");
  cli.add_flag("--recover", recover, "load the autosave newer than FILE instead of FILE");
  cli.add_flag("--no-autosave", no_autosave, "do not write autosaves");
  cli.add_option("--size", size_text, "window size WxH")->capture_default_str();
  CLI11_PARSE(cli, argc, argv);

  ImageSize size;
  try {
    size = parse_image_size(size_text, 4096);
  } catch (const std::exception& e) {
    std::cerr << "stitch-modeler: --size: " << e.what() << "\n";
    return 2;
  }

  glfwSetErrorCallback([](int code, const char* text) {
    std::cerr << "GLFW error " << code << ": " << text << "\n";
  });
  if (!glfwInit()) {
    std::cerr << "stitch-modeler: cannot initialise GLFW (no display? run under xvfb-run)\n";
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SAMPLES, 4);
  GLFWwindow* window =
      glfwCreateWindow(size.width, size.height, "stitch-modeler", nullptr, nullptr);
  if (!window) {
    std::cerr << "stitch-modeler: cannot open an OpenGL 3.3 core window\n";
    glfwTerminate();
    return 1;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(script.empty() ? 1 : 0);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini beside the user's files
  ImGui::StyleColorsLight();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");

  int status = 0;
  {
    App app;
    app.session = Session(make_cube());
    app.window = window;
    app.autosave_enabled = !no_autosave && script.empty();
    ScriptHooks hooks;
    hooks.print = [](const std::string& text) { std::cout << text << "\n"; };
    hooks.screenshot = [&](const std::string& path) { screenshot(app, hooks, path); };
    try {
      app.main_view.renderer = std::make_unique<Renderer>();
      if (!file.empty()) {
        const std::string autosave = autosave_path(file);
        if (autosave_is_newer(autosave, file)) {
          if (recover) {
            open_file(app.session, autosave);
            app.session.path = file;
            app.session.document.mark_modified();
            app.status = "recovered " + autosave;
          } else {
            open_file(app.session, file);
            if (script.empty() && !exit_after) {
              app.show_recover_dialog = true;
              app.recover_path = autosave;
            } else {
              std::cerr << "stitch-modeler: note: " << autosave << " is newer than " << file
                        << "; run with --recover to load it\n";
            }
          }
        } else {
          open_file(app.session, file);
        }
      } else if (recover && autosave_is_newer(autosave_path(""), "")) {
        open_file(app.session, autosave_path(""));
        app.session.path.clear();
        app.session.document.mark_modified();
      }
      after_change(app, true);

      bool quit = false;
      if (!script.empty()) {
        const auto lines = read_lines(script);
        for (size_t i = 0; i < lines.size() && !quit; ++i) {
          try {
            if (run_ui_line(app, lines[i])) continue;
            const DisplaySettings before = app.session.display;
            const std::string path_before = app.session.path;
            const ScriptResult r = run_script_line(app.session, lines[i], hooks);
            quit = r.quit;
            const DisplaySettings& now = app.session.display;
            const bool full = now.method != before.method || now.resolution != before.resolution ||
                              now.input_polygons != before.input_polygons ||
                              now.split != before.split || app.session.path != path_before ||
                              app.session.last_update.full;
            after_change(app, full);
          } catch (const std::exception& e) {
            std::cerr << script << ":" << i + 1 << ": " << e.what() << "\n";
            status = 2;
            quit = true;
          }
        }
      }
      if (status == 0 && !shot.empty()) screenshot(app, hooks, shot);
      if (exit_after) quit = true;

      auto last_frame = Clock::now();
      while (!quit && !glfwWindowShouldClose(window)) {
        glfwPollEvents();
        render_frame(app, hooks, true);
        glfwSwapBuffers(window);
        const auto now = Clock::now();
        const double dt = std::chrono::duration<double>(now - last_frame).count();
        last_frame = now;
        if (dt > 0) app.fps = 0.9 * app.fps + 0.1 / dt;
        if (std::chrono::duration<double>(now - app.last_autosave).count() > autosave_interval_s)
          write_autosave(app);
      }
      write_autosave(app);  // on a clean exit, if there are unsaved changes
    } catch (const std::exception& e) {
      std::cerr << "stitch-modeler: " << e.what() << "\n";
      status = 2;
    }
    app.half.release();
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return status;
}
