// Repair on reading (issue 37): each repair on a mesh built here, the refusals that remain, the
// messages in the file's own numbering, the report, and every OpenSubdiv regression shape
// smoothing, the sheets of a split edge meeting along one curve.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "edge_samples.hpp"
#include "stitch/analysis/continuity.hpp"
#include "stitch/eval/surface.hpp"
#include "stitch/mesh/build.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/repair.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/tess/tessellate.hpp"
#include "temp_folder.hpp"
#include "test_support.hpp"

namespace stitch {

void PrintTo(RepairKind kind, std::ostream* os) {
  *os << choice_name(repair_kind_table(), kind);
}

namespace {

using test::error_of;
using testing::stitch_cli;
using testing::TempFolder;

bool contains(const std::string& text, const std::string& words) {
  return text.find(words) != std::string::npos;
}

/// Whether one of the lines contains the words.
bool any_contains(const std::vector<std::string>& lines, const std::string& words) {
  return std::any_of(lines.begin(), lines.end(),
                     [&](const std::string& line) { return contains(line, words); });
}

BuildOptions strict() {
  BuildOptions options;
  options.repair = false;
  return options;
}

/// Whether two loops are the same cycle (the same corners in the same order, from any start).
template <class T>
bool same_cycle(std::vector<T> a, const std::vector<T>& b) {
  for (size_t r = 0; r < a.size(); ++r) {
    if (a == b) return true;
    std::rotate(a.begin(), a.begin() + 1, a.end());
  }
  return a.empty() && b.empty();
}

/// The corners of a face as (vertex, texture coordinate) pairs.
std::vector<std::pair<int, int>> corners(const PolygonSoup& soup, size_t f) {
  std::vector<std::pair<int, int>> out;
  for (size_t i = 0; i < soup.faces[f].size(); ++i)
    out.emplace_back(soup.faces[f][i], soup.face_uvs[f][i]);
  return out;
}

/// Checks that the patches sharing a place along sharp edges agree to 1e-12 of the model size
/// (round-off in evaluating the same curve from different nets); returns the number of sample
/// places that three or more patches share (the split edges').
int expect_sheets_meet(const HalfedgeMesh& mesh, const KgonOptions& options,
                       const std::string& name) {
  const double tolerance = 1e-12 * test::mesh_size(mesh);
  int shared_by_three = 0;
  const Surface surface(mesh, Method::mdc, options);
  for (const auto& [key, points] :
       test::edge_samples(mesh, surface, [&](Edge e) { return mesh.is_sharp(e); })) {
    for (const auto& [p, v] : points)
      EXPECT_LT((p - points.front().first).norm(), tolerance)
          << name << ": sample " << key[6] << " from (" << key[0] * 1e-6 << ", " << key[1] * 1e-6
          << ", " << key[2] * 1e-6 << ") towards (" << key[3] * 1e-6 << ", " << key[4] * 1e-6
          << ", " << key[5] * 1e-6 << ")";
    shared_by_three += points.size() >= 3;
  }
  return shared_by_three;
}

// --- each repair on a mesh built here --------------------------------------------------------

TEST(Repair, CubeWithThreeFacesFlippedComesOutAsTheCube) {
  PolygonSoup cube = test::cube_soup();
  for (int f = 0; f < 6; ++f) {
    cube.face_uvs.push_back({});
    for (int i = 0; i < 4; ++i) {
      cube.face_uvs.back().push_back(static_cast<int>(cube.uvs.size()));
      cube.uvs.emplace_back(f, i);
    }
  }
  PolygonSoup soup = cube;
  for (int f : {0, 2, 4}) {
    std::reverse(soup.faces[f].begin(), soup.faces[f].end());
    std::reverse(soup.face_uvs[f].begin(), soup.face_uvs[f].end());
  }
  // Three against three: the tie goes to the winding that points the cube outward.
  PolygonSoup fixed = soup;
  const RepairReport report = repair(fixed);
  ASSERT_EQ(report.changes.size(), 3U);
  EXPECT_EQ(report.count(RepairKind::flipped_face), 3);
  for (size_t f = 0; f < 6; ++f) EXPECT_TRUE(same_cycle(corners(fixed, f), corners(cube, f))) << f;
  EXPECT_EQ(report.changes[0].faces, std::vector<int>{0});
  EXPECT_EQ(report.changes[0].action, "reversed its loop and its texture coordinates");

  BuildReport built;
  const HalfedgeMesh mesh = build_mesh(soup, {}, &built);
  const TopologyStats stats = topology_stats(mesh);
  EXPECT_EQ(stats.euler, 2);
  EXPECT_EQ(stats.components, 1);
  EXPECT_EQ(stats.faces, 6);
  EXPECT_NEAR(test::signed_volume(mesh), 1.0, 1e-12);
  ASSERT_FALSE(built.warnings.empty());
  EXPECT_TRUE(contains(built.warnings[0], "flipped 3 faces wound against their neighbours"))
      << built.warnings[0];
  EXPECT_EQ(built.repair.count(RepairKind::flipped_face), 3);
  // The texture coordinates went with the corners.
  for (Face f : mesh.faces())
    for (Halfedge h : mesh.face_loop(f)) {
      const Eigen::Vector2d uv = built.corner_uvs.uv[built.corner_uvs.index[h.idx]];
      const int k = static_cast<int>(uv.x()), i = static_cast<int>(uv.y());
      EXPECT_EQ(cube.faces[k][i], mesh.origin(h).idx);
    }

  // Two flipped: the four keep their winding.
  soup = cube;
  for (int f : {1, 3}) std::reverse(soup.faces[f].begin(), soup.faces[f].end());
  fixed = soup;
  EXPECT_EQ(repair(fixed).count(RepairKind::flipped_face), 2);
  for (size_t f = 0; f < 6; ++f) EXPECT_TRUE(same_cycle(fixed.faces[f], cube.faces[f])) << f;
  // Four flipped: the cube comes out inside out, as the larger part has it.
  soup = cube;
  for (int f : {0, 2, 4, 5}) std::reverse(soup.faces[f].begin(), soup.faces[f].end());
  EXPECT_LT(test::signed_volume(build_mesh(soup)), 0);

  const std::string message = error_of([&] { (void)build_mesh(soup, strict()); });
  EXPECT_TRUE(contains(message, "refused as it is (repairing is off)")) << message;
  EXPECT_TRUE(
      contains(message, "2 faces wound against their neighbours (inconsistent orientation)"))
      << message;
  EXPECT_TRUE(contains(message, "in the same direction as face")) << message;
}

/// Two regular tetrahedra whose vertices 0 and 1 are the same point, (1, 1, 1).
PolygonSoup two_tetrahedra() {
  PolygonSoup soup;
  soup.positions = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1},
                    {1, 3, 3}, {-1, 3, 1},  {-1, 1, 3}};
  soup.faces = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2},   // the first
                {4, 0, 5}, {4, 5, 6}, {4, 6, 0}, {0, 6, 5}};  // translated by (0, 2, 2)
  return soup;
}

