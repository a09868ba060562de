// `stitch primitive`, `stitch edit` and `stitch check-surface` as a user runs them: outputs,
// summary lines, exit statuses, and nothing written on errors.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_run.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/topology/compare.hpp"
#include "stitch/topology/operation.hpp"
#include "stitch/topology/primitives.hpp"

namespace stitch {
namespace {

using stitch::testing::read_file;
using stitch::testing::TempFolder;

using stitch::testing::CliRun;
using stitch::testing::stitch_cli;

TEST(TopologyCli, PrimitiveCubeHasTheDocumentedNumbering) {
  TempFolder folder;
  const CliRun r = stitch_cli(folder, "primitive cube -o cube.obj");
  ASSERT_EQ(r.status, 0) << r.err;
  const HalfedgeMesh cube = read_mesh(folder.file("cube.obj"));
  EXPECT_EQ(cube, make_cube());
  for (const char* args : {"primitive torus 8 6 -o t.obj", "primitive prism 5 -o p.off",
                           "primitive dodecahedron -o d.ply"})
    EXPECT_EQ(stitch_cli(folder, args).status, 0) << args;
  EXPECT_EQ(topology_stats(read_mesh(folder.file("t.obj"))).genus, 1);
}

TEST(TopologyCli, PrimitiveRefusesBadNamesAndParameters) {
  TempFolder folder;
  for (const char* args : {"primitive sphere -o x.obj", "primitive prism -o x.obj",
                           "primitive torus 2 5 -o x.obj", "primitive prism x -o x.obj"}) {
    const CliRun r = stitch_cli(folder, args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_FALSE(r.err.empty()) << args;
    EXPECT_FALSE(std::filesystem::exists(folder.file("x.obj"))) << args;
  }
}

TEST(TopologyCli, HoleThroughACube) {
  // The example of docs/editing.md, as typed there.
  TempFolder folder;
  ASSERT_EQ(stitch_cli(folder, "primitive cube -o cube.obj").status, 0);
  const CliRun r = stitch_cli(folder, "edit cube.obj --op \"insert-edge 1@1 5@2\" -o holed.obj");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out,
            "insert-edge 1@1 5@2: new edge 13 merged faces 1 and 2 into face 1 (10 sides); V 8 E "
            "13 F 5, Euler 0, genus 1, components 1\n");
  EXPECT_EQ(read_file(folder.file("holed.obj")),
            "# written by stitch\n"
            "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
            "f 1 4 3 2 1 5 6 7 8 5\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
  BuildOptions two_gons;
  two_gons.allow_two_gons = true;
  const HalfedgeMesh holed = read_mesh(folder.file("holed.obj"), two_gons);
  const TopologyStats s = topology_stats(holed);
  EXPECT_EQ(s.genus, 1);
  EXPECT_EQ(s.degree_histogram.at(10), 1);
  // Read back, it is the mesh the library made (the new edge beside edge 1-5 included).
  HalfedgeMesh expected = make_cube();
  apply_operation(expected, "insert-edge 1@1 5@2");
  EXPECT_TRUE(same_up_to_renumbering(holed, expected));
}

TEST(TopologyCli, EditedMeshesWithMultiEdgesReadBackTheSame) {
  // A face running along an edge twice, a 2-sided face, edges doubled by a tube: the file must
  // read back as the same mesh for a later `stitch edit` or `stitch smooth`.
  TempFolder folder;
  ASSERT_EQ(stitch_cli(folder, "primitive cube -o cube.obj").status, 0);
  for (const char* op : {"insert-edge 1@1 7@2", "insert-edge 1@1 4@1", "connect-faces 1 2"}) {
    SCOPED_TRACE(op);
    const CliRun r = stitch_cli(folder, std::string("edit cube.obj --op \"") + op + "\" -o e.obj");
    ASSERT_EQ(r.status, 0) << r.err;
    BuildOptions two_gons;
    two_gons.allow_two_gons = true;
    HalfedgeMesh expected = make_cube();
    apply_operation(expected, op);
    expected.garbage_collection();
    const HalfedgeMesh back = read_mesh(folder.file("e.obj"), two_gons);
    EXPECT_TRUE(same_up_to_renumbering(back, expected));
  }
}

TEST(TopologyCli, OpsFileAndOptionsInOrder) {
  TempFolder folder;
  ASSERT_EQ(stitch_cli(folder, "primitive cube -o cube.obj").status, 0);
  folder.write("ops.txt",
               "# a handle, then split a face of it\n"
               "\n"
               "connect-faces 1 2   # bottom to top\n"
               "subdivide-edge 1 2\n");
  const CliRun r = stitch_cli(
      folder, "edit cube.obj --op \"extrude-face 2 0.5\" --ops ops.txt --op dual -o out.obj");
  ASSERT_EQ(r.status, 0) << r.err;
  // Three summary lines, in command-line order: --op, then the file's two, then --op.
  std::vector<std::string> lines;
  for (size_t start = 0, end; (end = r.out.find('\n', start)) != std::string::npos; start = end + 1)
    lines.push_back(r.out.substr(start, end - start));
  ASSERT_EQ(lines.size(), 4u) << r.out;
  EXPECT_EQ(lines[0].rfind("extrude-face 2 0.5: ", 0), 0u) << lines[0];
  EXPECT_EQ(lines[1].rfind("connect-faces 1 2: ", 0), 0u) << lines[1];
  EXPECT_EQ(lines[2].rfind("subdivide-edge 1 2: ", 0), 0u) << lines[2];
  EXPECT_EQ(lines[3].rfind("dual: ", 0), 0u) << lines[3];
  EXPECT_NE(lines[3].find("genus 1, components 1"), std::string::npos) << lines[3];
  BuildOptions two_gons;
  two_gons.allow_two_gons = true;
  EXPECT_EQ(topology_stats(read_mesh(folder.file("out.obj"), two_gons)).genus, 1);
}

TEST(TopologyCli, EditErrorsExitTwoNameTheOperationAndWriteNothing) {
  TempFolder folder;
  ASSERT_EQ(stitch_cli(folder, "primitive cube -o cube.obj").status, 0);
  folder.write("bad.txt", "subdivide-edge 1 2\n# fine so far\ncollapse-edge 1 7\n");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--op \"frobnicate 3\"", "--op 1 ('frobnicate 3'): frobnicate: unknown operation"},
      {"--op \"subdivide-edge 1 2\" --op \"insert-edge 7@1 1@1\"",
       "--op 2 ('insert-edge 7@1 1@1'): insert-edge: corner 7@1: vertex 7 is not on face 1"},
      {"--op \"delete-edge 1 7\"", "no edge joins vertices 1 and 7"},
      {"--ops bad.txt", "bad.txt:3: collapse-edge: no edge joins vertices 1 and 7"},
      {"--op \"extrude-face 2\"", "extrude-face takes a face, a distance and an optional scale"},
  };
  for (const auto& [args, message] : cases) {
    const CliRun r = stitch_cli(folder, "edit cube.obj " + args + " -o out.obj");
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << "\n" << r.err;
    EXPECT_FALSE(std::filesystem::exists(folder.file("out.obj"))) << args;
  }
}

TEST(TopologyCli, CheckSurface) {
  TempFolder folder;
  folder.write(
      "crossing.obj",
      "v 0 0 0\nv 2 0 0\nv 0 2 0\nv 0.5 0.5 -1\nv 0.5 0.5 1\nv 3 3 0.5\nf 1 2 3\nf 4 5 6\n");
  CliRun r = stitch_cli(folder, "check-surface crossing.obj");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.out.find("1 self-intersecting pairs"), std::string::npos) << r.out;
  r = stitch_cli(folder, "check-surface crossing.obj --json");
  EXPECT_EQ(r.status, 1);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["self_intersections"], 1);
  EXPECT_EQ(j["clean"], false);
  ASSERT_EQ(stitch_cli(folder, "primitive torus 24 12 -o torus.obj").status, 0);
  r = stitch_cli(folder, "check-surface torus.obj");
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  // Stages only when asked (stderr is no terminal here), never under --quiet.
  EXPECT_EQ(r.err, "");
  r = stitch_cli(folder, "check-surface torus.obj --progress");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("stitch: reading torus.obj..."), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("stitch: checking 288 polygons..."), std::string::npos) << r.err;
  r = stitch_cli(folder, "check-surface torus.obj --progress -q");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(stitch_cli(folder, "check-surface missing.obj").status, 2);
}

}  // namespace
}  // namespace stitch
