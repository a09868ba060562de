#include "input.hpp"

#include <fmt/format.h>
#include <imgui.h>

#include <cmath>

#include "commands.hpp"
#include "viewport.hpp"

namespace stitch::modeler::app {

namespace {

/// Where the dragged vertex goes for the mouse ray `r`: in the view plane through its start, or
/// the point of the chosen axis line through its start closest to the ray.
Vec3 drag_target(const App& app, const Ray& r) {
  const Vec3 p0 = app.mouse.drag_origin;
  const OrbitView& view = app.session.view;
  if (app.mouse.tool == DragTool::view_plane) {
    const Vec3 n = (view.target - view.eye()).normalized();
    const double denom = r.direction.dot(n);
    return std::abs(denom) > 1e-9 ? r.origin + ((p0 - r.origin).dot(n) / denom) * r.direction : p0;
  }
  const Vec3 a = app.mouse.tool == DragTool::axis_x   ? Vec3::UnitX()
                 : app.mouse.tool == DragTool::axis_y ? Vec3::UnitY()
                                                      : Vec3::UnitZ();
  const Vec3 w0 = p0 - r.origin;
  const double b = a.dot(r.direction), d = a.dot(w0), e = r.direction.dot(w0);
  const double denom = 1 - b * b;
  return denom > 1e-9 ? p0 + ((b * e - d) / denom) * a : p0;
}

void drag_vertex(App& app, double x, double y) {
  Session& s = app.session;
  const Vec3 p = drag_target(app, mouse_ray(app, x, y));
  try {
    // The first motion of a drag starts an undo step; the rest extend it.
    s.apply(s.document.move_vertices({Vertex(s.selection->index)}, {p}, app.mouse.vertex_moved));
    app.mouse.vertex_moved = true;
    app.status = fmt::format("vertex {} at {:.3f} {:.3f} {:.3f}", s.selection->index + 1, p.x(),
                             p.y(), p.z());
    after_change(app, false);
  } catch (const std::exception& ex) {
    app.status = ex.what();
  }
}

void press(App& app, int button, double x, double y, bool ctrl) {
  Session& s = app.session;
  MouseGesture& m = app.mouse;
  m.button = button;
  m.press_x = m.last_x = x;
  m.press_y = m.last_y = y;
  m.moved = false;
  m.vertex_moved = false;
  m.dragging_vertex = button == 0 && ctrl && s.selection && s.selection->kind == PickKind::vertex;
  if (m.dragging_vertex) m.drag_origin = s.document.mesh().position(Vertex(s.selection->index));
}

void click(App& app, double x, double y) {
  Session& s = app.session;
  const auto p = pick(s.document.mesh(), mouse_ray(app, x, y), app.picking.kind);
  if (s.selection && (!p || !(*p == *s.selection))) app.picking.previous = s.selection;
  s.selection = p;
  if (p) app.status = "selected " + describe(s.document.mesh(), *p);
  app.views.overlays_dirty = true;
}

}  // namespace

void handle_mouse(App& app) {
  const ImGuiIO& io = ImGui::GetIO();
  Session& s = app.session;
  MouseGesture& m = app.mouse;
  double x = 0, y = 0;
  glfwGetCursorPos(app.window, &x, &y);
  if (!io.WantCaptureMouse) {
    if (io.MouseWheel != 0.0f) s.view.zoom(io.MouseWheel);
    for (int b = 0; b < 3; ++b)
      if (ImGui::IsMouseClicked(b)) press(app, b, x, y, io.KeyCtrl);
  }
  if (m.button < 0) return;
  const double dx = x - m.last_x, dy = y - m.last_y;
  if (std::abs(x - m.press_x) + std::abs(y - m.press_y) > 3) m.moved = true;
  if ((dx != 0 || dy != 0) && m.moved) {
    if (m.dragging_vertex)
      drag_vertex(app, x, y);
    else if (m.button == 0)
      s.view.orbit(dx, dy);
    else
      s.view.pan(dx, dy, app.layout.viewport.height());
    m.last_x = x;
    m.last_y = y;
  }
  if (!ImGui::IsMouseDown(m.button)) {
    if (!m.moved && m.button == 0 && !io.WantCaptureMouse) click(app, x, y);
    m.button = -1;
    m.dragging_vertex = false;
  }
}

void handle_keys(App& app) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureKeyboard) return;
  if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_Z)) run_line(app, "undo");
  if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_Y)) run_line(app, "redo");
  if (!io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_F))
    run_line(app, app.session.selection ? "frame selection" : "frame all");
  if (!io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_A)) run_line(app, "frame all");
}

}  // namespace stitch::modeler::app
