#include "frame.hpp"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "file_dialog.hpp"
#include "input.hpp"
#include "panels.hpp"
#include "stitch/render/image.hpp"
#include "viewport.hpp"

namespace stitch::modeler::app {

namespace {

/// The whole window, for the 3D view when the panels are hidden.
ScreenRect whole_window() {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  return {vp->Pos.x, vp->Pos.y, vp->Pos.x + vp->Size.x, vp->Pos.y + vp->Size.y};
}

}  // namespace

void FrameTimer::drawn(double milliseconds) {
  draw_ms[drawn_count % kKept] = milliseconds;
  ++drawn_count;
}

void FrameTimer::shown(Clock::time_point when) {
  if (last_shown) {
    const double dt = std::chrono::duration<double>(when - *last_shown).count();
    if (dt > 0) shown_fps = shown_fps > 0 ? 0.9 * shown_fps + 0.1 / dt : 1.0 / dt;
  }
  last_shown = when;
}

double FrameTimer::median_draw_ms() const {
  const int n = std::min(drawn_count, kKept);
  if (n == 0) return 0.0;
  std::array<double, kKept> sorted = draw_ms;
  std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.begin() + n);
  return sorted[n / 2];
}

double FrameTimer::fps() const {
  if (shown_fps > 0) return shown_fps;
  const double ms = median_draw_ms();
  return ms > 0 ? 1000.0 / ms : 0.0;
}

void render_frame(App& app, bool interactive) {
  const auto start = Clock::now();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  app.layout.panels.clear();
  app.layout.labels.clear();
  if (interactive) {
    handle_mouse(app);
    handle_keys(app);
  }
  if (app.layout.show_ui)
    draw_panels(app);  // sets layout.viewport
  else
    app.layout.viewport = whole_window();
  // Framing (`frame all`, the views) fits the model to the area it is drawn in.
  app.session.viewport_width = app.layout.viewport.width();
  app.session.viewport_height = app.layout.viewport.height();
  file_dialogs(app);
  recover_dialog(app);
  ImGui::Render();
  draw_scene(app);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  glFinish();  // the frame's time includes the GL's work, not just issuing it
  app.frames.drawn(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
}

void screenshot(App& app, const std::string& path) {
  // Two frames: ImGui sizes new windows in the first.
  for (int i = 0; i < 2; ++i) render_frame(app, false);
  int w = 0, h = 0;
  glfwGetFramebufferSize(app.window, &w, &h);
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

}  // namespace stitch::modeler::app
