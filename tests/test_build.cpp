// Building half-edge meshes from files: the bundled examples, the OpenSubdiv regression shapes
// (closed, with boundary, non-manifold), and the refusal of invalid polygon soups.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "stitch/mesh/build.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/topology/primitives.hpp"
#include "test_support.hpp"

namespace {

using stitch::BuildOptions;
using stitch::BuildReport;
using stitch::Error;
using stitch::HalfedgeMesh;
using stitch::PolygonSoup;
using stitch::test::error_of;
using stitch::test::signed_volume;

std::string example(const std::string& name) {
  return stitch::test::example_path(name + ".obj");
}
std::string opensubdiv_mesh(const std::string& name) {
  return stitch::test::opensubdiv_shape(name + ".obj");
}
struct ExpectedExample {
  std::string name;
  int vertices, edges, faces, components, genus;
  std::map<int, int> degrees;   // face degree -> count
  std::map<int, int> valences;  // vertex valence -> count
};

void PrintTo(const ExpectedExample& x, std::ostream* os) {
  *os << x.name;
}

class Examples : public ::testing::TestWithParam<ExpectedExample> {};

TEST_P(Examples, BuildWithTheDocumentedTopology) {
  const ExpectedExample& x = GetParam();
  BuildReport report;
  std::vector<std::string> warnings;
  const HalfedgeMesh mesh = stitch::read_mesh(example(x.name), {}, &report, &warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_TRUE(report.warnings.empty());
  EXPECT_TRUE(stitch::find_problems(mesh).empty());
  const stitch::TopologyStats s = stitch::topology_stats(mesh);
  EXPECT_EQ(s.vertices, x.vertices);
  EXPECT_EQ(s.edges, x.edges);
  EXPECT_EQ(s.faces, x.faces);
  EXPECT_EQ(s.euler, x.vertices - x.edges + x.faces);
  EXPECT_EQ(s.components, x.components);
  EXPECT_EQ(s.genus, x.genus);
  EXPECT_EQ(s.degree_histogram, x.degrees);
  EXPECT_EQ(s.valence_histogram, x.valences);
  // Outward orientation; the files' coordinates are exact small numbers, so any positive
  // volume distinguishes it from the (negative) inward one.
  EXPECT_GT(signed_volume(mesh), 0.0);
}

INSTANTIATE_TEST_SUITE_P(
    AllExamples, Examples,
    ::testing::Values(
        ExpectedExample{"cube", 8, 12, 6, 1, 0, {{4, 6}}, {{3, 8}}},
        ExpectedExample{"tetrahedron", 4, 6, 4, 1, 0, {{3, 4}}, {{3, 4}}},
        ExpectedExample{"torus", 48, 96, 48, 1, 1, {{4, 48}}, {{4, 48}}},
        ExpectedExample{"cube_hole", 8, 13, 5, 1, 1, {{4, 4}, {10, 1}}, {{3, 6}, {4, 2}}},
        ExpectedExample{"two_cubes", 16, 25, 11, 1, 0, {{4, 10}, {10, 1}}, {{3, 14}, {4, 2}}}),
    [](const auto& info) { return info.param.name; });

TEST(Examples, TenSidedFacesHoldBothHalfEdgesOfTheInsertedEdge) {
  for (const char* name : {"cube_hole", "two_cubes"}) {
    const HalfedgeMesh mesh = stitch::read_mesh(example(name));
    int faces_with_both_sides = 0;
    for (stitch::Face f : mesh.faces())
      for (stitch::Halfedge h : mesh.face_loop(f))
        if (mesh.face(HalfedgeMesh::twin(h)) == f) ++faces_with_both_sides;
    // One edge, seen from both of its half-edges in the same face.
    EXPECT_EQ(faces_with_both_sides, 2) << name;
  }
}

TEST(Examples, UseTheNumberingOfThePrimitives) {
  EXPECT_EQ(stitch::read_mesh(example("cube")), stitch::make_cube());
  EXPECT_EQ(stitch::read_mesh(example("tetrahedron")), stitch::make_tetrahedron());
  // The torus file's coordinates are rounded to 6 decimals: same connectivity, positions within
  // half a unit of the last written digit.
  const PolygonSoup file = stitch::to_polygon_soup(stitch::read_mesh(example("torus")));
  const PolygonSoup made = stitch::to_polygon_soup(stitch::make_torus(8, 6));
  EXPECT_EQ(file.faces, made.faces);
  ASSERT_EQ(file.positions.size(), made.positions.size());
  for (size_t i = 0; i < file.positions.size(); ++i)
    EXPECT_LE((file.positions[i] - made.positions[i]).lpNorm<Eigen::Infinity>(), 5e-7) << i;
}

struct ExpectedShape {
  std::string name;
  int vertices, faces, genus;  // V and F counted from the file's v and f lines
};

void PrintTo(const ExpectedShape& x, std::ostream* os) {
  *os << x.name;
}

class ClosedShapes : public ::testing::TestWithParam<ExpectedShape> {};

TEST_P(ClosedShapes, Build) {
  const ExpectedShape& x = GetParam();
  std::vector<std::string> warnings;
  const HalfedgeMesh mesh = stitch::read_mesh(opensubdiv_mesh(x.name), {}, nullptr, &warnings);
  EXPECT_TRUE(stitch::find_problems(mesh).empty());
  const stitch::TopologyStats s = stitch::topology_stats(mesh);
  EXPECT_EQ(s.vertices, x.vertices);
  EXPECT_EQ(s.faces, x.faces);
  EXPECT_EQ(s.genus, x.genus);
  // Closed: each component has Euler characteristic 2 - 2 g_i; their sum is 2c - 2g.
  EXPECT_EQ(s.euler, 2 * s.components - 2 * x.genus);
  // Only the OpenSubdiv tags stitch does not use (interpolateboundary, ...) are warned about.
  for (const std::string& w : warnings) EXPECT_NE(w.find("OpenSubdiv tag"), std::string::npos) << w;
}

INSTANTIATE_TEST_SUITE_P(OpenSubdiv, ClosedShapes,
                         ::testing::Values(ExpectedShape{"bilinear_cube", 8, 6, 0},
                                           ExpectedShape{"catmark_cube", 8, 6, 0},
                                           ExpectedShape{"catmark_torus", 32, 32, 1},
                                           ExpectedShape{"catmark_torus_creases0", 32, 32, 1},
                                           ExpectedShape{"catmark_pyramid", 5, 5, 0},
                                           ExpectedShape{"catmark_smoothtris0", 42, 80, 0},
                                           ExpectedShape{"catmark_righthanded", 436, 434, 0},
                                           ExpectedShape{"catmark_chaikin0", 24, 22, 0},
                                           ExpectedShape{"catmark_cubes_semisharp", 32, 24, 0},
                                           ExpectedShape{"loop_icosahedron", 12, 20, 0},
                                           ExpectedShape{"loop_tetrahedron", 4, 4, 0},
                                           ExpectedShape{"loop_cube", 14, 24, 0},
                                           ExpectedShape{"loop_cubes_infsharp", 56, 96, 0},
                                           ExpectedShape{"loop_icos_semisharp", 48, 80, 0}),
                         [](const auto& info) { return info.param.name; });

class BoundaryShapes : public ::testing::TestWithParam<std::string> {};

TEST_P(BoundaryShapes, KeepTheirBoundaryOrHaveHolesFilled) {
  const std::string path = opensubdiv_mesh(GetParam());
  BuildReport kept_report;
  const HalfedgeMesh kept = stitch::read_mesh(path, {}, &kept_report);
  const stitch::TopologyStats stats = stitch::topology_stats(kept);
  EXPECT_GT(stats.boundary_loops, 0);
  EXPECT_EQ(stats.boundary_loops, kept_report.filled_holes);
  EXPECT_LT(kept.patch_corners().size(), kept.halfedges().size());

  BuildOptions options;
  options.fill_holes = true;
  BuildReport report;
  const HalfedgeMesh mesh = stitch::read_mesh(path, options, &report);
  EXPECT_EQ(report.filled_holes, stats.boundary_loops);
  EXPECT_NO_THROW(stitch::validate(mesh));
  EXPECT_EQ(stitch::topology_stats(mesh).boundary_loops, 0);
  EXPECT_EQ(mesh.patch_corners().size(), mesh.halfedges().size());
}

INSTANTIATE_TEST_SUITE_P(OpenSubdiv, BoundaryShapes,
                         ::testing::Values("catmark_bishop", "catmark_pawn", "catmark_rook",
                                           "catmark_car", "catmark_nonquads"));

struct NonManifoldShape {
  std::string name;
  std::string problem;  // words the message must contain
};

void PrintTo(const NonManifoldShape& x, std::ostream* os) {
  *os << x.name;
}

class NonManifoldShapes : public ::testing::TestWithParam<NonManifoldShape> {};

TEST_P(NonManifoldShapes, RepairedByDefaultRefusedWhenStrictNamingTheProblem) {
  const std::string path = opensubdiv_mesh(GetParam().name);
  for (bool fill_holes : {false, true}) {
    BuildOptions options;
    options.fill_holes = fill_holes;
    BuildReport report;
    EXPECT_TRUE(stitch::find_problems(stitch::read_mesh(path, options, &report)).empty());
    EXPECT_FALSE(report.repair.empty());
    options.repair = false;
    const std::string message = error_of([&] { (void)stitch::read_mesh(path, options); });
    EXPECT_NE(message.find(GetParam().problem), std::string::npos) << message;
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find("line"), std::string::npos) << message;
  }
}

INSTANTIATE_TEST_SUITE_P(OpenSubdiv, NonManifoldShapes,
                         ::testing::Values(
                             // Its quads collapse to triangles by repeating the pole vertex.
                             NonManifoldShape{"catmark_nonman_quadpole8", "repeats vertex 5"},
                             NonManifoldShape{"loop_nonman_verts", "is non-manifold"},
                             NonManifoldShape{"catmark_fan", "non-manifold edge"}),
                         [](const auto& info) { return info.param.name; });

// --- soups built in memory ---------------------------------------------------------------

using stitch::test::cube_soup;

TEST(BuildMesh, CubeRoundTripsThroughPolygonSoup) {
  const PolygonSoup soup = cube_soup();
  const HalfedgeMesh mesh = stitch::build_mesh(soup);
  const PolygonSoup back = stitch::to_polygon_soup(mesh);
  EXPECT_EQ(back.positions, soup.positions);
  EXPECT_EQ(back.faces.size(), soup.faces.size());
  EXPECT_EQ(stitch::build_mesh(back), mesh);
}

TEST(BuildMesh, DropsUnusedVerticesWithAWarning) {
  PolygonSoup soup = cube_soup();
  soup.positions.insert(soup.positions.begin(), stitch::Vec3(9, 9, 9));
  for (auto& loop : soup.faces)
    for (int& v : loop) ++v;
  BuildReport report;
  const HalfedgeMesh mesh = stitch::build_mesh(soup, {}, &report);
  EXPECT_EQ(mesh.num_vertices(), 8);
  EXPECT_EQ(report.dropped_vertices, 1);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_NE(report.warnings[0].find("unused"), std::string::npos);
  EXPECT_EQ(report.vertex_source.front(), 1);
}

// Without the repair (test_repair.cpp has it), as `--strict` reads.
TEST(BuildMesh, RefusesInvalidSoups) {
  const auto refuse = [](PolygonSoup soup, const std::string& words) {
    soup.source = "soup.obj";
    soup.face_lines.assign(soup.faces.size(), 0);
    for (size_t f = 0; f < soup.faces.size(); ++f) soup.face_lines[f] = 10 + static_cast<int>(f);
    BuildOptions strict;
    strict.repair = false;
    const std::string message = error_of([&] { (void)stitch::build_mesh(soup, strict); });
    EXPECT_NE(message.find(words), std::string::npos)
        << "expected '" << words << "' in: " << message;
  };
  PolygonSoup soup = cube_soup();
  soup.faces[2] = {0, 1, 1, 5, 4};
  refuse(soup,
         "soup.obj: refused as it is (repairing is off): 1 face that repeats a vertex: face 3 "
         "(line 12) repeats vertex 2 at consecutive positions");
  soup = cube_soup();
  soup.faces[5] = {1, 3};
  refuse(soup, "face 6 (line 15) has 2 vertices");
  soup = cube_soup();
  soup.faces[1] = {4, 6, 7, 5};  // flipped
  refuse(soup, "inconsistent orientation");
  soup = cube_soup();
  soup.faces[0][0] = 8;
  refuse(soup, "refers to vertex 9, but there are 8 vertices");
  soup = cube_soup();
  soup.positions[3].y() = std::numeric_limits<double>::quiet_NaN();
  refuse(soup, "vertex 4 has a non-finite coordinate");
  refuse(PolygonSoup{}, "no faces");
}

// Found by fuzz-obj: a thousand triangles on the same vertex pairs. Which of them are neighbours
// cannot be decided within the search budget, so the soup is refused with a reason (each choice
// is now charged its group's size: counted as one step, this soup took 2.7 s in Release and
// more than the fuzzer's 10 s under ASan, against 0.09 s now). Without the repair, the refusal
// names what the repair would have dropped.
TEST(BuildMesh, RefusesFacesPiledOnOnePairOfVerticesWithAReason) {
  PolygonSoup soup;
  soup.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int k = 0; k < 250; ++k)
    for (const std::vector<int>& face :
         {std::vector{0, 1, 2}, std::vector{2, 1, 0}, std::vector{0, 1, 3}, std::vector{3, 1, 0}})
      soup.faces.push_back(face);
  BuildOptions options;
  options.allow_two_gons = true;  // as `stitch` and the modeler read files
  options.repair = false;
  const std::string message = error_of([&] { (void)stitch::build_mesh(soup, options); });
  EXPECT_NE(message.find("refused as it is (repairing is off): 996 duplicate faces"),
            std::string::npos)
      << message;
  // The repair drops the copies; the two pillows left share an edge, as one pinched sphere.
  options.repair = true;
  BuildReport report;
  const HalfedgeMesh mesh = stitch::build_mesh(soup, options, &report);
  EXPECT_EQ(report.repair.count(stitch::RepairKind::duplicate_face), 996);
  EXPECT_EQ(stitch::topology_stats(mesh).faces, 4);
}

}  // namespace
