// OpenSubdiv's crease and corner tags in OBJ files: read into the soup and onto the mesh, refused
// with file and line when malformed, written back by the OBJ writer, and counted by `stitch info`.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "cli_run.hpp"
#include "stitch/mesh/build.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/validate.hpp"
#include "temp_folder.hpp"
#include "test_support.hpp"

namespace {

using stitch::BuildReport;
using stitch::Edge;
using stitch::HalfedgeMesh;
using stitch::infinitely_sharp;
using stitch::PolygonSoup;
using stitch::Vertex;
using stitch::test::error_of;
using stitch::test::opensubdiv_shape;
using stitch::testing::read_file;
using stitch::testing::stitch_cli;
using stitch::testing::TempFolder;

// 8 vertices (0-based in tags: 0..7) and 6 faces on lines 1..14, so a tag appended is on line 15.
const std::string kCube =
    "v -1 -1 -1\nv 1 -1 -1\nv -1 1 -1\nv 1 1 -1\nv -1 -1 1\nv 1 -1 1\nv -1 1 1\nv 1 1 1\n"
    "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";

/// Sharpness per edge, keyed by the edge's vertices (smaller first) as the file numbers them
/// (from 0), so meshes read from different files can be compared.
std::map<std::pair<int, int>, double> edge_sharpness(const HalfedgeMesh& mesh,
                                                     const std::vector<int>& source) {
  std::map<std::pair<int, int>, double> out;
  for (Edge e : mesh.edges())
    if (mesh.sharpness(e) > 0) {
      const auto h = HalfedgeMesh::halfedge(e, 0);
      const int a = source[mesh.origin(h).idx], b = source[mesh.target(h).idx];
      out[{std::min(a, b), std::max(a, b)}] = mesh.sharpness(e);
    }
  return out;
}

std::map<int, double> vertex_sharpness(const HalfedgeMesh& mesh, const std::vector<int>& source) {
  std::map<int, double> out;
  for (Vertex v : mesh.vertices())
    if (mesh.sharpness(v) > 0) out[source[v.idx]] = mesh.sharpness(v);
  return out;
}

struct Counts {
  int infinite = 0, semi = 0;
};

Counts crease_counts(const HalfedgeMesh& mesh) {
  Counts c;
  for (Edge e : mesh.edges())
    if (mesh.sharpness(e) > 0) ++(mesh.sharpness(e) >= infinitely_sharp ? c.infinite : c.semi);
  return c;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(ReadTags, TorusCreases0HasEightSemiSharpEdgesAndAWarningNamingThem) {
  const std::string path = opensubdiv_shape("catmark_torus_creases0.obj");
  const PolygonSoup soup = stitch::read_polygon_soup(path);
  ASSERT_EQ(soup.creases.size(), 8u);
  EXPECT_EQ(soup.creases[0].a, 1);  // `t crease 2/1/0 1 5 4.7`: vertices count from 0
  EXPECT_EQ(soup.creases[0].b, 5);
  EXPECT_EQ(soup.creases[0].line, 71);
  EXPECT_EQ(soup.creases[7].line, 78);
  BuildReport report;
  const HalfedgeMesh mesh = stitch::build_mesh(soup, {}, &report);
  const Counts c = crease_counts(mesh);
  EXPECT_EQ(c.infinite, 0);
  EXPECT_EQ(c.semi, 8);
  for (const auto& [edge, s] : edge_sharpness(mesh, report.vertex_source)) EXPECT_EQ(s, 4.7);
  EXPECT_EQ(stitch::topology_stats(mesh).crease_edges, 8);
  // One warning, with the count and the first edges numbered from 1 (tag 1 5 is edge (2, 6)).
  int semi_warnings = 0;
  for (const std::string& w : report.warnings)
    if (contains(w, "semi-sharp")) {
      ++semi_warnings;
      EXPECT_TRUE(contains(w, "8 edges have finite sharpness")) << w;
      EXPECT_TRUE(contains(w, "(2, 6)")) << w;
      EXPECT_TRUE(contains(w, "(3 more)")) << w;
      // How they are taken: by refinement, or rounded with --sharp-from.
      EXPECT_TRUE(contains(w, "refining")) << w;
      EXPECT_TRUE(contains(w, "--sharp-from")) << w;
    }
  EXPECT_EQ(semi_warnings, 1);
}

TEST(ReadTags, CubesSemisharpHasItsCreasesCornersAndIgnoredTagsWarned) {
  const std::string path = opensubdiv_shape("catmark_cubes_semisharp.obj");
  std::vector<std::string> warnings;
  BuildReport report;
  const HalfedgeMesh mesh = stitch::read_mesh(path, {}, &report, &warnings);
  // 2 edges at 2.0, one at 0.1, 11 at 5.0; corners 1.4 and 3.0; nothing infinitely sharp.
  const Counts c = crease_counts(mesh);
  EXPECT_EQ(c.infinite, 0);
  EXPECT_EQ(c.semi, 14);
  const auto edges = edge_sharpness(mesh, report.vertex_source);
  EXPECT_EQ(edges.at({8, 9}), 2.0);
  EXPECT_EQ(edges.at({24, 25}), 0.1);
  EXPECT_EQ(edges.at({26, 28}), 5.0);
  EXPECT_EQ(vertex_sharpness(mesh, report.vertex_source),
            (std::map<int, double>{{0, 1.4}, {16, 3.0}}));
  const auto stats = stitch::topology_stats(mesh);
  EXPECT_EQ(stats.crease_edges, 14);
  EXPECT_EQ(stats.corner_vertices, 2);
  // The two tags stitch does not use are each named with their line, and nothing else is said.
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_TRUE(contains(warnings[0], "line 163")) << warnings[0];
  EXPECT_TRUE(contains(warnings[0], "'interpolateboundary' ignored")) << warnings[0];
  EXPECT_TRUE(contains(warnings[1], "line 164")) << warnings[1];
  EXPECT_TRUE(contains(warnings[1], "'facevaryinginterpolateboundary' ignored")) << warnings[1];
  int semi_warnings = 0;
  for (const std::string& w : report.warnings) semi_warnings += contains(w, "semi-sharp");
  EXPECT_EQ(semi_warnings, 2);  // edges, and vertices
}

TEST(ReadTags, LoopCubesInfsharpHasInfinitelySharpCreasesAndNoSemiSharpWarning) {
  BuildReport report;
  const HalfedgeMesh mesh =
      stitch::read_mesh(opensubdiv_shape("loop_cubes_infsharp.obj"), {}, &report);
  // 17 crease tags at 10 and one at 0.0, which leaves its edge smooth; one corner at 10.
  const Counts c = crease_counts(mesh);
  EXPECT_EQ(c.infinite, 16);
  EXPECT_EQ(c.semi, 0);
  EXPECT_EQ(edge_sharpness(mesh, report.vertex_source).count({42, 43}), 0u);
  EXPECT_EQ(vertex_sharpness(mesh, report.vertex_source), (std::map<int, double>{{0, 10.0}}));
  int sharp = 0;
  for (Edge e : mesh.edges()) sharp += mesh.is_sharp(e);
  EXPECT_EQ(sharp, 16);
  for (const std::string& w : report.warnings) EXPECT_FALSE(contains(w, "semi-sharp")) << w;
}

TEST(ReadTags, SeveralElementsPerTagTakeOneOrOneEachSharpness) {
  TempFolder folder;
  // OpenSubdiv reads crease integers in pairs: (0, 1) and (1, 3), not a chain 0-1-1-3.
  const std::string path = folder.write("multi.obj", kCube +
                                                         "t crease 4/2/0 0 1 1 3 10 2.5\n"
                                                         "t crease 4/1/0 4 5 5 7 3\n"
                                                         "t corner 2/1/0 0 7 10\n"
                                                         "t corner 2/2/0 2 3 0.5 6\n");
  BuildReport report;
  const HalfedgeMesh mesh = stitch::read_mesh(path, {}, &report);
  EXPECT_EQ(edge_sharpness(mesh, report.vertex_source),
            (std::map<std::pair<int, int>, double>{
                {{0, 1}, 10.0}, {{1, 3}, 2.5}, {{4, 5}, 3.0}, {{5, 7}, 3.0}}));
  EXPECT_EQ(vertex_sharpness(mesh, report.vertex_source),
            (std::map<int, double>{{0, 10.0}, {7, 10.0}, {2, 0.5}, {3, 6.0}}));
}

TEST(ReadTags, OtherTagsAreIgnoredWithOneWarningPerNameNamingTheirLine) {
  TempFolder folder;
  const std::string path = folder.write("other.obj", kCube +
                                                         "t interpolateboundary 1/0/0 1\n"  // 15
                                                         "t hole 1/0/0 2\n"                 // 16
                                                         "t interpolateboundary 1/0/0 2\n"  // 17
                                                         "t smoothtriangles 0/0/1 smooth\n"
                                                         "t mystery 0/2/0 1.5 2\n");
  std::vector<std::string> warnings;
  const PolygonSoup soup = stitch::read_polygon_soup(path, &warnings);
  EXPECT_TRUE(soup.creases.empty());
  EXPECT_TRUE(soup.corners.empty());
  ASSERT_EQ(warnings.size(), 4u);
  EXPECT_TRUE(contains(warnings[0], "line 15: OpenSubdiv tag 'interpolateboundary' ignored"))
      << warnings[0];
  EXPECT_TRUE(contains(warnings[0], "1 more")) << warnings[0];
  EXPECT_TRUE(contains(warnings[1], "line 16: OpenSubdiv tag 'hole' ignored")) << warnings[1];
  EXPECT_TRUE(contains(warnings[2], "'smoothtriangles'")) << warnings[2];
  EXPECT_TRUE(contains(warnings[3], "line 19: OpenSubdiv tag 'mystery' ignored")) << warnings[3];
  for (const std::string& w : warnings) EXPECT_TRUE(contains(w, path)) << w;
}

struct BadTag {
  std::string name, line, message;
};

void PrintTo(const BadTag& t, std::ostream* os) {
  *os << t.name << ": " << t.line;
}

class RefusesBadTag : public ::testing::TestWithParam<BadTag> {};

TEST_P(RefusesBadTag, NamingFileAndLine) {
  TempFolder folder;
  const std::string path = folder.write("bad.obj", kCube + GetParam().line + "\n");
  const std::string error = error_of([&] { (void)stitch::read_mesh(path); });
  ASSERT_FALSE(error.empty()) << "accepted: " << GetParam().line;
  EXPECT_TRUE(contains(error, path)) << error;
  // The reader says "FILE, line 15"; build_mesh (unknown edge, unused vertex) says "line 15 of".
  EXPECT_TRUE(contains(error, "line 15")) << error;
  EXPECT_TRUE(contains(error, GetParam().message)) << error;
}

INSTANTIATE_TEST_SUITE_P(
    Tags, RefusesBadTag,
    ::testing::Values(
        BadTag{"NoName", "t", "needs a name"},
        BadTag{"NoCounts", "t crease", "needs a name and its argument counts"},
        BadTag{"CountsWithSpaces", "t crease 2 1 0 1 10", "must be three integers"},
        BadTag{"TwoCounts", "t crease 2/1 0 1 10", "must be three integers"},
        BadTag{"FourCounts", "t crease 2/1/0/0 0 1 10", "must be three integers"},
        BadTag{"CountNotANumber", "t crease 2/x/0 0 1 10", "not an integer"},
        BadTag{"NegativeCount", "t crease 2/-1/0 0 1 10", "negative number of arguments"},
        BadTag{"TooFewArguments", "t crease 2/1/0 0 1", "but 2 follow"},
        BadTag{"TooManyArguments", "t crease 2/1/0 0 1 10 11", "but 4 follow"},
        BadTag{"HugeCount", "t crease 9999999999/1/0 0 1 10", "but 3 follow"},
        BadTag{"VertexNotAnInteger", "t crease 2/1/0 0 1.5 10", "not an integer"},
        BadTag{"SharpnessNotANumber", "t crease 2/1/0 0 1 sharp", "not a number"},
        BadTag{"SharpnessNaN", "t crease 2/1/0 0 1 nan", "sharpness nan"},
        BadTag{"SharpnessInfinite", "t corner 1/1/0 0 inf", "sharpness inf"},
        BadTag{"SharpnessNegative", "t crease 2/1/0 0 1 -2", "sharpness -2"},
        BadTag{"VertexNegative", "t crease 2/1/0 0 -1 10", "names vertex -1"},
        BadTag{"VertexOutOfRange", "t crease 2/1/0 0 8 10", "names vertex 8, but the file has 8"},
        BadTag{"CornerOutOfRange", "t corner 1/1/0 9 10", "names vertex 9, but the file has 8"},
        BadTag{"OddCreaseVertices", "t crease 3/1/0 0 1 3 10", "needs pairs of vertices"},
        BadTag{"CreaseSharpnessCount", "t crease 4/3/0 0 1 1 3 1 2 3", "1 for all or 1 per edge"},
        BadTag{"CornerSharpnessCount", "t corner 3/2/0 0 1 2 1 2", "1 for all or 1 per vertex"},
        BadTag{"CornerWithoutVertex", "t corner 0/1/0 10", "names no vertex"},
        BadTag{"CreaseWithString", "t crease 2/1/1 0 1 10 x", "string arguments"},
        BadTag{"EdgeToItself", "t crease 2/1/0 3 3 10", "to itself"},
        BadTag{"NoSuchEdge", "t crease 2/1/0 0 7 10", "no face has that edge"}),
    [](const auto& info) { return info.param.name; });

TEST(ReadTags, CornerOnAnUnusedVertexIsRefused) {
  TempFolder folder;
  const std::string path = folder.write("unused.obj", kCube + "v 5 5 5\nt corner 1/1/0 8 10\n");
  const std::string error = error_of([&] { (void)stitch::read_mesh(path); });
  EXPECT_TRUE(contains(error, "line 16 of " + path)) << error;
  EXPECT_TRUE(contains(error, "which no face uses")) << error;
  EXPECT_TRUE(contains(error, "the tag counts from 0: 8")) << error;
}

TEST(WriteTags, ObjRoundTripKeepsEveryTag) {
  TempFolder folder;
  for (const char* name : {"catmark_cubes_semisharp.obj", "loop_cubes_infsharp.obj",
                           "catmark_torus_creases0.obj", "catmark_chaikin0.obj"}) {
    BuildReport first;
    const HalfedgeMesh mesh = stitch::read_mesh(opensubdiv_shape(name), {}, &first);
    const std::string out = folder.file(std::string("again_") + name);
    stitch::write_mesh(out, mesh);
    BuildReport second;
    const HalfedgeMesh back = stitch::read_mesh(out, {}, &second);
    EXPECT_FALSE(edge_sharpness(mesh, first.vertex_source).empty()) << name;
    // Unused vertices are dropped when read, so the written file numbers vertices as the mesh.
    std::vector<int> identity(mesh.num_vertices());
    for (int i = 0; i < mesh.num_vertices(); ++i) identity[i] = i;
    EXPECT_EQ(edge_sharpness(back, second.vertex_source), edge_sharpness(mesh, identity)) << name;
    EXPECT_EQ(vertex_sharpness(back, second.vertex_source), vertex_sharpness(mesh, identity))
        << name;
  }
  const std::string text = read_file(folder.file("again_loop_cubes_infsharp.obj"));
  EXPECT_TRUE(contains(text, "\nt crease 2/1/0 ")) << text;
  EXPECT_TRUE(contains(text, "\nt corner 1/1/0 0 10\n")) << text;
}

TEST(WriteTags, EditKeepsTagsAndPlyDropsThemAsDocumented) {
  TempFolder folder;
  folder.write("in.obj", kCube +
                             "t crease 2/1/0 0 1 10\nt crease 2/1/0 4 5 2.5\n"
                             "t corner 1/1/0 7 10\n");
  // An edit that leaves the tagged elements alone: the output keeps their tags.
  const auto r = stitch_cli(folder, "edit in.obj --op \"extrude-face 2 0.5\" -o out.obj");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string text = read_file(folder.file("out.obj"));
  EXPECT_TRUE(contains(text, "t crease 2/1/0 0 1 10\n")) << text;
  EXPECT_TRUE(contains(text, "t crease 2/1/0 4 5 2.5\n")) << text;
  EXPECT_TRUE(contains(text, "t corner 1/1/0 7 10\n")) << text;
  const HalfedgeMesh in = stitch::read_mesh(folder.file("in.obj"));
  const PolygonSoup soup = stitch::to_polygon_soup(in);
  EXPECT_EQ(soup.creases.size(), 2u);
  stitch::write_polygon_soup(folder.file("out.ply"), soup);
  EXPECT_TRUE(stitch::read_polygon_soup(folder.file("out.ply")).creases.empty());
}

TEST(WriteTags, RefusesTagsThatWouldNotReadBack) {
  TempFolder folder;
  PolygonSoup soup = stitch::to_polygon_soup(stitch::test::cube_mesh());
  soup.creases.push_back({0, 99, 10, 0});
  EXPECT_TRUE(contains(error_of([&] { stitch::write_polygon_soup(folder.file("x.obj"), soup); }),
                       "refers to vertex 100"));
  soup.creases.back() = {0, 1, -1, 0};
  EXPECT_TRUE(contains(error_of([&] { stitch::write_polygon_soup(folder.file("x.obj"), soup); }),
                       "sharpness -1"));
  EXPECT_FALSE(std::filesystem::exists(folder.file("x.obj")));
}

TEST(CliInfoTags, ReportsBoundaryLoopsCreasesAndCorners) {
  TempFolder folder;
  // The cube without its last face: one boundary loop, 5 faces, 20 patches.
  const std::string open = kCube.substr(0, kCube.rfind("f "));
  folder.write("open.obj", open +
                               "t crease 2/1/0 0 1 10\nt crease 2/1/0 4 5 2.5\n"
                               "t corner 1/1/0 2 10\nt corner 1/1/0 4 0.5\n");
  const auto j = stitch_cli(folder, "info open.obj --json");
  ASSERT_EQ(j.status, 0) << j.err;
  const auto info = nlohmann::json::parse(j.out);
  EXPECT_EQ(info["faces"], 5);
  EXPECT_EQ(info["boundary_loops"], 1);
  EXPECT_EQ(info["patches"], 20);
  EXPECT_EQ(info["crease_edges"]["infinitely_sharp"], 1);
  EXPECT_EQ(info["crease_edges"]["semi_sharp"], 1);
  EXPECT_EQ(info["corner_vertices"]["infinitely_sharp"], 1);
  EXPECT_EQ(info["corner_vertices"]["semi_sharp"], 1);
  EXPECT_EQ(info["genus"], 0);
  // The hole is no extraordinary face: every surface face is a quad.
  EXPECT_TRUE(info["extraordinary_faces"].empty()) << info["extraordinary_faces"];
  EXPECT_TRUE(contains(j.err, "1 edge has finite sharpness")) << j.err;

  const auto t = stitch_cli(folder, "info open.obj");
  ASSERT_EQ(t.status, 0) << t.err;
  EXPECT_TRUE(contains(t.out, "faces 5\n")) << t.out;
  EXPECT_TRUE(contains(t.out, "boundary loops 1\n")) << t.out;
  EXPECT_TRUE(contains(t.out, "crease edges 2 (1 infinitely sharp, 1 semi-sharp)")) << t.out;
  EXPECT_TRUE(contains(t.out, "corner vertices 2 (1 infinitely sharp, 1 semi-sharp)")) << t.out;
  EXPECT_TRUE(contains(t.out, "(one per corner, holes excepted) 20\n")) << t.out;
}

TEST(CliInfoTags, MalformedTagExitsWithStatusTwoNamingTheLine) {
  TempFolder folder;
  folder.write("bad.obj", kCube + "t crease 2/1/0 0 1 nan\n");
  const auto r = stitch_cli(folder, "info bad.obj");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, "bad.obj, line 15")) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

}  // namespace
