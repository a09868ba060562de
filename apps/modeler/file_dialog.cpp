#include "file_dialog.hpp"

#include <imgui.h>

#include <cstdio>
#include <string>

#include "app_state.hpp"
#include "commands.hpp"

namespace stitch::modeler::app {

namespace {

const char* title_of(FileAction action) {
  switch (action) {
    case FileAction::open:
      return "Open file";
    case FileAction::append:
      return "Append file";
    case FileAction::save_as:
      return "Save as";
    case FileAction::export_surface:
      return "Export smooth surface";
  }
  return "";
}

/// A modal asking for a path, which runs the script line `command PATH` on `button`.
void path_dialog(App& app, FileAction action, const char* label, std::array<char, 512>& path,
                 const char* button, const char* command) {
  if (!ImGui::BeginPopupModal(title_of(action), nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ImGui::InputText(label, path.data(), path.size());
  if (ImGui::Button(button)) {
    run_line(app, std::string(command) + " " + path.data());
    ImGui::CloseCurrentPopup();
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

}  // namespace

void request_file_dialog(App& app, FileAction action) {
  if (action == FileAction::save_as)
    std::snprintf(app.files.save_path.data(), app.files.save_path.size(), "%s",
                  app.session.path.c_str());
  app.files.requested = action;
}

void file_dialogs(App& app) {
  FileDialogs& f = app.files;
  if (f.requested) ImGui::OpenPopup(title_of(*f.requested));
  f.requested.reset();
  path_dialog(app, FileAction::open, "path (.obj .off .ply .stl .glb .gltf .stitch)", f.open_path,
              "Open", "open");
  // Shares Open's path: the second mesh is usually beside the first.
  path_dialog(app, FileAction::append,
              "path (.obj .off .ply .stl .glb .gltf .stitch; may end in --offset X,Y,Z)",
              f.open_path, "Append", "append");
  path_dialog(app, FileAction::save_as, "path (.stitch keeps K-gons and view)", f.save_path, "Save",
              "save");
  path_dialog(app, FileAction::export_surface,
              "path (.ply .obj .off .stl .glb .gltf; .json: Bezier patches)", f.export_path,
              "Export", "export");
}

}  // namespace stitch::modeler::app
