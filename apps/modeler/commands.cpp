#include "commands.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <sstream>
#include <vector>

#include "file_dialog.hpp"
#include "frame.hpp"
#include "layout_report.hpp"
#include "stitch/mesh/io.hpp"
#include "viewport.hpp"

namespace stitch::modeler::app {

namespace {

/// The rest of the line after its first word, without a comment (paths may contain blanks).
std::string argument_of(std::string_view line) {
  std::string rest{line.substr(0, line.find('#'))};
  const size_t word_end = rest.find_first_of(" \t", rest.find_first_not_of(" \t"));
  if (word_end == std::string::npos) return "";
  rest.erase(0, word_end);
  rest.erase(0, rest.find_first_not_of(" \t"));
  rest.erase(rest.find_last_not_of(" \t\r") + 1);
  return rest;
}

/// The application's own lines, about the window rather than the session: `ui on|off`,
/// `dialog ...`, `layout PATH`. Returns false for any other line.
bool run_window_line(App& app, std::string_view line) {
  std::istringstream in{std::string(line)};
  std::string word;
  if (!(in >> word)) return false;
  if (word == "ui") {
    const std::string value = argument_of(line);
    if (value != "on" && value != "off") throw UsageError("usage: ui on|off");
    app.layout.show_ui = value == "on";
    return true;
  }
  if (word == "dialog") {
    // The file dialogs, for pictures and layout checks: `dialog open|append|save|export
    // [FOLDER]`, `dialog close`.
    std::string action, folder;
    in >> action;
    const std::string rest = argument_of(argument_of(line));
    if (action == "close") {
      close_file_dialog(app);
      return true;
    }
    if (action.empty()) throw UsageError("usage: dialog open|append|save|export [FOLDER] | close");
    request_file_dialog(app, parse_file_action(action), rest);
    return true;
  }
  if (word == "layout") {
    const std::string path = argument_of(line);
    if (path.empty()) throw UsageError("usage: layout PATH (the screen layout as JSON)");
    // Two frames: ImGui sizes new windows in the first.
    for (int i = 0; i < 2; ++i) render_frame(app, false);
    write_layout_report(app, path);
    return true;
  }
  return false;
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
