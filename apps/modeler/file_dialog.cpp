#include "file_dialog.hpp"

#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "app_state.hpp"
#include "commands.hpp"
#include "stitch/mesh/io.hpp"
#include "widgets.hpp"

namespace stitch::modeler::app {

namespace fs = std::filesystem;

namespace {

/// Records a Selectable's label: its box reaches across the window and half an item spacing
/// beyond, so the text's own extent is recorded, from where ImGui draws it.
void record_selectable(ScreenLayout& layout, const std::string& label) {
  record_label(layout, label, std::floor(ImGui::GetStyle().ItemSpacing.x * 0.5f));
}

struct ActionText {
  const char* title;
  const char* button;
  const char* command;
};

ActionText text_of(FileAction action) {
  switch (action) {
    case FileAction::open:
      return {"Open", "Open", "open"};
    case FileAction::append:
      return {"Append", "Append", "append"};
    case FileAction::save_as:
      return {"Save as", "Save", "save"};
    case FileAction::export_surface:
      return {"Export smooth surface", "Export", "export"};
  }
  return {"", "", ""};
}

/// The popup's name: the action's title, then (after ###, which ImGui's IDs start from) one ID
/// for every action, so that a new request replaces the dialog shown.
std::string popup_name(FileAction action) {
  return std::string(text_of(action).title) + "###file-dialog";
}

std::vector<std::string> extensions_of(FileAction action) {
  switch (action) {
    case FileAction::open:
    case FileAction::append:
      return open_extensions();
    case FileAction::save_as:
      return save_extensions();
    case FileAction::export_surface:
      return export_extensions();
  }
  return {};
}

void copy_name(OpenFileDialog& d) {
  std::snprintf(d.name.data(), d.name.size(), "%s", d.browser.name().c_str());
}

/// Runs the action's script line on `path`; on success remembers the file and closes.
void choose(App& app, OpenFileDialog& d, const fs::path& path) {
  std::string line = std::string(text_of(d.action).command) + " " + path.string();
  if (d.action == FileAction::append && d.offset[0])
    line += fmt::format(" --offset {}", d.offset.data());
  try {
    const ScriptResult r = run_app_line(app, line);
    if (!r.message.empty()) app.status = r.message;
  } catch (const std::exception& e) {
    d.error = e.what();
    return;
  }
  try {
    app.files.recent.add(path);
  } catch (const std::exception& e) {
    app.status = e.what();  // the file was opened or written; only the list could not be kept
  }
  ImGui::CloseCurrentPopup();
  app.files.shown.reset();
}

/// The keys of the browser, while its dialog has the keyboard.
void handle_keys(OpenFileDialog& d, bool name_field_active) {
  FileBrowser& b = d.browser;
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_UpArrow))) {
    b.move(-1);
    copy_name(d);
    d.scroll_to_highlight = true;
  }
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_DownArrow))) {
    b.move(1);
    copy_name(d);
    d.scroll_to_highlight = true;
  }
  // Backspace in an empty field: the field has nothing to delete, so it means "up".
  if (name_field_active && d.name[0] == '\0' &&
      ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Backspace))) {
    b.backspace_on_empty_name();
    d.scroll_to_highlight = true;
  }
}

void enter(App& app, OpenFileDialog& d) {
  d.error.clear();
  if (const auto path = d.browser.enter()) {
    choose(app, d, *path);
  } else {
    copy_name(d);
    d.scroll_to_highlight = true;
  }
}

