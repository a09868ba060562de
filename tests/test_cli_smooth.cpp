// `stitch smooth`, `stitch info` and `stitch analyze` as a user runs them.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_run.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/validate.hpp"
#include "test_support.hpp"

namespace stitch {
namespace {

using testing::stitch_cli;
using testing::TempFolder;

TEST(CliSmooth, WritesEveryFormatAndSaysWhere) {
  TempFolder folder;
  const std::string in = test::example_path("cube_hole.obj");
  for (const char* ext : {".obj", ".ply", ".off", ".stl"}) {
    const std::string out = std::string("surface") + ext;
    const auto r = stitch_cli(folder, "smooth '" + in + "' -o " + out + " --resolution 3");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find(out), std::string::npos) << r.out;
    EXPECT_TRUE(std::filesystem::exists(folder.file(out))) << out;
  }
  // The OBJ reads back as a closed mesh with the input's genus.
  const HalfedgeMesh back = read_mesh(folder.file("surface.obj"));
  EXPECT_EQ(topology_stats(back).genus, 1);
  EXPECT_EQ(back.num_faces(), 26 * 9);  // 26 patches, 3 x 3 quads each
}

TEST(CliSmooth, EveryMethodAndTheKgonControlsRun) {
  TempFolder folder;
  const std::string in = test::example_path("torus.obj");
  for (const char* extra : {"--method asc", "--method cc", "--method mdc --kgon-scale 0.7",
                            "--regularize --kgon-rotate 15"}) {
    const auto r = stitch_cli(folder, "smooth '" + in + "' -o s.obj --resolution 2 " + extra);
    EXPECT_EQ(r.status, 0) << extra << ": " << r.err;
  }
}

TEST(CliSmooth, UnweldedWantsPlyAndRefusesOtherwiseWithoutWriting) {
  TempFolder folder;
  const std::string in = test::example_path("tetrahedron.obj");
  auto r = stitch_cli(folder, "smooth '" + in + "' -o s.obj --unwelded");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("PLY"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(folder.file("s.obj")));
  r = stitch_cli(folder, "smooth '" + in + "' -o s.ply --unwelded --resolution 2");
  ASSERT_EQ(r.status, 0) << r.err;
  // Binary PLY with double x y z nx ny nz u v and int patch.
  const std::string ply = testing::read_file(folder.file("s.ply"));
  EXPECT_NE(ply.find("property double nx"), std::string::npos);
  EXPECT_NE(ply.find("property int patch"), std::string::npos);
  EXPECT_NE(ply.find("element vertex 108"), std::string::npos);  // 12 patches x 3 x 3
}

TEST(CliSmooth, KeepsBoundariesOrFillsHoles) {
  TempFolder folder;
  const std::string in = test::opensubdiv_shape("catmark_pawn.obj");
  const int loops = stitch::topology_stats(stitch::read_mesh(in)).boundary_loops;
  ASSERT_GT(loops, 0);
  auto r = stitch_cli(folder, "smooth '" + in + "' -o s.obj --resolution 2");
  ASSERT_EQ(r.status, 0) << r.err;
  // The welded output is a mesh with the same boundary loops.
  EXPECT_EQ(stitch::topology_stats(stitch::read_mesh(folder.file("s.obj"))).boundary_loops, loops);
  r = stitch_cli(folder, "smooth '" + in + "' -o f.obj --resolution 2 --fill-holes");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("filled"), std::string::npos) << r.err;  // a warning says so
  EXPECT_EQ(stitch::topology_stats(stitch::read_mesh(folder.file("f.obj"))).boundary_loops, 0);
}

TEST(CliSmooth, ValenceTwoVertexGivesAWarningAndFiniteOutput) {
  TempFolder folder;
  // A tetrahedron with edge (1, 2) split by vertex 5 of valence 2.
  const std::string in = folder.write("v2.obj",
                                      "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 0 0\n"
                                      "f 1 5 2 3\nf 1 3 4\nf 1 4 2 5\nf 2 4 3\n");
  const auto r = stitch_cli(folder, "smooth v2.obj -o s.obj --resolution 4");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("valence 2"), std::string::npos) << r.err;
  const std::string obj = testing::read_file(folder.file("s.obj"));
  EXPECT_EQ(obj.find("nan"), std::string::npos);
  EXPECT_EQ(obj.find("inf"), std::string::npos);
}

TEST(CliInfo, ReportsTopologyAsJson) {
  TempFolder folder;
  const auto r = stitch_cli(folder, "info '" + test::example_path("cube_hole.obj") + "' --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["vertices"], 8);
  EXPECT_EQ(j["edges"], 13);
  EXPECT_EQ(j["faces"], 5);
  EXPECT_EQ(j["genus"], 1);
  EXPECT_EQ(j["degree_histogram"]["10"], 1);
  EXPECT_EQ(j["extraordinary_vertices"].size(), 6u);
}

TEST(CliAnalyze, ShowsThePapersClaimAsNumbers) {
  TempFolder folder;
  const auto r =
      stitch_cli(folder, "analyze '" + test::example_path("cube.obj") + "' --method all --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["methods"].size(), 3u);
  for (const auto& m : j["methods"]) {
    const double near_ev = m["touching_extraordinary"]["max_deg"];
    if (m["method"] == "mdc") {
      EXPECT_LT(near_ev, 1e-8);  // round-off, see test_surface.cpp
    } else if (m["method"] == "asc") {
      EXPECT_GT(near_ev, 1.0);  // AS&C kinks near the cube's corners
    }
    EXPECT_FALSE(m["max_jump_by_distance"].empty());
  }
}

}  // namespace
}  // namespace stitch

