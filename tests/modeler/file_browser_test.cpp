// The file dialogs' logic without a window: listing, filtering, sorting, keyboard navigation,
// choosing a file, and the recent-files list.
#include "stitch/modeler/file_browser.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "stitch/error.hpp"
#include "stitch/output/output.hpp"
#include "temp_folder.hpp"

namespace stitch::modeler {
namespace {

namespace fs = std::filesystem;

bool has(const std::vector<std::string>& list, const std::string& e) {
  return std::find(list.begin(), list.end(), e) != list.end();
}

/// A folder with subfolders, meshes, a project, other files and hidden ones.
void fill(const stitch::testing::TempFolder& dir) {
  fs::create_directories(dir.path() / "meshes");
  fs::create_directories(dir.path() / "Archive");
  fs::create_directories(dir.path() / ".cache");
  for (const char* name :
       {"b.obj", "A.OBJ", "c.ply", "shape.stitch", "notes.txt", ".hidden.obj", "surface.glb"})
    dir.write(name, "x");
  dir.write("meshes/inner.off", "x");
}

std::vector<std::string> names(const std::vector<FileEntry>& entries) {
  std::vector<std::string> out;
  for (const FileEntry& e : entries) out.push_back(e.is_folder ? e.name + "/" : e.name);
  return out;
}

TEST(ModelerFileBrowser, EachActionListsTheFormatsOfItsReadersOrWriters) {
  const auto open = open_extensions(), save = save_extensions(), out = export_extensions();
  for (const char* e : {".obj", ".off", ".ply", ".stl", ".glb", ".gltf", ".stitch"})
    EXPECT_TRUE(has(open, e)) << e;
  EXPECT_EQ(save.front(), ".stitch");  // a name without an extension becomes a project
  for (const char* e : {".obj", ".off", ".ply", ".stl"}) EXPECT_TRUE(has(save, e)) << e;
  EXPECT_FALSE(has(save, ".glb"));  // meshes are not written as glTF
  for (const char* e : {".obj", ".ply", ".glb", ".gltf", ".json"}) EXPECT_TRUE(has(out, e)) << e;
  EXPECT_FALSE(has(out, ".stitch"));
  // Export offers every extension of the table of output formats, and nothing else.
  size_t extensions = 0;
  for (const OutputFormat& f : output_formats())
    for (std::string_view e : f.extensions)
      if (!e.empty()) {
        EXPECT_TRUE(has(out, std::string(e))) << e;
        ++extensions;
      }
  EXPECT_EQ(out.size(), extensions);
  EXPECT_EQ(out.front(), output_formats().front().extensions[0]);
  for (const char* e : {".step", ".stp", ".igs", ".iges", ".bez.json"})
    EXPECT_TRUE(has(out, e)) << e;
}

TEST(ModelerFileBrowser, ExportListsAndNamesEveryOutputFormat) {
  stitch::testing::TempFolder dir;
  fill(dir);
  for (const char* name : {"p.bez.json", "q.STEP", "r.igs", "s.iges", "t.stp"})
    dir.write(name, "x");
  FileBrowser b(dir.path(), export_extensions(), false);
  EXPECT_EQ(names(b.entries()), (std::vector<std::string>{"Archive/", "meshes/", "A.OBJ", "b.obj",
                                                          "c.ply", "p.bez.json", "q.STEP", "r.igs",
                                                          "s.iges", "surface.glb", "t.stp"}));
  // A name without an output extension gets the first format's; a two-dot one is kept.
  b.set_name("smooth");
  EXPECT_EQ(b.enter(), fs::weakly_canonical(dir.path()) /
                           ("smooth" + std::string(output_formats().front().extensions[0])));
  b.set_name("patches.bez.json");
  EXPECT_EQ(b.enter(), fs::weakly_canonical(dir.path()) / "patches.bez.json");
  EXPECT_TRUE(has_extension("P.BEZ.JSON", {".bez.json"}));
  EXPECT_FALSE(has_extension("p.json", {".bez.json"}));
  EXPECT_FALSE(has_extension("notes.txt", {".step"}));
  EXPECT_TRUE(has_extension("notes.txt", {}));
}

TEST(ModelerFileBrowser, ListsFoldersFirstThenMatchingFilesSortedWithoutCase) {
  stitch::testing::TempFolder dir;
  fill(dir);
  EXPECT_EQ(names(list_folder(dir.path(), open_extensions())),
            (std::vector<std::string>{"Archive/", "meshes/", "A.OBJ", "b.obj", "c.ply",
                                      "shape.stitch", "surface.glb"}));
  EXPECT_EQ(names(list_folder(dir.path(), {".ply"})),
            (std::vector<std::string>{"Archive/", "meshes/", "c.ply"}));
  EXPECT_EQ(names(list_folder(dir.path(), {})).size(), 8u);  // all files, hidden ones left out
  EXPECT_THROW(list_folder(dir.path() / "missing", {}), InputError);
}

TEST(ModelerFileBrowser, KeysMoveOpenFoldersGoUpAndChooseFiles) {
  stitch::testing::TempFolder dir;
  fill(dir);
  FileBrowser b(dir.path(), open_extensions(), true);
  EXPECT_EQ(b.highlighted(), -1);
  b.move(1);  // down: the first entry, a folder, leaves the name empty
  EXPECT_EQ(b.highlighted(), 0);
  EXPECT_EQ(b.name(), "");
  b.move(-1);  // stays at the top
  EXPECT_EQ(b.highlighted(), 0);
  b.move(3);  // down three: b.obj
  EXPECT_EQ(b.name(), "b.obj");
  b.move(100);  // the last one
  EXPECT_EQ(b.name(), "surface.glb");
  // Enter on a file chooses it.
  b.highlight(3);
  EXPECT_EQ(b.enter(), fs::weakly_canonical(dir.path()) / "b.obj");
  // Enter on a folder opens it; Backspace with no name goes back up, the folder highlighted.
  b.highlight(1);
  EXPECT_FALSE(b.enter());
  EXPECT_EQ(b.folder().filename(), "meshes");
  EXPECT_EQ(names(b.entries()), (std::vector<std::string>{"inner.off"}));
  b.backspace_on_empty_name();
  EXPECT_EQ(b.folder(), fs::weakly_canonical(dir.path()));
  ASSERT_EQ(b.highlighted(), 1);
  EXPECT_EQ(b.entries()[1].name, "meshes");
  // Typing highlights the first entry starting with the text, without case.
  b.set_name("S");
  EXPECT_EQ(b.entries()[b.highlighted()].name, "shape.stitch");
  b.set_name("me");
  EXPECT_EQ(b.entries()[b.highlighted()].name, "meshes");
  EXPECT_FALSE(b.enter());  // the folder a typed start highlights opens too
  EXPECT_EQ(b.folder().filename(), "meshes");
  b.set_name("x");
  EXPECT_EQ(b.highlighted(), -1);
  b.backspace_on_empty_name();  // a name is typed: Backspace edits it, the folder stays
  EXPECT_EQ(b.folder().filename(), "meshes");
}

TEST(ModelerFileBrowser, OpenNeedsAFileSaveAddsTheExtension) {
  stitch::testing::TempFolder dir;
  fill(dir);
  FileBrowser open(dir.path(), open_extensions(), true);
  EXPECT_FALSE(open.enter());  // nothing typed or highlighted
  EXPECT_NE(open.error(), "");
  open.set_name("missing.obj");
  EXPECT_FALSE(open.enter());
  EXPECT_NE(open.error().find("no such file"), std::string::npos) << open.error();
  FileBrowser save(dir.path(), save_extensions(), false);
  save.set_name("new model");
  EXPECT_EQ(save.enter(), fs::weakly_canonical(dir.path()) / "new model.stitch");
  save.set_name("b");  // Save takes the name typed, not the file it highlights
  EXPECT_EQ(save.entries()[save.highlighted()].name, "b.obj");
  EXPECT_EQ(save.enter(), fs::weakly_canonical(dir.path()) / "b.stitch");
  open.set_name("sha");  // Open takes the file it highlights
  EXPECT_EQ(open.enter(), fs::weakly_canonical(dir.path()) / "shape.stitch");
  save.set_name("mesh.OFF");  // one of the formats already: kept
  EXPECT_EQ(save.enter(), fs::weakly_canonical(dir.path()) / "mesh.OFF");
  // "All files" shows the rest too.
  save.show_all_files(true);
  EXPECT_TRUE(std::any_of(save.entries().begin(), save.entries().end(),
                          [](const FileEntry& e) { return e.name == "notes.txt"; }));
}

TEST(ModelerRecentFiles, NewestFirstWithoutRepeatsKeptInAFile) {
  stitch::testing::TempFolder dir;
  EXPECT_EQ(recent_files_path("/config", "/home/u"), fs::path("/config/stitch/recent-files"));
  EXPECT_EQ(recent_files_path(nullptr, "/home/u"), fs::path("/home/u/.config/stitch/recent-files"));
  EXPECT_EQ(recent_files_path("", "/home/u"), fs::path("/home/u/.config/stitch/recent-files"));
  const fs::path file = recent_files_path(dir.path().c_str(), nullptr);
  {
    RecentFiles recent(file);
    EXPECT_TRUE(recent.paths().empty());  // no file yet
    recent.add(dir.path() / "a.obj");
    recent.add(dir.path() / "b.obj");
    recent.add(dir.path() / "x" / ".." / "a.obj");  // the same file: moved to the front
    EXPECT_EQ(recent.paths(), (std::vector<std::string>{(dir.path() / "a.obj").string(),
                                                        (dir.path() / "b.obj").string()}));
  }
  RecentFiles again(file);  // read back from the file
  ASSERT_EQ(again.paths().size(), 2u);
  EXPECT_EQ(again.paths()[0], (dir.path() / "a.obj").string());
  for (int i = 0; i < 20; ++i) again.add(dir.path() / ("m" + std::to_string(i) + ".obj"));
  EXPECT_EQ(again.paths().size(), RecentFiles::kMostKept);
  EXPECT_EQ(again.paths()[0], (dir.path() / "m19.obj").string());
  EXPECT_EQ(RecentFiles(file).paths(), again.paths());
}

}  // namespace
}  // namespace stitch::modeler