void draw_dialog(App& app, OpenFileDialog& d) {
  ScreenLayout& layout = app.layout;
  Widgets ui(layout);
  FileBrowser& b = d.browser;
  const ImGuiStyle& style = ImGui::GetStyle();

  ui.text("Folder: " + elided(b.folder().string(), ems(26)));
  ImGui::SameLine();
  if (ui.button("Up")) b.backspace_on_empty_name();

  // The listing: folders first, the highlighted entry selected.
  const float list_height = ImGui::GetTextLineHeightWithSpacing() * 12 + 2 * style.FramePadding.y;
  ImGui::BeginChild("##entries", ImVec2(ems(32), list_height), true);
  std::optional<int> clicked, double_clicked;
  for (int i = 0; i < int(b.entries().size()); ++i) {
    const FileEntry& e = b.entries()[i];
    const std::string label = elided(e.is_folder ? e.name + "/" : e.name, ems(29));
    ImGui::PushID(i);
    if (ImGui::Selectable(label.c_str(), i == b.highlighted(),
                          ImGuiSelectableFlags_AllowDoubleClick)) {
      clicked = i;
      if (ImGui::IsMouseDoubleClicked(0)) double_clicked = i;
    }
    record_selectable(layout, label);
    if (i == b.highlighted() && d.scroll_to_highlight) ImGui::SetScrollHereY();
    ImGui::PopID();
  }
  if (b.entries().empty()) ImGui::TextDisabled("(no matching files)");
  d.scroll_to_highlight = false;
  ImGui::EndChild();
  if (clicked) {
    b.highlight(*clicked);
    copy_name(d);
    if (double_clicked) enter(app, d);
    if (!app.files.shown) return;  // chosen: the dialog is gone
  }

  // The name field has the keyboard: typing names a file, Enter chooses.
  ImGui::AlignTextToFramePadding();
  ui.text("Name:");
  ImGui::SameLine();
  if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
  ImGui::SetNextItemWidth(ems(28));
  const bool entered = ImGui::InputText("##name", d.name.data(), d.name.size(),
                                        ImGuiInputTextFlags_EnterReturnsTrue);
  const bool field_active = ImGui::IsItemActive();
  if (ImGui::IsItemEdited()) b.set_name(d.name.data());
  handle_keys(d, field_active);
  if (entered) {
    b.set_name(d.name.data());
    enter(app, d);
    if (!app.files.shown) return;
    ImGui::SetKeyboardFocusHere(-1);  // keep typing after opening a folder
  }

  // The filter: the formats of the action, or all files.
  const std::string formats = [&] {
    std::string list;
    for (const std::string& e : b.extensions()) list += (list.empty() ? "" : " ") + e;
    return list;
  }();
  int filter = b.showing_all_files() ? 1 : 0;
  const std::string shown_formats = elided(formats, ems(24));
  const char* filters[] = {shown_formats.c_str(), "all files"};
  ImGui::SetNextItemWidth(ems(28));
  if (ui.combo("files", &filter, filters, 2)) b.show_all_files(filter == 1);

  if (d.action == FileAction::append) {
    ImGui::SetNextItemWidth(ems(10));
    ImGui::InputText("offset X,Y,Z (optional)", d.offset.data(), d.offset.size());
    record_label(layout, "offset X,Y,Z (optional)");
  }

  // Recent files of the action's formats: a click puts the path in the name field.
  const auto& recent = app.files.recent.paths();
  std::vector<const std::string*> matching;
  for (const std::string& p : recent)
    if (b.showing_all_files() || has_extension(p, b.extensions())) matching.push_back(&p);
  if (!matching.empty() && ui.header("Recent files", ImGuiTreeNodeFlags_DefaultOpen)) {
    for (const std::string* p : matching) {
      const std::string label = elided(*p, ems(30));
      if (ImGui::Selectable(label.c_str())) {
        b.set_name(*p);
        copy_name(d);
      }
      record_selectable(layout, label);
    }
  }

  const std::string& error = !d.error.empty() ? d.error : b.error();
  if (!error.empty()) {
    const std::string shown = elided(error, ems(32));
    ImGui::TextColored(ImVec4(0.8f, 0.1f, 0.1f, 1.0f), "%s", shown.c_str());
    record_label(layout, shown);
  }
  if (ui.button(text_of(d.action).button)) {
    b.set_name(d.name.data());
    enter(app, d);
    if (!app.files.shown) return;
  }
  ImGui::SameLine();
  if (ui.button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
    ImGui::CloseCurrentPopup();
    app.files.shown.reset();
  }
}

}  // namespace

FileAction parse_file_action(const std::string& name) {
  if (name == "open") return FileAction::open;
  if (name == "append") return FileAction::append;
  if (name == "save") return FileAction::save_as;
  if (name == "export") return FileAction::export_surface;
  throw UsageError("unknown file dialog '" + name + "' (open, append, save or export)");
}

void request_file_dialog(App& app, FileAction action, fs::path folder) {
  const Session& s = app.session;
  if (folder.empty() && !s.path.empty()) folder = fs::absolute(s.path).parent_path();
  const bool must_exist = action == FileAction::open || action == FileAction::append;
  OpenFileDialog d{action, FileBrowser(folder, extensions_of(action), must_exist), {}, {}, false,
                   {}};
  // Save as starts from the document's own name.
  if (action == FileAction::save_as && !s.path.empty())
    d.browser.set_name(fs::path(s.path).filename().string());
  // Export proposes the first output format (the dialog's first extension).
  if (action == FileAction::export_surface)
    d.browser.set_name("smooth" + d.browser.extensions().front());
  copy_name(d);
  app.files.pending = std::move(d);
}

void close_file_dialog(App& app) {
  app.files.pending.reset();
  app.files.shown.reset();
}

void file_dialogs(App& app) {
  FileDialogs& f = app.files;
  if (f.pending) {
    f.shown = std::move(f.pending);
    f.pending.reset();
    ImGui::OpenPopup(popup_name(f.shown->action).c_str());
  }
  if (!f.shown) return;
  if (!ImGui::BeginPopupModal(popup_name(f.shown->action).c_str(), nullptr,
                              ImGuiWindowFlags_AlwaysAutoResize)) {
    f.shown.reset();  // closed by ImGui
    return;
  }
  draw_dialog(app, *f.shown);
  if (f.shown) record_panel(app.layout);
  ImGui::EndPopup();
}

}  // namespace stitch::modeler::app
