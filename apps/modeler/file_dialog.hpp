// The modeler's file dialogs: Open, Append, Save as and Export, each asking for a path and then
// running the script line `open PATH`, `append PATH`, `save PATH` or `export PATH`.
#pragma once

#include <array>
#include <optional>
#include <string>

namespace stitch::modeler::app {

struct App;

enum class FileAction { open, append, save_as, export_surface };

struct FileDialogs {
  /// The dialog a menu asked for, opened at the next frame's dialogs (ImGui wants modal popups
  /// opened outside the menu that asks for them).
  std::optional<FileAction> requested;
  std::array<char, 512> open_path{}, save_path{}, export_path{};
};

/// Asks for the dialog of `action` (File menu).
void request_file_dialog(App& app, FileAction action);
/// Draws the open dialog, if any; begun after every other window, so that it is on top.
void file_dialogs(App& app);

}  // namespace stitch::modeler::app
