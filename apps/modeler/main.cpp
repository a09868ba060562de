// stitch-modeler: the interactive modeler. A thin GLFW + Dear ImGui layer: every edit is a
// script line run by the window-free session (include/stitch/modeler/session.hpp), the surface is
// kept up to date incrementally by stitch::IncrementalSurface, and the renderer re-uploads only the
// patches an edit changed. This file starts the window and runs the loop; app_state.hpp lists the
// parts.
#include <fmt/format.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

#include "app_state.hpp"
#include "commands.hpp"
#include "frame.hpp"
#include "stitch/mesh/formats.hpp"
#include "stitch/project/project_file.hpp"
#include "stitch/render/options.hpp"
#include "stitch/topology/primitives.hpp"
#include "viewport.hpp"

namespace stitch::modeler::app {

namespace {

constexpr double kAutosaveIntervalSeconds = 180.0;

struct Options {
  std::string file, script, screenshot;
  bool exit_after = false, recover = false, no_autosave = false;
  ImageSize size;
  float font_scale = 1.0f;
};

/// Opens the document (or the newer autosave with --recover, or offers it in a dialog).
void open_document(App& app, const Options& o) {
  Session& s = app.session;
  if (o.file.empty()) {
    if (o.recover && autosave_is_newer(autosave_path(""), "")) {
      open_file(s, autosave_path(""));
      s.path.clear();
      s.document.mark_modified();
    }
    return;
  }
  const std::string autosave = autosave_path(o.file);
  // The status says what was opened, and which tubes' controls were chosen.
  if (!autosave_is_newer(autosave, o.file)) {
    app.status = open_file(s, o.file);
  } else if (o.recover) {
    open_file(s, autosave);
    s.path = o.file;
    s.document.mark_modified();
    app.status = "recovered " + autosave;
  } else {
    app.status = open_file(s, o.file);
    if (o.script.empty() && !o.exit_after) {
      app.autosave.offer_pending = true;
      app.autosave.offered_path = autosave;
    } else {
      std::cerr << "stitch-modeler: note: " << autosave << " is newer than " << o.file
                << "; run with --recover to load it\n";
    }
  }
  // Printed as the `open` line prints it.
  if (const auto& u = s.tube_unfoldings(); !u.empty())
    app.hooks.print(describe_unfoldings(s.document.mesh(), u));
}

/// The modeler in its window: the document, the script, the screenshot, then the loop.
int run(GLFWwindow* window, const Options& o) {
  App app(window);
  app.layout.font_scale = o.font_scale;
  app.autosave.enabled = !o.no_autosave && o.script.empty();
  app.hooks.print = [](const std::string& text) { std::cout << text << "\n"; };
  app.hooks.screenshot = [&app](const std::string& path) { screenshot(app, path); };
  app.hooks.commands = window_commands(app);
  app.views.main.renderer = std::make_unique<Renderer>();
  // Two frames lay the panels out (ImGui sizes new windows in the first), so that the document
  // is framed in the area they leave.
  for (int i = 0; i < 2; ++i) render_frame(app, false);
  app.session.view.set_standard(View::iso, app.session.mesh_bounds(), app.session.view_aspect());
  open_document(app, o);
  after_change(app, true);
  // A file opened by hand joins the recent files (not in a script or a --exit run).
  if (!o.file.empty() && o.script.empty() && !o.exit_after) {
    try {
      app.files.recent.add(o.file);
    } catch (const std::exception& e) {
      app.status = e.what();
    }
  }

  int status = 0;
  bool quit = false;
  if (!o.script.empty()) status = run_script_file(app, o.script, quit);
  if (status == 0 && !o.screenshot.empty()) screenshot(app, o.screenshot);
  if (o.exit_after) quit = true;

  while (!quit && !glfwWindowShouldClose(window)) {
    glfwPollEvents();
    render_frame(app, true);
    glfwSwapBuffers(window);
    const auto now = Clock::now();
    app.frames.shown(now);
    if (std::chrono::duration<double>(now - app.autosave.last).count() > kAutosaveIntervalSeconds)
      write_autosave(app);
  }
  write_autosave(app);  // on a clean exit, if there are unsaved changes
  return status;
}

}  // namespace

App::App(GLFWwindow* w)
    : session(make_cube()),
      window(w),
      files(recent_files_path(std::getenv("XDG_CONFIG_HOME"), std::getenv("HOME"))) {}

}  // namespace stitch::modeler::app

int main(int argc, char** argv) {
  using namespace stitch;
  CLI::App cli{"stitch-modeler: interactive smooth modeling with topology changes"};
  modeler::app::Options o;
  std::string size_text = "1280x800";
  cli.add_option("FILE", o.file,
                 fmt::format("mesh ({}) or project ({}) to open; default: a cube",
                             extension_list(kMeshReadExtensions), kProjectExtensions.front()));
  cli.add_option("--script", o.script, "run the lines of this file (see docs/modeler.md)");
  cli.add_option("--screenshot", o.screenshot, "after the script, write the window to this PNG");
  cli.add_flag("--exit", o.exit_after, "quit after the script and screenshot");
  cli.add_flag("--recover", o.recover, "load the autosave newer than FILE instead of FILE");
  cli.add_flag("--no-autosave", o.no_autosave, "do not write autosaves");
  cli.add_option("--size", size_text, "window size WxH")->capture_default_str();
  cli.add_option("--font-scale", o.font_scale,
                 "text and widget size, times the screen's own scale (e.g. 1.5)")
      ->check(CLI::Range(0.5f, 4.0f))
      ->capture_default_str();
  CLI11_PARSE(cli, argc, argv);
  try {
    o.size = parse_image_size(size_text, 4096);
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
  // The 3D view is multisampled in its own framebuffer (gl_objects.hpp); the window's is not,
  // since GL 3.3 cannot blit into a multisampled framebuffer.
  glfwWindowHint(GLFW_SAMPLES, 0);
  GLFWwindow* window =
      glfwCreateWindow(o.size.width, o.size.height, "stitch-modeler", nullptr, nullptr);
  if (!window) {
    std::cerr << "stitch-modeler: cannot open an OpenGL 3.3 core window\n";
    glfwTerminate();
    return 1;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(o.script.empty() ? 1 : 0);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini beside the user's files
  ImGui::StyleColorsLight();
  // The screen's scale (high-DPI monitors) times the one asked for: the font is rasterised at
  // that size rather than magnified, and the paddings and spacings grow with it.
  float screen_scale = 1.0f, unused = 1.0f;
  glfwGetWindowContentScale(window, &screen_scale, &unused);
  const float scale = o.font_scale * std::max(screen_scale, 1.0f);
  ImFontConfig font;
  // ImGui's default font is drawn for 13 pixels; whole pixels keep the layout's sizes whole
  // (a fraction of a pixel too much content gives a panel a scroll bar).
  font.SizePixels = std::round(13.0f * scale);
  ImGui::GetIO().Fonts->AddFontDefault(&font);
  ImGui::GetStyle().ScaleAllSizes(scale);
  o.font_scale = scale;
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");

  int status = 0;
  try {
    status = modeler::app::run(window, o);
  } catch (const std::exception& e) {
    std::cerr << "stitch-modeler: " << e.what() << "\n";
    status = 2;
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return status;
}