TEST(Repair, TwoTetrahedraSharingAVertexComeOutAsTwoClosedPieces) {
  PolygonSoup soup = two_tetrahedra();
  soup.corners = {{0, 2.0, 0}};
  soup.creases = {{0, 1, 3.0, 0}, {0, 4, 5.0, 0}};
  BuildReport report;
  const HalfedgeMesh mesh = build_mesh(soup, {}, &report);
  ASSERT_EQ(report.repair.changes.size(), 1U);
  const RepairChange& change = report.repair.changes[0];
  EXPECT_EQ(change.kind, RepairKind::non_manifold_vertex);
  EXPECT_EQ(change.vertices, std::vector<int>{0});
  EXPECT_EQ(change.faces, (std::vector<int>{0, 1, 2, 4, 6, 7}));
  EXPECT_EQ(change.defect,
            "vertex 1 is non-manifold: its faces (face 1, face 2, face 3, face 5, face 7, ... (1 "
            "more)) form 2 fans");
  EXPECT_TRUE(any_contains(report.warnings, "split 1 non-manifold vertex")) << report.warnings[0];

  const TopologyStats stats = topology_stats(mesh);
  EXPECT_EQ(stats.vertices, 8);
  EXPECT_EQ(stats.components, 2);
  EXPECT_EQ(stats.boundary_loops, 0);
  EXPECT_EQ(stats.euler, 4);
  EXPECT_GT(test::signed_volume(mesh), 0);
  // The copies: at the same place, both corners (OpenSubdiv's non-manifold vertex), and the tags
  // went with them.
  std::vector<Vertex> copies;
  for (Vertex v : mesh.vertices())
    if (report.vertex_source[v.idx] == 0) copies.push_back(v);
  ASSERT_EQ(copies.size(), 2U);
  for (Vertex v : copies) {
    EXPECT_EQ(mesh.position(v), Vec3(1, 1, 1));
    EXPECT_EQ(mesh.sharpness(v), infinitely_sharp);
  }
  std::map<int, double> crease_to;  // the other end's soup vertex -> sharpness
  for (Vertex v : copies)
    for (Halfedge h : mesh.vertex_fan(v))
      if (mesh.sharpness(HalfedgeMesh::edge(h)) > 0)
        crease_to[report.vertex_source[mesh.target(h).idx]] = mesh.sharpness(HalfedgeMesh::edge(h));
  EXPECT_EQ(crease_to, (std::map<int, double>{{1, 3.0}, {4, 5.0}}));
  // Both surfaces pass through the point the pieces share.
  const Surface surface(mesh, Method::mdc);
  for (Corner c : surface.corners())
    if (report.vertex_source[mesh.origin(c).idx] == 0) {
      EXPECT_LT((surface.evaluate(c, 0, 0).position - Vec3(1, 1, 1)).norm(), 1e-12);
    }

  const std::string message = error_of([&] { (void)build_mesh(soup, strict()); });
  EXPECT_TRUE(contains(message,
                       "1 non-manifold vertex (its faces form several fans): vertex 1 "
                       "is non-manifold"))
      << message;
}