namespace stitch {
namespace {

// The cube with a hole has a 10-sided face running along the bridge twice, which OpenSubdiv
// cannot take as it is; cc evaluates it after Catmull-Clark steps. Catmull-Clark is G1 at
// extraordinary points, so its jump is round-off (measured ~3e-13 degrees), like mdc's.
TEST(CliAnalyze, AllAnalyzesEveryMethodOnTheCubeWithAHole) {
  testing::TempFolder folder;
  const std::string in = test::example_path("cube_hole.obj");
  const auto r = testing::stitch_cli(folder, "analyze '" + in + "' --method all --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["methods"].size(), 3u);
  EXPECT_EQ(j["methods"][2]["method"], "cc");
  EXPECT_FALSE(j["methods"][2].contains("refused"));
  EXPECT_LT(j["methods"][2]["touching_extraordinary"]["max_deg"].get<double>(), 1e-8);
  EXPECT_LT(j["methods"][2]["max_position_gap_relative"].get<double>(), 1e-9);
  EXPECT_GT(j["methods"][0]["touching_extraordinary"]["max_deg"].get<double>(), 1.0);  // asc
}

}  // namespace
}  // namespace stitch

namespace stitch {
namespace {

using testing::stitch_cli;
using testing::TempFolder;

// On a terminal the long stages show how far they are, reading included (issue 17); elsewhere
// (a pipe, a file: what scripts see) nothing but the result. The terminal is the one `script`
// (util-linux, in every Debian) gives the command.
TEST(CliSmooth, ShowsPercentagesOnATerminalAndNothingElsewhere) {
  if (std::system("script --version > /dev/null 2>&1") != 0) GTEST_SKIP() << "no script(1)";
  TempFolder folder;
  // More lines than the OBJ reader's reporting interval (65536), so parsing reports too.
  auto r = stitch_cli(folder, "primitive torus 200 200 -o torus.obj");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string command = "cd '" + folder.path().string() + "' && script -qec \"'" +
                              std::string(STITCH_CLI) +
                              "' smooth torus.obj -o s.ply --resolution 2\" /dev/null > tty.txt";
  ASSERT_EQ(std::system(command.c_str()), 0);
  const std::string tty = testing::read_file(folder.file("tty.txt"));
  for (const char* stage : {"reading torus.obj... ", "and writing s.ply... "}) {
    const size_t at = tty.find(stage);
    ASSERT_NE(at, std::string::npos) << tty;
    // The same line redrawn with a percentage, up to 100.
    EXPECT_NE(tty.find(std::string(stage) + "100%", at), std::string::npos) << tty;
  }
  EXPECT_NE(tty.find(" 33%"), std::string::npos) << tty;  // the bytes read: a third of reading
  r = stitch_cli(folder, "smooth torus.obj -o s.ply --resolution 2");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find('%'), std::string::npos) << r.err;
}

}  // namespace
}  // namespace stitch

namespace stitch {
namespace {

// --check warns about folds and self-intersections of what was written, and stays quiet on a
// clean surface (issue 13, item 4). The straight tube through prism 30's caps folds in four pairs
// of triangles at resolution 16 (docs/method.md, "Quads split along the shorter diagonal";
// prism 9's four-step twist, used here before, is clean since item 7, prism 11's five-step twist
// since item 8, and prism 14's half twist since quads are split along their shorter diagonal).
TEST(CliSmooth, CheckWarnsAboutAFoldingSurfaceAndNotAboutACleanOne) {
  testing::TempFolder folder;
  auto r = testing::stitch_cli(folder, "primitive cube -o straight-in.obj");
  ASSERT_EQ(r.status, 0) << r.err;
  r = testing::stitch_cli(folder, "primitive prism 30 -o twisted-in.obj");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const std::string name : {"straight", "twisted"}) {
    const std::string op = name == "straight" ? "insert-edge 1@1 5@2" : "insert-edge 1@1 31@2";
    r = testing::stitch_cli(folder,
                            "edit " + name + "-in.obj --op \"" + op + "\" -o " + name + ".obj");
    ASSERT_EQ(r.status, 0) << r.err;
    // --no-unfold-tubes: the fitted K-gons, which fold on prism 30's tube.
    r = testing::stitch_cli(
        folder, "smooth " + name + ".obj -o s.ply --resolution 16 --check --no-unfold-tubes");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err.find("not clean") != std::string::npos, name == "twisted") << r.err;
    if (name == "twisted") {
      EXPECT_NE(r.err.find("4 folded pairs"), std::string::npos) << r.err;
    }
  }
  // By default the twisted tube's K-gon controls are chosen where the fitted ones fold
  // (unfold_tubes), and the surface is clean; the note says what was chosen.
  r = testing::stitch_cli(folder, "smooth twisted.obj -o s.ply --resolution 16 --check");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("not clean"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("stitch: note: twisted.obj: the tube of face 1 (bridge 1 31) folds with its "
                       "fitted K-gons"),
            std::string::npos)
      << r.err;
  // --quiet leaves the note out.
  r = testing::stitch_cli(folder, "smooth twisted.obj -o s.ply --resolution 16 --check --quiet");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  // The adaptive triangles are checked too (before, --check with --tolerance checked nothing):
  // the cube's tube is clean at the default tolerance, prism 30's fitted K-gons fold with the
  // coarser triangles of 1e-2 (its folds are the tessellation's, clean at resolution 32:
  // method.md, "Quads split along the shorter diagonal").
  r = testing::stitch_cli(
      folder, "smooth straight.obj -o a.obj --tolerance 1e-3 --check --no-unfold-tubes");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("not clean"), std::string::npos) << r.err;
  r = testing::stitch_cli(folder,
                          "smooth twisted.obj -o a.obj --tolerance 1e-2 --check --no-unfold-tubes");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("not clean at tolerance 0.01"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("folded pairs"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace stitch
