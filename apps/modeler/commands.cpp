#include "commands.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <sstream>
#include <vector>

#include "stitch/mesh/io.hpp"
#include "viewport.hpp"

namespace stitch::modeler::app {

namespace {

/// The application's own lines, about the window rather than the session: `ui on|off`.
/// Returns false for any other line.
bool run_window_line(App& app, std::string_view line) {
  std::istringstream in{std::string(line)};
  std::string word, value, extra;
  if (!(in >> word) || word != "ui") return false;
  if (!(in >> value) || (value != "on" && value != "off") || (in >> extra && extra[0] != '#'))
    throw MeshError("usage: ui on|off");
  app.layout.show_ui = value == "on";
  return true;
}

std::vector<std::string> read_lines(const std::string& path) {
  std::istringstream in(read_regular_file(path));
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

}  // namespace

ScriptResult run_app_line(App& app, std::string_view line) {
  if (run_window_line(app, line)) return {};
  Session& s = app.session;
  const DisplaySettings before = s.display;
  const std::string path_before = s.path;
  const bool was_modified = s.document.modified();
  ScriptResult r = run_script_line(s, line, app.hooks);
  const DisplaySettings& now = s.display;
  const bool full = now.method != before.method || now.resolution != before.resolution ||
                    now.input_polygons != before.input_polygons || now.split != before.split ||
                    s.path != path_before || s.last_update.full;
  // A save leaves nothing to recover.
  if (was_modified && !s.document.modified() && line.starts_with("save")) remove_autosave(app);
  // run_script_line kept the surface current; what changed is in session.surface.recomputed().
  after_change(app, full);
  return r;
}

void run_line(App& app, const std::string& line) {
  try {
    const ScriptResult r = run_app_line(app, line);
    if (!r.message.empty()) app.status = r.message;
    if (r.quit) glfwSetWindowShouldClose(app.window, GLFW_TRUE);
  } catch (const std::exception& e) {
    app.status = e.what();
  }
}

int run_script_file(App& app, const std::string& path, bool& quit) {
  quit = false;
  std::vector<std::string> lines;
  try {
    lines = read_lines(path);
  } catch (const std::exception& e) {
    std::cerr << "stitch-modeler: " << e.what() << "\n";
    return 2;
  }
  ScriptHooks hooks = app.hooks;
  hooks.run_line = [&app](std::string_view line) { return run_app_line(app, line); };
  if (const auto error = run_script(app.session, lines, hooks, &quit)) {
    std::cerr << path << ":" << error->line << ": " << error->message << "\n";
    quit = true;
    return 2;
  }
  return 0;
}

void write_autosave(App& app) {
  if (!app.autosave.enabled || !app.session.document.modified()) return;
  const std::string path = autosave_path(app.session.path);
  try {
    if (const auto folder = std::filesystem::path(path).parent_path(); !folder.empty())
      std::filesystem::create_directories(folder);
    save_project(path, app.session.project());
  } catch (const std::exception& e) {
    app.status = fmt::format("autosave failed: {}", e.what());
    std::cerr << "stitch-modeler: " << app.status << "\n";
  }
  app.autosave.last = Clock::now();
}

void remove_autosave(const App& app) {
  std::error_code ec;
  std::filesystem::remove(autosave_path(app.session.path), ec);
}

}  // namespace stitch::modeler::app