/// Three quads on the edge from (0, 0, 0) (vertex 0) to (0, 0, 1) (vertex 1), a third of a
/// turn apart; the first and the last run from 0 to 1, the middle one from 1 to 0.
PolygonSoup book() {
  PolygonSoup soup;
  soup.positions = {{0, 0, 0}, {0, 0, 1}};
  for (int page = 0; page < 3; ++page) {
    const double angle = 2 * M_PI * page / 3;
    soup.positions.emplace_back(std::cos(angle), std::sin(angle), 0);
    soup.positions.emplace_back(std::cos(angle), std::sin(angle), 1);
  }
  soup.faces = {{0, 1, 3, 2}, {1, 0, 4, 5}, {0, 1, 7, 6}};
  return soup;
}

/// A fin standing on an edge that ends inside a surface: the 4x4 quads of a saddle and one
/// quad standing up on the edge from vertex 7 to vertex 12 (0-based; both ends interior).
PolygonSoup fin_on_a_saddle() {
  PolygonSoup soup;
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 4; ++i)
      soup.positions.emplace_back(i, j, 0.1 * ((i - 2) * (i - 2) - (j - 2) * (j - 2)));
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      soup.faces.push_back({5 * j + i, 5 * j + i + 1, 5 * j + i + 6, 5 * j + i + 5});
  soup.positions.emplace_back(2, 1, 1.5);
  soup.positions.emplace_back(2, 2, 1.5);
  soup.faces.push_back({7, 12, 26, 25});
  return soup;
}

TEST(Repair, FinOnAnEdgeInsideASurfaceMeetsItAlongTheWholeEdge) {
  BuildReport report;
  const HalfedgeMesh mesh = build_mesh(fin_on_a_saddle(), {}, &report);
  EXPECT_EQ(report.repair.count(RepairKind::non_manifold_edge), 1);
  EXPECT_EQ(report.repair.count(RepairKind::non_manifold_vertex), 2);
  // The saddle's copies of the edge's ends are corners with that one sharp edge. Their K-gons
  // are turned to hold the edge, so the fin's straight boundary curve is the saddle's crease.
  EXPECT_EQ(expect_sheets_meet(mesh, {}, "fin"), 2 * 9);
  // And the saddle keeps one tangent plane there: the whole fan is one sector, G1 (1e-9
  // degrees: round-off in the normals of the patches meeting at the vertex; 1e-14 measured).
  const Surface surface(mesh, Method::mdc);
  const ContinuityReport continuity = analyze_continuity(mesh, surface);
  EXPECT_LT(continuity.features.sector_normal_spread_deg, 1e-9);
  EXPECT_EQ(continuity.features.cone_points, 0);
}

