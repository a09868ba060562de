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

std::vector<std::string> read_lines(const std::string& path) {
  std::istringstream in(read_regular_file(path));
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

}  // namespace

std::vector<ScriptCommand> window_commands(App& app) {
  // The rows hold the window they act on, so they are made per App rather than kept in a table.
  auto ui = [&app](Session&, const ScriptLine& line, const ScriptHooks&) {
    const std::string value = line.rest();
    if (value != "on" && value != "off") throw UsageError("usage: ui on|off");
    app.layout.show_ui = value == "on";
    return ScriptResult{};
  };
  auto dialog = [&app](Session&, const ScriptLine& line, const ScriptHooks&) {
    const std::string action = line.words.size() > 1 ? line.words[1] : "";
    if (action == "close") {
      close_file_dialog(app);
      return ScriptResult{};
    }
    if (action.empty()) throw UsageError("usage: dialog open|append|save|export [FOLDER] | close");
    const std::string action_and_folder = line.rest();
    const std::string folder = ScriptLine{action_and_folder, {}}.rest();
    request_file_dialog(app, parse_file_action(action), folder);
    return ScriptResult{};
  };
  auto layout = [&app](Session&, const ScriptLine& line, const ScriptHooks&) {
    const std::string path = line.rest();
    if (path.empty()) throw UsageError("usage: layout PATH (the screen layout as JSON)");
    // Two frames: ImGui sizes new windows in the first.
    for (int i = 0; i < 2; ++i) render_frame(app, false);
    write_layout_report(app, path);
    return ScriptResult{};
  };
  return {
      {"ui", "ui on|off", "shows or hides the panels (for pictures)", ui},
      {"dialog", "dialog open|append|save|export [FOLDER] | close",
       "opens the file dialog of an action on FOLDER (for pictures and layout checks), or closes "
       "it",
       dialog},
      {"layout", "layout PATH", "writes the screen layout as JSON (apps/modeler/layout_report.hpp)",
       layout},
  };
}

ScriptResult run_app_line(App& app, std::string_view line) {
  Session& s = app.session;
  // The window's own lines change nothing in the session: nothing to upload after them.
  if (const ScriptLine read = read_script_line(line);
      !read.words.empty() && find_script_command(app.hooks.commands, read.words[0]))
    return run_script_line(s, line, app.hooks);
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
