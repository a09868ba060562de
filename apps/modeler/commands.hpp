// Running script lines in the application: the session's lines (script_commands.hpp) plus the
// application's own (`ui on|off`, window_commands), each followed by uploading what it changed. The
// GUI's buttons, the command-line field and `--script` all run lines through run_app_line, and a
// script file runs through the library's run_script loop.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "app_state.hpp"

namespace stitch::modeler::app {

/// The application's own script lines, about the window rather than the session (`ui`, `dialog`,
/// `layout`): rows for ScriptHooks::commands, which act on `app`.
std::vector<ScriptCommand> window_commands(App& app);
/// Runs one line and uploads what it changed. Throws on a bad line (which changes nothing).
ScriptResult run_app_line(App& app, std::string_view line);
/// Runs one line the way the GUI does: the message or the error goes to the status bar.
void run_line(App& app, const std::string& line);
/// Runs the script file `path` (library run_script); an error is printed as `PATH:LINE:
/// message`. Returns 0, or 2 after an error; `quit` tells whether the script asked to quit.
int run_script_file(App& app, const std::string& path, bool& quit);

/// Writes the unsaved work to the autosave project, if autosaving and modified.
void write_autosave(App& app);
void remove_autosave(const App& app);

}  // namespace stitch::modeler::app