TEST(Repair, BookOfThreeQuadsKeepsOnePairOnTheSpine) {
  const PolygonSoup soup = book();
  BuildReport report;
  const HalfedgeMesh mesh = build_mesh(soup, {}, &report);
  EXPECT_EQ(report.repair.count(RepairKind::non_manifold_edge), 1);
  EXPECT_EQ(report.repair.count(RepairKind::non_manifold_vertex), 2);
  EXPECT_EQ(report.repair.count(RepairKind::flipped_face), 0);
  const RepairChange& edge = report.repair.changes.back();
  ASSERT_EQ(edge.kind, RepairKind::non_manifold_edge);
  EXPECT_EQ(edge.defect,
            "non-manifold edge (1, 2): it is shared by 3 faces (face 1, face 2, face 3)");
  // Page 2 runs the other way: it pairs with its neighbour round the edge, page 3.
  EXPECT_EQ(
      edge.action,
      "split it: face 2 with face 3 keeps it, tagged infinitely sharp; face 1 gets a boundary "
      "edge at the same place");
  EXPECT_TRUE(
      any_contains(report.warnings, "split 1 non-manifold edge (shared by 3 or more faces)"));

  const TopologyStats stats = topology_stats(mesh);
  EXPECT_EQ(stats.components, 2);
  EXPECT_EQ(stats.boundary_loops, 2);
  EXPECT_EQ(stats.faces, 3);
  EXPECT_EQ(stats.vertices, 10);
  EXPECT_EQ(stats.crease_edges, 1);
  EXPECT_EQ(stats.corner_vertices, 4);  // the spine's ends, twice each
  for (auto boundary : {BoundaryInterpolation::edge_and_corner, BoundaryInterpolation::edge_only}) {
    KgonOptions options;
    options.boundary = boundary;
    EXPECT_EQ(expect_sheets_meet(mesh, options, "book"), 2 * 9);  // two halves of the spine
  }
  const std::string message = error_of([&] { (void)build_mesh(soup, strict()); });
  EXPECT_TRUE(contains(message,
                       "1 non-manifold edge (shared by 3 or more faces): non-manifold edge "
                       "(1, 2): it is shared by 3 faces"))
      << message;
}

// OpenSubdiv's fan: three sheets on a chain of four edges. Inside the chain the copies stay
// crease vertices, so the shared curve is smooth there; its ends are corners.
TEST(Repair, FanOfThreeSheetsSharesOneCurve) {
  BuildReport report;
  const HalfedgeMesh mesh = read_mesh(test::opensubdiv_shape("catmark_fan.obj"), {}, &report);
  std::map<int, std::string> action;  // file vertex -> what became of it
  for (const RepairChange& c : report.repair.changes)
    if (c.kind == RepairKind::non_manifold_vertex) action[c.vertices[0] + 1] = c.action;
  ASSERT_EQ(action.size(), 5U);
  for (int v : {8, 12}) EXPECT_TRUE(contains(action[v], "infinitely sharp corner")) << v;
  for (int v : {9, 10, 11}) EXPECT_TRUE(contains(action[v], "crease vertices")) << v;
  int corners = 0;
  for (Vertex v : mesh.vertices()) corners += mesh.sharpness(v) == infinitely_sharp;
  EXPECT_EQ(corners, 4);
}

/// A band of `n` quads round a circle whose ends are joined with a half twist.
PolygonSoup mobius_strip(int n) {
  PolygonSoup soup;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * M_PI * i / n;
    const Vec3 centre(2 * std::cos(t), 2 * std::sin(t), 0);
    const Vec3 across =
        std::cos(t / 2) * Vec3(std::cos(t), std::sin(t), 0) + std::sin(t / 2) * Vec3(0, 0, 1);
    soup.positions.push_back(centre + 0.5 * across);
    soup.positions.push_back(centre - 0.5 * across);
  }
  for (int i = 0; i + 1 < n; ++i) soup.faces.push_back({2 * i, 2 * i + 1, 2 * i + 3, 2 * i + 2});
  soup.faces.push_back({2 * n - 2, 2 * n - 1, 0, 1});  // the twist: top meets bottom
  soup.source = "strip.obj";
  for (int f = 0; f < n; ++f) soup.face_lines.push_back(2 * n + 1 + f);
  return soup;
}

