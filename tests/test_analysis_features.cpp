// Continuity on meshes with boundaries and creases: interior sides as on closed meshes, boundary
// sides left out, crease sides watertight, G1 within each sector at the vertices on them.
//
// Tolerances. Interior normal jumps: 1e-6 degrees, the round-off level of double precision the
// specification states (section 6): one evaluation's normal is good to ~1e-14 degrees, deep
// splits near an extraordinary point lose up to 2^12 of that, and any real kink is degrees (AS&C
// on the same meshes). Positions (interior and crease gaps): 1e-12 of the bounding-box diagonal,
// a few thousand ulps: the two sides evaluate the same Bezier curve from the same points.
// Normals within a sector: 1e-6 degrees, for the same reason as the interior jumps.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>

#include "cli_run.hpp"
#include "stitch/analysis/continuity.hpp"
#include "stitch/analysis/sectors.hpp"
#include "stitch/eval/surface.hpp"
#include "stitch/kgon/kgon.hpp"
#include "stitch/topology/primitives.hpp"
#include "test_support.hpp"

namespace stitch {
namespace {

constexpr double kJumpDeg = 1e-6;
constexpr double kGap = 1e-12;

/// An open n x n grid of unit quads in the plane z = 0 with its middle vertex raised, so the
/// surface is curved; faces point to +z. Optionally the middle row of edges is a crease.
HalfedgeMesh raised_grid(int n, bool crease_middle_row = false) {
  PolygonSoup s;
  const auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      s.positions.emplace_back(i, j, i == n / 2 && j == n / 2 ? 0.8 : 0.0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      s.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  HalfedgeMesh mesh = build_mesh(s);
  if (crease_middle_row)
    for (Edge e : mesh.edges()) {
      const int a = mesh.origin(HalfedgeMesh::halfedge(e, 0)).idx;
      const int b = mesh.origin(HalfedgeMesh::halfedge(e, 1)).idx;
      if (a / (n + 1) == n / 2 && b / (n + 1) == n / 2) mesh.set_sharpness(e, infinitely_sharp);
    }
  return mesh;
}

/// The unit cube without its top face (z = +0.5): a box open at the top.
HalfedgeMesh open_cube() {
  PolygonSoup s;
  for (int i = 0; i < 8; ++i)
    s.positions.emplace_back((i & 1) ? 0.5 : -0.5, (i & 2) ? 0.5 : -0.5, (i & 4) ? 0.5 : -0.5);
  s.faces = {{0, 2, 3, 1}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  return build_mesh(s);
}

/// catmark_torus_creases0 with its tagged loop of edges (0-based vertices 1, 5, ..., 29) made
/// infinitely sharp: the file tags them 4.7, semi-sharp, which is a crease for mdc only from
/// KgonOptions::sharp_from on, and none for cc. Set in code so the test depends on neither.
HalfedgeMesh creased_torus() {
  HalfedgeMesh mesh = read_mesh(test::opensubdiv_shape("catmark_torus_creases0.obj"));
  int sharpened = 0;
  for (Edge e : mesh.edges()) {
    const int a = mesh.origin(HalfedgeMesh::halfedge(e, 0)).idx;
    const int b = mesh.origin(HalfedgeMesh::halfedge(e, 1)).idx;
    const int d = std::abs(a - b);
    if (a % 4 == 1 && b % 4 == 1 && a < 32 && b < 32 && (d == 4 || d == 28)) {
      mesh.set_sharpness(e, infinitely_sharp);
      ++sharpened;
    }
  }
  EXPECT_EQ(sharpened, 8);
  return mesh;
}

int boundary_edges(const HalfedgeMesh& mesh) {
  int n = 0;
  for (Edge e : mesh.edges()) n += mesh.is_boundary(e) ? 1 : 0;
  return n;
}

/// Sharp edges that are not on the boundary: creases, for this surface's method.
int crease_edges(const HalfedgeMesh& mesh, const Surface& surface) {
  const auto sharp = sharp_edges(mesh, surface);
  int n = 0;
  for (Edge e : mesh.edges()) n += sharp[e.idx] && !mesh.is_boundary(e) ? 1 : 0;
  return n;
}

void expect_smooth_inside(const ContinuityReport& r, const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_GT(r.touching_ev.samples + r.away_from_ev.samples, 0);
  EXPECT_LT(r.touching_ev.max_deg, kJumpDeg);
  EXPECT_LT(r.away_from_ev.max_deg, kJumpDeg);
  EXPECT_LT(r.max_gap, kGap);
  EXPECT_LT(r.ev_normal_spread_deg, kJumpDeg);
  EXPECT_TRUE(r.has_sharp_features);
  EXPECT_LT(r.features.crease_gap, kGap);
  EXPECT_LT(r.features.sector_normal_spread_deg, kJumpDeg);
}

TEST(Sectors, SplitTheFanAtSharpEdgesAndLeaveHolesOut) {
  const HalfedgeMesh grid = raised_grid(4, true);
  const auto sharp = sharp_edges(grid, Surface(grid, Method::mdc));
  // An edge vertex of the grid: two faces and the outside, one sector of two patches.
  const Vertex edge_vertex(2);
  EXPECT_EQ(sharp_spokes(grid, edge_vertex, sharp), 2);
  auto sectors = vertex_sectors(grid, edge_vertex, sharp);
  ASSERT_EQ(sectors.size(), 1u);
  EXPECT_EQ(sectors[0].size(), 2u);
  // The raised middle vertex on the crease: two sectors of two patches, one on each side.
  const Vertex middle(2 * 5 + 2);
  EXPECT_EQ(sharp_spokes(grid, middle, sharp), 2);
  sectors = vertex_sectors(grid, middle, sharp);
  ASSERT_EQ(sectors.size(), 2u);
  for (const auto& s : sectors) {
    ASSERT_EQ(s.size(), 2u);
    // Consecutive corners of a sector are neighbours across a smooth spoke.
    EXPECT_EQ(grid.rotate_ccw(s[0]), s[1]);
    EXPECT_FALSE(grid.is_sharp(HalfedgeMesh::edge(grid.prev(s[0]))));
  }
  // A smooth vertex: one sector, the whole fan.
  const HalfedgeMesh cube = test::cube_mesh();
  const auto none = sharp_edges(cube, Surface(cube, Method::mdc));
  EXPECT_EQ(vertex_sectors(cube, Vertex(0), none).size(), 1u);
  EXPECT_EQ(vertex_sectors(cube, Vertex(0), none)[0].size(), 3u);
}

TEST(AnalysisFeatures, ClosedMeshesReportNoFeatures) {
  const HalfedgeMesh cube = test::cube_mesh();
  const ContinuityReport r = analyze_continuity(cube, Surface(cube, Method::mdc));
  EXPECT_FALSE(r.has_sharp_features);
  EXPECT_EQ(r.features.boundary_sides, 0);
  EXPECT_EQ(r.features.sector_vertices, 0);
  EXPECT_EQ(r.extraordinary_points, 8);
}

TEST(AnalysisFeatures, OpenGridWithARaisedVertex) {
  const HalfedgeMesh grid = raised_grid(4);
  const ContinuityReport r = analyze_continuity(grid, Surface(grid, Method::mdc));
  expect_smooth_inside(r, "open grid");
  // 16 boundary edges, two patch sides each; every boundary vertex is in a sector, and the 12
  // that are not grid corners have sectors of two patches.
  EXPECT_EQ(r.features.boundary_sides, 2 * 16);
  EXPECT_EQ(r.features.crease_sides, 0);
  EXPECT_EQ(r.features.sector_vertices, 16);
  EXPECT_EQ(r.features.sectors_compared, 12);
  // Sectors of two patches along a straight boundary close to K = 4: nothing is extraordinary.
  EXPECT_EQ(r.extraordinary_points, 0);
  EXPECT_EQ(r.touching_ev.samples, 0);
  // Interior sides only: two halves of each of the 24 inner edges, and 4 spokes per quad.
  const ContinuityOptions options;
  const long per_side = options.samples_per_side + 2 * (options.max_halvings - 1);
  EXPECT_EQ(r.away_from_ev.samples, per_side * (2 * 24 + 16 * 4));
}

TEST(AnalysisFeatures, OpenGridWithACreaseThroughTheRaisedVertex) {
  const HalfedgeMesh grid = raised_grid(4, true);
  for (Method m : {Method::mdc, Method::asc}) {
    const ContinuityReport r = analyze_continuity(grid, Surface(grid, m));
    expect_smooth_inside(r, to_string(m));
    EXPECT_EQ(r.features.crease_sides, 2 * 4);
    EXPECT_EQ(r.features.boundary_sides, 2 * 16);
    // The two ends of the crease are corners (two boundary edges and the crease): sectors of
    // one patch; the three inner crease vertices add two sectors of two patches each.
    EXPECT_EQ(r.features.sector_vertices, 16 + 3);
    EXPECT_EQ(r.features.sectors_compared, 12 - 2 + 3 * 2);
  }
  // The crease is real: the patches on either side of it meet at an angle at the raised vertex.
  const Surface surface(grid, Method::mdc);
  const auto sectors = vertex_sectors(grid, Vertex(2 * 5 + 2), sharp_edges(grid, surface));
  ASSERT_EQ(sectors.size(), 2u);
  EXPECT_GT(angle_deg(surface.evaluate(sectors[0][0], 0.25, 0).normal,
                      surface.evaluate(sectors[1][1], 0, 0.25).normal),
            1.0);
}

TEST(AnalysisFeatures, CubeWithOneFaceRemoved) {
  const HalfedgeMesh box = open_cube();
  ASSERT_EQ(boundary_edges(box), 4);
  const ContinuityReport mdc = analyze_continuity(box, Surface(box, Method::mdc));
  expect_smooth_inside(mdc, "open cube, mdc");
  EXPECT_EQ(mdc.features.boundary_sides, 8);
  EXPECT_EQ(mdc.features.sector_vertices, 4);
  EXPECT_EQ(mdc.features.sectors_compared, 4);
  EXPECT_EQ(mdc.extraordinary_points, 4);  // the bottom corners, valence 3
  EXPECT_GT(mdc.touching_ev.samples, 0);
  // The measure sees kinks where there are some: AS&C's near the bottom corners.
  const ContinuityReport asc = analyze_continuity(box, Surface(box, Method::asc));
  EXPECT_GT(asc.touching_ev.max_deg, 1.0);
  EXPECT_LT(asc.features.sector_normal_spread_deg, kJumpDeg);
}

TEST(AnalysisFeatures, PawnHasABoundaryAndIsSmoothInside) {
  const HalfedgeMesh pawn = read_mesh(test::opensubdiv_shape("catmark_pawn.obj"));
  const int edges = boundary_edges(pawn);
  ASSERT_GT(edges, 0);
  // The file also tags 120 edges 6: creases for mdc (from KgonOptions::sharp_from = 4 on),
  // rounded by cc; either way the rest of the surface is smooth.
  for (Method m : {Method::mdc, Method::cc}) {
    const Surface surface(pawn, m);
    const ContinuityReport r = analyze_continuity(pawn, surface);
    expect_smooth_inside(r, "pawn, " + to_string(m));
    EXPECT_EQ(r.features.boundary_sides, 2 * edges);
    EXPECT_EQ(r.features.crease_sides, 2 * crease_edges(pawn, surface));
    EXPECT_GT(r.features.sectors_compared, 0);
    EXPECT_GT(r.touching_ev.samples, 0);
  }
}

TEST(AnalysisFeatures, TorusCreaseIsWatertightAndSmoothOnEachSide) {
  const HalfedgeMesh torus = creased_torus();
  for (Method m : {Method::mdc, Method::cc}) {
    const ContinuityReport r = analyze_continuity(torus, Surface(torus, m));
    expect_smooth_inside(r, "creased torus, " + to_string(m));
    EXPECT_EQ(r.features.boundary_sides, 0);
    EXPECT_EQ(r.features.crease_sides, 2 * 8);
    // Eight crease vertices of valence 4, each with two sectors of two patches.
    EXPECT_EQ(r.features.sector_vertices, 8);
    EXPECT_EQ(r.features.sectors_compared, 16);
  }
}

TEST(AnalysisFeatures, CommandLineShowsFeaturesOnlyWhenThereAreSome) {
  testing::TempFolder folder;
  const std::string pawn = test::opensubdiv_shape("catmark_pawn.obj");
  auto r = testing::stitch_cli(folder, "analyze '" + pawn + "' --method mdc --json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  const auto& f = j["methods"][0]["sharp_features"];
  EXPECT_GT(f["boundary_sides"].get<int>(), 0);
  EXPECT_LT(f["crease_max_position_gap_relative"].get<double>(), kGap);
  EXPECT_LT(f["g1_normal_spread_in_sectors_deg"].get<double>(), kJumpDeg);
  EXPECT_LT(j["methods"][0]["touching_extraordinary"]["max_deg"].get<double>(), kJumpDeg);

  r = testing::stitch_cli(folder, "analyze '" + pawn + "' --method mdc");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("boundary"), std::string::npos) << r.out;

  const std::string cube = test::example_path("cube.obj");
  r = testing::stitch_cli(folder, "analyze '" + cube + "' --method mdc --json");
  ASSERT_EQ(r.status, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j["methods"][0].contains("sharp_features"));
  r = testing::stitch_cli(folder, "analyze '" + cube + "' --method mdc");
  EXPECT_EQ(r.out.find("sharp"), std::string::npos) << r.out;
}

TEST(AnalysisFeatures, SharpFromZeroMakesEveryTagSharpAndNoUntaggedEdge) {
  // --sharp-from 0 used to make every untagged edge a crease, and the K-gons then read
  // sharp-curve arrays that a mesh without tags does not have (a crash). Now an untagged edge is
  // never sharp: the closed cube is the default's surface, and a tagged crease is still a crease.
  KgonOptions zero;
  zero.sharp_from = 0;
  const HalfedgeMesh cube = make_cube();
  for (Edge e : cube.edges()) EXPECT_FALSE(is_sharp(cube, e, zero));
  for (Vertex v : cube.vertices()) EXPECT_EQ(vertex_kind(cube, v, zero), VertexKind::smooth);
  const Surface by_zero(cube, Method::mdc, zero), by_default(cube, Method::mdc);
  for (Corner c : by_default.corners())
    EXPECT_EQ(by_zero.evaluate(c, 0.3, 0.7).position, by_default.evaluate(c, 0.3, 0.7).position);
  HalfedgeMesh tagged = cube;
  tagged.set_sharpness(Edge(0), 0.5);
  EXPECT_TRUE(is_sharp(tagged, Edge(0), zero));
  EXPECT_FALSE(is_sharp(tagged, Edge(0), KgonOptions{}));
  EXPECT_NO_THROW(Surface(tagged, Method::mdc, zero));
}

}  // namespace
}  // namespace stitch
