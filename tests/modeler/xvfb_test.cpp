// End to end: the real stitch-modeler under Xvfb with Mesa's software renderer, driven by a
// script. Skipped only when xvfb-run is not installed (CI installs the xvfb package).
#include <gtest/gtest.h>

#include <filesystem>

#include "docs_text.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/modeler/project.hpp"
#include "temp_folder.hpp"
#include "test_support.hpp"
#include "xvfb_support.hpp"

namespace stitch::modeler {
namespace {

/// Fraction of pixels whose colour differs by more than 24 levels in some channel (more than
/// antialiasing noise) inside the window's middle third, where the model is drawn between the
/// panels.
double differing(const Png& a, const Png& b) {
  if (a.width != b.width || a.height != b.height) return 1.0;
  int n = 0, total = 0;
  for (int y = a.height / 3; y < 2 * a.height / 3; ++y)
    for (int x = a.width / 3; x < 2 * a.width / 3; ++x) {
      ++total;
      const size_t i = (static_cast<size_t>(y) * a.width + x) * 4;
      for (int c = 0; c < 3; ++c)
        if (std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c])) > 24) {
          ++n;
          break;
        }
    }
  return static_cast<double>(n) / total;
}

TEST(ModelerXvfb, ScriptedSessionBuildsTheCubeWithAHole) {
  if (!have_xvfb_run())
    GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb); skipping the GUI test";
  stitch::testing::TempFolder dir;
  const std::string script = dir.write(
      "session.txt", "open " + test::example_path("cube.obj") +
                         "\n"
                         "view iso\n"
                         "save " +
                         dir.file("before.obj") +
                         "\n"
                         "screenshot " +
                         dir.file("cube.png") +
                         "\n"
                         "insert-edge 1@1 5@2   # the vertical bridge: a hole through the cube\n"
                         "save " +
                         dir.file("hole.obj") +
                         "\n"
                         "screenshot " +
                         dir.file("hole.png") +
                         "\n"
                         "mode zebra\n"
                         "screenshot " +
                         dir.file("zebra.png") +
                         "\n"
                         "method asc\n"
                         "screenshot " +
                         dir.file("zebra_asc.png") +
                         "\n"
                         "split mdc\n"
                         "screenshot " +
                         dir.file("split.png") +
                         "\n"
                         "split off\n"
                         "method mdc\n"
                         "mode shaded\n"
                         "undo\n"
                         "save " +
                         dir.file("undone.obj") +
                         "\n"
                         "screenshot " +
                         dir.file("undone.png") +
                         "\n"
                         "redo\n"
                         "save " +
                         dir.file("redone.stitch") +
                         "\n"
                         "quit\n");
  const std::string log = dir.file("log.txt");
  ASSERT_EQ(run_modeler("--size 800x600 --script " + script, log), 0) << read_text(log);

  // The saved mesh: the cube with a hole.
  const TopologyStats hole = topology_stats(read_mesh(dir.file("hole.obj"), {false, true}));
  EXPECT_EQ(hole.genus, 1);
  EXPECT_EQ(hole.components, 1);
  EXPECT_EQ(hole.faces, 5);
  EXPECT_EQ(hole.degree_histogram.at(10), 1);
  // Undo restored the exact earlier mesh (same file bytes, same numbering and positions), and
  // redo the hole.
  EXPECT_EQ(read_text(dir.file("undone.obj")), read_text(dir.file("before.obj")));
  EXPECT_TRUE(read_mesh(dir.file("undone.obj")) == read_mesh(test::example_path("cube.obj")));
  EXPECT_EQ(topology_stats(load_project(dir.file("redone.stitch")).state.mesh).genus, 1);

  const Png cube = load_png(dir.file("cube.png")), with_hole = load_png(dir.file("hole.png")),
            zebra = load_png(dir.file("zebra.png")),
            zebra_asc = load_png(dir.file("zebra_asc.png")),
            split = load_png(dir.file("split.png")), undone = load_png(dir.file("undone.png"));
  for (const Png* p : {&cube, &with_hole, &zebra, &zebra_asc, &split, &undone}) {
    ASSERT_EQ(p->width, 800);
    ASSERT_EQ(p->height, 600);
    EXPECT_GT(colours(*p), 50u);  // not blank: shading gives many colours
  }
  // Each step changes the picture where the model is; undo brings back the first picture.
  EXPECT_GT(differing(cube, with_hole), 0.01);
  EXPECT_GT(differing(with_hole, zebra), 0.05);
  EXPECT_GT(differing(zebra, zebra_asc), 0.005);
  EXPECT_GT(differing(zebra_asc, split), 0.05);
  EXPECT_LT(differing(cube, undone), 0.001);
}