TEST(Repair, MobiusStripIsStillRefusedWithThePlace) {
  PolygonSoup soup = mobius_strip(8);
  for (const std::string& message :
       {error_of([&] { (void)build_mesh(soup); }), error_of([&] { (void)repair(soup); })}) {
    EXPECT_TRUE(contains(message, "strip.obj: a piece of the mesh cannot be oriented consistently"))
        << message;
    EXPECT_TRUE(contains(message,
                         "the piece with face 1 (line 17) is not orientable (like a "
                         "Möbius strip)"))
        << message;
    // Named where the file's windings disagree: the join with the half twist.
    EXPECT_TRUE(contains(message,
                         "no flips make its faces agree; face 1 (line 17) and face 8 "
                         "(line 24) run along edge (1, 2) in the same direction"))
        << message;
  }
  EXPECT_EQ(soup.faces, mobius_strip(8).faces);  // left as it was
  const std::string message = error_of([&] { (void)build_mesh(soup, strict()); });
  EXPECT_TRUE(contains(message, "1 non-orientable piece: the piece with face 1")) << message;
  // Two strips: both counted and named.
  PolygonSoup two = mobius_strip(8);
  const int nv = static_cast<int>(two.positions.size());
  for (int v = 0; v < nv; ++v) two.positions.push_back(two.positions[v] + Vec3(10, 0, 0));
  for (int f = 0; f < 8; ++f) {
    std::vector<int> loop = two.faces[f];
    for (int& v : loop) v += nv;
    two.faces.push_back(loop);
  }
  EXPECT_TRUE(contains(error_of([&] { (void)build_mesh(two); }), "2 pieces of the mesh cannot"));
}

