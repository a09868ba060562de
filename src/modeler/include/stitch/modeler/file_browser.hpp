// The logic of the modeler's file dialogs, without a window: listing a folder (folders first,
// files filtered by the extensions of the dialog's action), moving through it with the keys,
// choosing a file, and the list of recent files. The application draws it with ImGui
// (apps/modeler/file_dialog.cpp); the unit tests drive it directly.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stitch::modeler {

/// The files each dialog offers, from the format tables of the readers and writers (mesh/
/// formats.hpp, project/project_file.hpp, the output formats of stitch/output/output.hpp): lower
/// case, with the dot.
std::vector<std::string> open_extensions();  ///< Open and Append: meshes read, projects
std::vector<std::string> save_extensions();  ///< Save as: projects (first), meshes written
/// Export: every output format's extensions, in the table's order (its first format's first).
std::vector<std::string> export_extensions();

/// Whether `name` ends with one of `extensions` (compared without case; an extension may have
/// two dots, as .bez.json); true for an empty list (all files).
bool has_extension(std::string_view name, const std::vector<std::string>& extensions);

struct FileEntry {
  std::string name;
  bool is_folder = false;
  bool operator==(const FileEntry&) const = default;
};

/// The entries of `folder`: its subfolders, then its files with one of `extensions`
/// (has_extension), each group sorted by name without case
/// (ties in byte order). Names starting with '.' are left out. Throws InputError naming the
/// folder when it cannot be listed.
std::vector<FileEntry> list_folder(const std::filesystem::path& folder,
                                   const std::vector<std::string>& extensions);

/// A file dialog's state: the folder shown, its entries, the highlighted entry and the name
/// typed. Keys: move() for the arrows, enter() for Enter, backspace_on_empty_name() for
/// Backspace when nothing is typed, set_name() for typing.
class FileBrowser {
 public:
  /// `must_exist`: the chosen file must exist (Open, Append); otherwise a name without one of
  /// the extensions gets the first (Save as, Export).
  FileBrowser(std::filesystem::path folder, std::vector<std::string> extensions, bool must_exist);

  [[nodiscard]] const std::filesystem::path& folder() const { return folder_; }
  [[nodiscard]] const std::vector<FileEntry>& entries() const { return entries_; }
  [[nodiscard]] const std::vector<std::string>& extensions() const { return extensions_; }
  /// The highlighted entry, or -1.
  [[nodiscard]] int highlighted() const { return highlighted_; }
  [[nodiscard]] const std::string& name() const { return name_; }
  /// Why the folder could not be listed or the name not chosen; empty when all is well.
  [[nodiscard]] const std::string& error() const { return error_; }
  /// Whether all files are shown rather than those with the action's extensions.
  [[nodiscard]] bool showing_all_files() const { return all_files_; }

  /// Lists another folder (relative folders are taken from the current one).
  void open_folder(const std::filesystem::path& folder);
  /// Backspace with no name typed: the parent folder, with the folder left highlighted.
  void backspace_on_empty_name();
  void show_all_files(bool all);
  /// Lists the folder again.
  void refresh();
  /// Up/down arrows: moves the highlight by `steps`, within the list; the name field then holds
  /// the highlighted file's name (a folder leaves it empty).
  void move(int steps);
  /// A click on entry `index`: highlights it, as move() does.
  void highlight(int index);
  /// Typing in the name field: highlights the first entry whose name starts with the text
  /// (without case), or nothing.
  void set_name(std::string name);
  /// Enter (or a double click, or the dialog's button): opens the highlighted or named folder
  /// and returns nothing, or returns the chosen file's path: the name typed, or in Open the
  /// entry it highlights when no file has that name. Returns nothing with error() set
  /// when the name cannot be chosen (nothing typed or highlighted, or an Open of a file that is
  /// not there).
  std::optional<std::filesystem::path> enter();

 private:
  std::filesystem::path folder_;
  std::vector<std::string> extensions_;
  bool must_exist_ = true;
  bool all_files_ = false;
  std::vector<FileEntry> entries_;
  int highlighted_ = -1;
  std::string name_;
  std::string error_;
};

/// Where the recent-files list is kept: $XDG_CONFIG_HOME/stitch/recent-files, or
/// HOME/.config/stitch/recent-files; the values are the environment's (null when unset).
std::filesystem::path recent_files_path(const char* xdg_config_home, const char* home);

/// The files opened and saved lately, newest first, kept in a small text file (one absolute
/// path per line).
class RecentFiles {
 public:
  static constexpr std::size_t kMostKept = 10;
  /// Reads the list from `file` (none yet when it does not exist; unreadable lines are skipped).
  explicit RecentFiles(std::filesystem::path file);
  [[nodiscard]] const std::vector<std::string>& paths() const { return paths_; }
  /// Puts `path` (made absolute) first, drops its older entry and the oldest beyond
  /// kMostKept, and writes the file (atomically, creating its folder). Throws OutputError when
  /// the file cannot be written; the list in memory is updated anyway.
  void add(const std::filesystem::path& path);

 private:
  std::filesystem::path file_;
  std::vector<std::string> paths_;
};

}  // namespace stitch::modeler