TEST(ModelerXvfb, ScriptErrorsGiveTheLineAndStatus2) {
  if (!have_xvfb_run())
    GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb); skipping the GUI test";
  stitch::testing::TempFolder dir;
  const std::string script = dir.write("bad.txt", "view iso\ninsert-edge 1@1 1@3\nquit\n");
  const std::string log = dir.file("log.txt");
  EXPECT_EQ(run_modeler("--script " + script, log), 2);
  EXPECT_NE(read_text(log).find("bad.txt:2:"), std::string::npos) << read_text(log);
}

TEST(ModelerXvfb, HelpListsTheWindowsLinesWhichTheModelerPageDescribes) {
  if (!have_xvfb_run())
    GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb); skipping the GUI test";
  stitch::testing::TempFolder dir;
  const std::string script = dir.write("help.txt", "help\nhelp layout\nquit\n");
  const std::string log = dir.file("log.txt");
  ASSERT_EQ(run_modeler("--script " + script, log), 0) << read_text(log);
  // The rows after "application:", each "  SYNOPSIS  help" (a long synopsis puts the help on
  // an indented line of its own).
  std::istringstream printed(read_text(log));
  std::vector<std::string> names;
  bool in_application = false;
  for (std::string line; std::getline(printed, line);) {
    if (line == "application:") in_application = true;
    if (line.empty() || line[0] != ' ') continue;
    if (in_application && line.size() > 2 && line[2] != ' ')
      names.push_back(line.substr(2, line.find(' ', 2) - 2));
  }
  EXPECT_EQ(names, (std::vector<std::string>{"ui", "dialog", "layout"})) << read_text(log);
  EXPECT_NE(read_text(log).find("layout PATH: writes the screen layout"), std::string::npos)
      << read_text(log);
  const std::string docs = read_docs("modeler.md");
  for (const std::string& name : names)
    EXPECT_TRUE(names_in_code(docs, name)) << "docs/modeler.md does not name `" << name << "`";
}

TEST(ModelerXvfb, ScreenshotExitAndRecover) {
  if (!have_xvfb_run())
    GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb); skipping the GUI test";
  stitch::testing::TempFolder dir;
  // A document with a newer autosave holding unsaved work (the cube with a hole).
  const std::string doc = dir.write("cube.obj", read_text(test::example_path("cube.obj")));
  std::filesystem::last_write_time(
      doc, std::filesystem::file_time_type::clock::now() - std::chrono::hours(1));
  Project unsaved;
  unsaved.state.mesh = read_mesh(test::example_path("cube_hole.obj"), {false, true});
  unsaved.view.set_standard(View::iso, BoundingBox{Vec3::Constant(-1), Vec3::Constant(1)});
  save_project(autosave_path(doc), unsaved);

  // Without --recover: the document, a note about the autosave, a screenshot, exit.
  const std::string log = dir.file("log.txt");
  ASSERT_EQ(
      run_modeler("'" + doc + "' --size 640x480 --screenshot '" + dir.file("shot.png") + "' --exit",
                  log),
      0)
      << read_text(log);
  EXPECT_NE(read_text(log).find("--recover"), std::string::npos) << read_text(log);
  const Png shot = load_png(dir.file("shot.png"));
  EXPECT_EQ(shot.width, 640);
  EXPECT_GT(colours(shot), 50u);

  // With --recover: the autosave's mesh.
  const std::string script = dir.write("s.txt", "save " + dir.file("recovered.obj") + "\nquit\n");
  ASSERT_EQ(run_modeler("'" + doc + "' --recover --script " + script, log), 0) << read_text(log);
  EXPECT_EQ(topology_stats(read_mesh(dir.file("recovered.obj"), {false, true})).genus, 1);
}

}  // namespace
}  // namespace stitch::modeler
