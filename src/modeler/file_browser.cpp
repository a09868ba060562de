#include "stitch/modeler/file_browser.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <utility>

#include "stitch/error.hpp"
#include "stitch/mesh/formats.hpp"
#include "stitch/mesh/halfedge_mesh.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/output/output.hpp"
#include "stitch/project/project_file.hpp"

namespace stitch::modeler {

namespace fs = std::filesystem;

namespace {

template <class... Tables>
std::vector<std::string> joined(const Tables&... tables) {
  std::vector<std::string> all;
  auto add = [&all](const auto& table) {
    for (std::string_view e : table)
      if (std::find(all.begin(), all.end(), e) == all.end()) all.emplace_back(e);
  };
  (add(tables), ...);
  return all;
}

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

bool name_before(const FileEntry& a, const FileEntry& b) {
  if (a.is_folder != b.is_folder) return a.is_folder;
  const std::string la = lower(a.name), lb = lower(b.name);
  return la != lb ? la < lb : a.name < b.name;
}

}  // namespace

std::vector<std::string> open_extensions() {
  return joined(kMeshReadExtensions, kProjectExtensions);
}
std::vector<std::string> save_extensions() {
  return joined(kProjectExtensions, kMeshWriteExtensions);
}
std::vector<std::string> export_extensions() {
  std::vector<std::string_view> all;
  for (const OutputFormat& f : output_formats())
    for (std::string_view e : f.extensions)
      if (!e.empty()) all.push_back(e);
  return joined(all);
}

bool has_extension(std::string_view name, const std::vector<std::string>& extensions) {
  const std::string lowered = lower(name);
  return extensions.empty() ||
         std::any_of(extensions.begin(), extensions.end(),
                     [&](const std::string& e) { return lowered.ends_with(e); });
}

std::vector<FileEntry> list_folder(const fs::path& folder,
                                   const std::vector<std::string>& extensions) {
  std::vector<FileEntry> entries;
  std::error_code ec;
  fs::directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec);
  if (ec)
    throw InputError(fmt::format("{}: cannot list the folder: {}", folder.string(), ec.message()));
  for (; it != fs::directory_iterator(); it.increment(ec)) {
    if (ec)
      throw InputError(
          fmt::format("{}: cannot list the folder: {}", folder.string(), ec.message()));
    const std::string name = it->path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    std::error_code type_ec;
    const bool is_folder = it->is_directory(type_ec);  // follows links: a link to a folder is one
    if (!is_folder && !has_extension(name, extensions)) continue;
    entries.push_back({name, is_folder});
  }
  std::sort(entries.begin(), entries.end(), name_before);
  return entries;
}

FileBrowser::FileBrowser(fs::path folder, std::vector<std::string> extensions, bool must_exist)
    : extensions_(std::move(extensions)), must_exist_(must_exist) {
  open_folder(folder.empty() ? fs::current_path() : std::move(folder));
}

void FileBrowser::open_folder(const fs::path& folder) {
  std::error_code ec;
  fs::path target = folder.is_absolute() ? folder : folder_ / folder;
  target = fs::weakly_canonical(target, ec);
  if (ec) target = folder;
  try {
    entries_ = list_folder(target, all_files_ ? std::vector<std::string>{} : extensions_);
  } catch (const Error& e) {
    error_ = e.what();  // stays in the folder it was in
    return;
  }
  folder_ = std::move(target);
  highlighted_ = -1;
  name_.clear();
  error_.clear();
}

void FileBrowser::backspace_on_empty_name() {
  if (!name_.empty() || !folder_.has_parent_path() || folder_ == folder_.root_path()) return;
  const std::string left = folder_.filename().string();
  open_folder(folder_.parent_path());
  for (int i = 0; i < int(entries_.size()); ++i)
    if (entries_[i].is_folder && entries_[i].name == left) highlighted_ = i;
}

void FileBrowser::show_all_files(bool all) {
  all_files_ = all;
  refresh();
}

void FileBrowser::refresh() {
  const std::string name = name_;
  open_folder(folder_);
  if (!name.empty()) set_name(name);
}

void FileBrowser::highlight(int index) {
  if (entries_.empty()) return;
  highlighted_ = std::clamp(index, 0, int(entries_.size()) - 1);
  const FileEntry& e = entries_[highlighted_];
  name_ = e.is_folder ? "" : e.name;
  error_.clear();
}

void FileBrowser::move(int steps) {
  if (entries_.empty()) return;
  highlight(highlighted_ < 0 ? (steps > 0 ? steps - 1 : int(entries_.size()) + steps)
                             : highlighted_ + steps);
}

void FileBrowser::set_name(std::string name) {
  name_ = std::move(name);
  error_.clear();
  highlighted_ = -1;
  if (name_.empty()) return;
  const std::string typed = lower(name_);
  for (int i = 0; i < int(entries_.size()); ++i)
    if (lower(entries_[i].name).starts_with(typed)) {
      highlighted_ = i;
      return;
    }
}

std::optional<fs::path> FileBrowser::enter() {
  error_.clear();
  if (name_.empty()) {
    if (highlighted_ >= 0 && entries_[highlighted_].is_folder) {
      open_folder(entries_[highlighted_].name);
      return std::nullopt;
    }
    error_ = "type a file name or choose a file";
    return std::nullopt;
  }
  const fs::path typed(name_);
  fs::path path = typed.is_absolute() ? typed : folder_ / typed;
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    open_folder(path);
    return std::nullopt;
  }
  // The entry the typed start of a name highlights: a folder to open, or in Open the file
  // (Save takes the typed name as it is, rather than overwrite a file that starts with it).
  if (highlighted_ >= 0 && !fs::exists(path, ec)) {
    const FileEntry& e = entries_[highlighted_];
    if (e.is_folder) {
      open_folder(e.name);
      return std::nullopt;
    }
    if (must_exist_) return folder_ / e.name;
  }
  if (must_exist_) {
    if (!fs::exists(path, ec)) {
      error_ = fmt::format("{}: no such file", path.string());
      return std::nullopt;
    }
  } else if (!extensions_.empty() && !has_extension(path.filename().string(), extensions_)) {
    path += extensions_.front();
  }
  return path;
}

fs::path recent_files_path(const char* xdg_config_home, const char* home) {
  fs::path base;
  if (xdg_config_home && *xdg_config_home)
    base = xdg_config_home;
  else if (home && *home)
    base = fs::path(home) / ".config";
  else
    base = fs::temp_directory_path();
  return base / "stitch" / "recent-files";
}

RecentFiles::RecentFiles(fs::path file) : file_(std::move(file)) {
  std::ifstream in(file_);
  for (std::string line; std::getline(in, line) && paths_.size() < kMostKept;)
    if (!line.empty() && fs::path(line).is_absolute() &&
        std::find(paths_.begin(), paths_.end(), line) == paths_.end())
      paths_.push_back(line);
}

void RecentFiles::add(const fs::path& path) {
  std::error_code ec;
  fs::path absolute = fs::absolute(path, ec);
  const std::string text = (ec ? path : absolute.lexically_normal()).string();
  std::erase(paths_, text);
  paths_.insert(paths_.begin(), text);
  if (paths_.size() > kMostKept) paths_.resize(kMostKept);
  if (const fs::path folder = file_.parent_path(); !folder.empty()) {
    fs::create_directories(folder, ec);
    if (ec)
      throw OutputError(
          fmt::format("{}: cannot create the folder: {}", folder.string(), ec.message()));
  }
  write_file_atomically(file_.string(), [this](std::ostream& out) {
    for (const std::string& p : paths_) out << p << "\n";
  });
}

}  // namespace stitch::modeler
