// The modeler's script language (`stitch-modeler --script`, the command-line field, the GUI's
// buttons): one command per line, `#` starting a comment. A line is, in this order, any
// `stitch edit --ops` line (operation_table(), docs/editing.md), a row of script_command_table()
// (the session's lines), or a row of ScriptHooks::commands (the application's lines about its
// window: `ui`, `dialog`, `layout` in apps/modeler/commands.cpp). The tables are the reference:
// `help` prints them, and docs/modeler.md describes every row (a test checks that it names each).
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace stitch::modeler {

struct Session;
struct ScriptHooks;

/// What a line did, for the application.
struct ScriptResult {
  bool quit = false;
  std::string message;  ///< what happened, for the status bar / log
};

/// A line as the commands read it.
struct ScriptLine {
  std::string_view text;           ///< the line without its comment
  std::vector<std::string> words;  ///< its words; the first is the command's name
  /// The text after the first word, trimmed: a path, which may contain blanks.
  [[nodiscard]] std::string rest() const;
};

/// The line without its `# comment` (a '#' at the start or after a blank; V@F#k keeps its '#'),
/// split into words.
ScriptLine read_script_line(std::string_view line);

/// One row of a script table. A std::function, so that the application's rows can hold the
/// window they act on. The synopsis and help are strings, built from the library's tables where a
/// line takes their names (methods, display modes, output formats).
struct ScriptCommand {
  std::string_view name;  ///< the line's first word
  std::string synopsis;   ///< the line with placeholders; starts with the name
  std::string help;       ///< what it does, in one line
  /// Runs the line. Throws stitch::Error (UsageError for a bad line) saying what is wrong; the
  /// session is unchanged by a refused line.
  std::function<ScriptResult(Session&, const ScriptLine&, const ScriptHooks&)> run;
};

/// The session's script commands, in the order `help` and messages list them.
std::span<const ScriptCommand> script_command_table();

/// The row of `table` named `name`, or nullptr.
const ScriptCommand* find_script_command(std::span<const ScriptCommand> table,
                                         std::string_view name);

/// What a script line needs from the application.
struct ScriptHooks {
  std::function<void(const std::string& path)> screenshot;  ///< renders the view to a PNG
  std::function<void(const std::string& text)> print;       ///< `info`, `help`, operation reports
  /// The application's own lines, run when a line is neither an operation nor a session command.
  std::vector<ScriptCommand> commands;
  /// When set, run_script runs each line through this instead of run_script_line, so that the
  /// application can upload what a line changed. It throws on a bad line, as run_script_line
  /// does.
  std::function<ScriptResult(std::string_view line)> run_line;
};

/// Runs one line: an operation, else a row of script_command_table(), else a row of
/// hooks.commands. Throws stitch::Error (UsageError for a bad line or an unknown command) saying
/// what is wrong; the session is unchanged by a refused line.
ScriptResult run_script_line(Session& session, std::string_view line, const ScriptHooks& hooks);

/// A script error with its 1-based line number.
struct ScriptError {
  int line = 0;
  std::string message;
};
/// Runs lines (through hooks.run_line when set) until the end or `quit`; stops at the first
/// error and returns it. `quit` tells whether the script asked to quit.
std::optional<ScriptError> run_script(Session& session, const std::vector<std::string>& lines,
                                      const ScriptHooks& hooks, bool* quit = nullptr);

}  // namespace stitch::modeler