TEST(Repair, DuplicateAndDegenerateFacesAreDroppedAndCounted) {
  PolygonSoup soup = test::cube_soup();
  soup.positions.emplace_back(5, 5, 5);  // only in a face that goes
  soup.faces[0] = {0, 2, 2, 3, 1};       // the cube's face with a repeat
  soup.faces.push_back({5, 4, 0, 1});    // face 3 again, from another corner
  soup.faces.push_back({3, 3, 7, 3});    // out to 7 and back: nothing left
  soup.faces.push_back({8, 8, 0});
  for (size_t f = 0; f < soup.faces.size(); ++f) {
    soup.face_uvs.push_back({});
    for (size_t i = 0; i < soup.faces[f].size(); ++i) {
      soup.face_uvs.back().push_back(static_cast<int>(soup.uvs.size()));
      soup.uvs.emplace_back(f, i);
    }
  }
  soup.corners = {{8, 10.0, 0}};
  soup.creases = {{0, 8, 10.0, 0}};
  PolygonSoup fixed = soup;
  const RepairReport report = repair(fixed);
  EXPECT_EQ(report.count(RepairKind::repeated_vertex), 3);
  EXPECT_EQ(report.count(RepairKind::degenerate_face), 2);
  EXPECT_EQ(report.count(RepairKind::duplicate_face), 1);
  EXPECT_EQ(report.count(RepairKind::dropped_tag), 2);
  PolygonSoup cube = test::cube_soup();
  EXPECT_EQ(fixed.faces, cube.faces);
  EXPECT_EQ(fixed.face_uvs[0], (std::vector<int>{0, 1, 3, 4}));  // the repeat's went with it
  EXPECT_EQ(fixed.face_origin, (std::vector<int>{0, 1, 2, 3, 4, 5}));
  EXPECT_TRUE(fixed.corners.empty());
  EXPECT_TRUE(fixed.creases.empty());
  const std::vector<std::string> summary = report.summary();
  ASSERT_EQ(summary.size(), 4U);
  EXPECT_EQ(
      summary[0],
      "removed the repeats in 3 faces that repeat a vertex: face 1 repeats vertex 3 at "
      "consecutive positions, face 8 repeats vertex 4 at consecutive positions and runs out to "
      "vertex 8 and straight back, face 9 repeats vertex 9 at consecutive positions");
  EXPECT_EQ(summary[1],
            "dropped 2 faces with fewer than 3 distinct vertices: face 8 is left with 1 distinct "
            "vertex, face 9 is left with 2 distinct vertices");
  EXPECT_EQ(summary[2], "dropped 1 duplicate face: face 7 repeats face 3");
  EXPECT_EQ(summary[3],
            "dropped 2 tags on elements that only dropped faces had: the corner tag names a "
            "vertex that only dropped faces had, the crease tag names an edge that only dropped "
            "faces had");

  BuildReport built;
  const HalfedgeMesh mesh = build_mesh(soup, {}, &built);
  EXPECT_EQ(built.dropped_vertices, 1);
  EXPECT_EQ(built.face_source, (std::vector<int>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(mesh, test::cube_mesh());
  const std::string message = error_of([&] { (void)build_mesh(soup, strict()); });
  EXPECT_TRUE(contains(message, "3 faces that repeat a vertex: face 1")) << message;
  EXPECT_TRUE(contains(message, "1 duplicate face: face 7 repeats face 3")) << message;
}

// Two faces each way on edge (4, 5): the repair leaves such an edge to the build's search for a
// manifold pairing when the vertices there look as if one could exist. Here none does, and the
// build refuses; the edge is then paired by angle like an edge of three faces.
TEST(Repair, EdgesTheBuildCannotPairArePairedByAngle) {
  PolygonSoup soup;
  soup.positions = {{2, 1, 0}, {0, -1, -1}, {2, 2, 0}, {2, 1, 0}, {2, 2, -1}};
  soup.faces = {{4, 3, 2}, {1, 4, 2}, {1, 3, 0}, {4, 1, 3}, {4, 3, 0}, {2, 3, 4}};
  BuildReport report;
  const HalfedgeMesh mesh = build_mesh(soup, {}, &report);
  EXPECT_TRUE(find_problems(mesh).empty());
  EXPECT_TRUE(any_contains(report.warnings,
                           "non-manifold edge (4, 5): it is shared by 4 faces (face 1, face 4, "
                           "face 5, face 6)"))
      << report.warnings[0];
  EXPECT_FALSE(error_of([&] { (void)build_mesh(soup, strict()); }).empty());
}

TEST(Repair, SoupsTheBuildAcceptsAreLeftAsTheyAre) {
  for (const std::string& name : test::closed_opensubdiv_shapes()) {
    PolygonSoup soup = read_polygon_soup(test::opensubdiv_shape(name));
    const PolygonSoup before = soup;
    EXPECT_TRUE(repair(soup).empty()) << name;
    EXPECT_EQ(soup.faces, before.faces) << name;
  }
  // Faces given with two vertices stay where 2-gons are allowed, and go where they are not.
  PolygonSoup soup = test::cube_soup();
  soup.faces.push_back({0, 1});
  PolygonSoup two_gons = soup;
  RepairOptions options;
  options.allow_two_gons = true;
  EXPECT_EQ(repair(two_gons, options).count(RepairKind::degenerate_face), 0);
  EXPECT_EQ(repair(soup).count(RepairKind::degenerate_face), 1);
}

// --- messages in the file's own numbering ------------------------------------------------------

TEST(Repair, MessagesNumberElementsAsTheFileDoes) {
  TempFolder folder;
  // Two triangles that share only vertex 0 (OFF, PLY), 1 (OBJ), or the origin (STL).
  const std::string off = folder.write(
      "bowtie.off", "OFF\n5 2 0\n0 0 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n3 0 1 2\n3 0 3 4\n");
  const std::string ply = folder.write(
      "bowtie.ply",
      "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty "
      "float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 "
      "0\n0 1 0\n-1 0 0\n0 -1 0\n3 0 1 2\n3 0 3 4\n");
  const std::string obj = folder.write(
      "bowtie.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv -1 0 0\nv 0 -1 0\nf 1 2 3\nf 1 4 5\n");
  const std::string stl = folder.write(
      "bowtie.stl",
      "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\n"
      "endfacet\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex -1 0 0\nvertex 0 -1 0\n"
      "endloop\nendfacet\nendsolid s\n");
  const std::map<std::string, std::string> expected{
      {off, "vertex 0 (line 3) is non-manifold: its faces (face 0 (line 8), face 1 (line 9))"},
      {ply, "vertex 0 (line 10) is non-manifold: its faces (face 0 (line 15), face 1 (line 16))"},
      {obj, "vertex 1 (line 1) is non-manifold: its faces (face 1 (line 6), face 2 (line 7))"},
      {stl,
       "the vertex at (0, 0, 0) is non-manifold: its faces (the face on line 3, the face on "
       "line 10)"}};
  for (const auto& [file, words] : expected) {
    const std::string& path = file;  // a lambda cannot capture a structured binding in C++17
    BuildReport report;
    const HalfedgeMesh mesh = read_mesh(path, {}, &report);
    EXPECT_EQ(topology_stats(mesh).components, 2) << path;
    ASSERT_FALSE(report.warnings.empty()) << path;
    EXPECT_TRUE(contains(report.warnings[0], words)) << report.warnings[0];
    const std::string message = error_of([&] { (void)read_mesh(path, strict()); });
    EXPECT_TRUE(contains(message, path + ": refused as it is")) << message;
    EXPECT_TRUE(contains(message, words)) << message;
  }
  // The JSON report numbers them the same way.
  BuildReport report;
  (void)read_mesh(obj, {}, &report);
  const nlohmann::json j = nlohmann::json::parse(to_json(report.repair));
  EXPECT_EQ(j["file"], obj);
  EXPECT_EQ(j["numbered_from"], 1);
  EXPECT_EQ(j["counts"], nlohmann::json({{"non_manifold_vertex", 1}}));
  ASSERT_EQ(j["changes"].size(), 1U);
  const nlohmann::json& change = j["changes"][0];
  EXPECT_EQ(change["kind"], "non_manifold_vertex");
  EXPECT_EQ(change["vertices"], nlohmann::json({1}));
  EXPECT_EQ(change["faces"], nlohmann::json({1, 2}));
  EXPECT_EQ(change["lines"], nlohmann::json({6, 7}));
  EXPECT_EQ(change["positions"], nlohmann::json({{0.0, 0.0, 0.0}}));
  EXPECT_EQ(change["action"],
            "split it into 2 vertices at the same position, each tagged as an infinitely sharp "
            "corner");
  (void)read_mesh(stl, {}, &report);
  const nlohmann::json s = nlohmann::json::parse(to_json(report.repair));
  EXPECT_TRUE(s["numbered_from"].is_null());
  EXPECT_FALSE(s["changes"][0].contains("vertices"));
}

TEST(Repair, CommandLineWarnsRefusesUnderStrictAndReportsJson) {
  TempFolder folder;
  folder.write("bowtie.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv -1 0 0\nv 0 -1 0\nf 1 2 3\nf 1 4 5\n");
  const auto smooth = stitch_cli(folder, "smooth bowtie.obj -o out.obj");
  EXPECT_EQ(smooth.status, 0) << smooth.err;
  EXPECT_TRUE(contains(smooth.err, "stitch: warning: bowtie.obj: split 1 non-manifold vertex"))
      << smooth.err;
  const auto strict = stitch_cli(folder, "smooth bowtie.obj -o strict.obj --strict");
  EXPECT_EQ(strict.status, 2);
  EXPECT_TRUE(contains(strict.err,
                       "bowtie.obj: refused as it is (repairing is off): 1 "
                       "non-manifold vertex"))
      << strict.err;
  EXPECT_FALSE(std::filesystem::exists(folder.file("strict.obj")));
  const auto info = stitch_cli(folder, "info bowtie.obj");
  EXPECT_TRUE(contains(info.out, "repaired on reading  1 non_manifold_vertex")) << info.out;
  const auto report = stitch_cli(folder, "info bowtie.obj --repair-report");
  EXPECT_EQ(report.status, 0) << report.err;
  const nlohmann::json j = nlohmann::json::parse(report.out);
  EXPECT_EQ(j["counts"]["non_manifold_vertex"], 1);
  EXPECT_EQ(j["changes"][0]["vertices"], nlohmann::json({1}));
}

// --- the OpenSubdiv regression shapes ------------------------------------------------------------

/// What the repair does to each OpenSubdiv shape that needs one.
struct ShapeRepairs {
  std::map<RepairKind, int> counts;
  int split_samples = 0;  ///< places on split edges that three or more patches share
};

const std::map<std::string, ShapeRepairs>& repaired_shapes() {
  using K = RepairKind;
  static const std::map<std::string, ShapeRepairs> shapes{
      // A fan of three sheets on a chain of four edges: one pair and one boundary on each.
      {"catmark_fan", {{{K::non_manifold_edge, 4}, {K::non_manifold_vertex, 5}}, 4 * 2 * 9}},
      {"catmark_gregory_test4", {{{K::non_manifold_vertex, 1}}}},
      // 100 faces on one edge: 50 pairs.
      {"catmark_nonman_edge100", {{{K::non_manifold_edge, 1}, {K::non_manifold_vertex, 2}}, 18}},
      // Nine shapes: fins on an edge, faces that fold back on an edge, a tube wound half one
      // way, half the other. One fin stands on an edge that ends inside a grid.
      {"catmark_nonman_edges",
       {{{K::repeated_vertex, 14},
         {K::degenerate_face, 4},
         {K::flipped_face, 5},
         {K::non_manifold_edge, 5},
         {K::non_manifold_vertex, 7}},
        90}},
      // Quads that repeat the pole, made triangles.
      {"catmark_nonman_quadpole8", {{{K::repeated_vertex, 8}}}},
      {"catmark_nonman_quadpole64", {{{K::repeated_vertex, 64}}}},
      {"catmark_nonman_quadpole360", {{{K::repeated_vertex, 360}}}},
      {"catmark_nonman_verts", {{{K::non_manifold_vertex, 4}}}},
      // Two triangles on one edge in the same direction; pillows with faces at a vertex.
      {"catmark_val2_nonman", {{{K::flipped_face, 1}, {K::non_manifold_vertex, 3}}}},
      {"loop_nonman_edge100", {{{K::non_manifold_edge, 1}, {K::non_manifold_vertex, 2}}, 18}},
      {"loop_nonman_edges",
       {{{K::repeated_vertex, 4},
         {K::degenerate_face, 4},
         {K::flipped_face, 4},
         {K::non_manifold_edge, 6},
         {K::non_manifold_vertex, 9}},
        108}},
      {"loop_nonman_verts", {{{K::non_manifold_vertex, 4}}}},
      {"loop_val2_interior", {{{K::non_manifold_vertex, 1}}}},
  };
  return shapes;
}

std::vector<std::string> all_shapes() {
  std::vector<std::string> names = test::opensubdiv_shape_files();
  for (std::string& name : names) name.erase(name.size() - 4);  // the ".obj"
  return names;
}

class EveryOpenSubdivShape : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryOpenSubdivShape, Smooths) {
  const std::string& name = GetParam();
  BuildOptions options;
  options.allow_two_gons = true;  // as stitch reads files
  BuildReport report;
  const HalfedgeMesh mesh = read_mesh(test::opensubdiv_shape(name + ".obj"), options, &report);
  const auto found = repaired_shapes().find(name);
  std::map<RepairKind, int> counts;
  for (const RepairChange& c : report.repair.changes) ++counts[c.kind];
  const std::map<RepairKind, int> expected =
      found == repaired_shapes().end() ? std::map<RepairKind, int>{} : found->second.counts;
  EXPECT_EQ(counts, expected);
  // Each kind repaired is named in a warning, first among them.
  const std::vector<std::string> summary = report.repair.summary();
  EXPECT_EQ(summary.size(), counts.size()) << name;
  ASSERT_GE(report.warnings.size(), summary.size()) << name;
  EXPECT_TRUE(std::equal(summary.begin(), summary.end(), report.warnings.begin())) << name;
  const Surface surface(mesh, Method::mdc);
  const TessellatedMesh t = tessellate(mesh, surface, {2, true});
  for (const Vec3& p : t.positions) ASSERT_TRUE(p.allFinite()) << name;
  if (found != repaired_shapes().end() && counts.count(RepairKind::non_manifold_edge)) {
    EXPECT_EQ(expect_sheets_meet(mesh, {}, name), found->second.split_samples) << name;
  }
  // Refused as before under --strict, with every defect counted.
  if (found != repaired_shapes().end()) {
    const std::string message =
        error_of([&] { (void)read_mesh(test::opensubdiv_shape(name + ".obj"), strict()); });
    EXPECT_TRUE(contains(message, "refused as it is (repairing is off)")) << message;
  }
}

INSTANTIATE_TEST_SUITE_P(OpenSubdiv, EveryOpenSubdivShape, ::testing::ValuesIn(all_shapes()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace stitch
