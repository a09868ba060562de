// The modeler's file dialogs: Open, Append, Save as and Export, each a file browser (the
// window-free stitch/modeler/file_browser.hpp, drawn here with ImGui) that runs the script line
// `open PATH`, `append PATH [--offset X,Y,Z]`, `save PATH` or `export PATH` on the chosen file.
// Keys: up/down arrows move through the list, Enter opens a folder or chooses the file,
// Backspace in an empty name field goes to the parent folder, typing names a file.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>

#include "stitch/modeler/file_browser.hpp"

namespace stitch::modeler::app {

struct App;

enum class FileAction { open, append, save_as, export_surface };

/// The dialog on screen.
struct OpenFileDialog {
  FileAction action;
  FileBrowser browser;
  std::array<char, 512> name{};   ///< the name field, kept equal to browser.name()
  std::array<char, 64> offset{};  ///< Append's offset "X,Y,Z" (empty: none)
  bool scroll_to_highlight = false;
  std::string error;  ///< why the last choice failed (the script line's error)
};

struct FileDialogs {
  explicit FileDialogs(std::filesystem::path recent_file) : recent(std::move(recent_file)) {}
  RecentFiles recent;
  /// Asked for by the menu or a script; opened as a modal popup at the next frame (ImGui wants
  /// popups opened outside the menu that asks for them).
  std::optional<OpenFileDialog> pending, shown;
};

/// Asks for the dialog of `action`, browsing `folder` (default: the document's folder, or the
/// working folder for an untitled document).
void request_file_dialog(App& app, FileAction action, std::filesystem::path folder = {});
/// Closes the dialog, if one is shown.
void close_file_dialog(App& app);
/// Parses "open", "append", "save", "export"; throws UsageError otherwise.
FileAction parse_file_action(const std::string& name);
/// Draws the dialog, if any; begun after every other window, so that it is on top.
void file_dialogs(App& app);

}  // namespace stitch::modeler::app
