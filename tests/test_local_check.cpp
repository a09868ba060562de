// The local surface check (folds and self-intersections near an edit): it finds what the whole
// surface check finds on the patches an edit changed, and its work follows the edit, not the
// mesh.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <sstream>

#include "cli_run.hpp"
#include "stitch/analysis/local_check.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/mesh_journal.hpp"
#include "stitch/tess/tessellate.hpp"
#include "stitch/topology/operation.hpp"
#include "stitch/topology/primitives.hpp"
#include "stitch/topology/remesh.hpp"
#include "temp_folder.hpp"

namespace stitch {
namespace {

/// Applies `op` under a journal and returns the corners whose patches it may have changed.
std::vector<Corner> edit(HalfedgeMesh& mesh, const std::string& op) {
  MeshJournal journal(mesh);
  apply_operation(mesh, op);
  const MeshDelta d = journal.finish();
  return patches_touched(mesh, d.vertices, d.edges, d.faces);
}

struct WholeCheck {
  SurfaceCheckReport report;
  std::set<int> problem_corners;  ///< half-edge indices of the patches of the listed pairs
};

/// check_surface on the welded tessellation, as `stitch smooth` + `stitch check-surface` run it.
WholeCheck whole_check(const HalfedgeMesh& mesh, const Surface& surface, int resolution) {
  TessellationOptions t;
  t.resolution = resolution;
  const TriangleSoup soup = triangulate(tessellate(mesh, surface, t));
  SurfaceCheckOptions o;
  o.max_listed = 1 << 30;
  WholeCheck w;
  w.report = check_surface(soup, o);
  const int quads_per_patch = resolution * resolution;
  for (const auto* pairs : {&w.report.intersecting_pairs, &w.report.folded_pairs})
    for (const auto& p : *pairs)
      for (int tri : p)
        w.problem_corners.insert(surface.corners()[soup.source[tri] / quads_per_patch].idx);
  return w;
}

std::set<int> indices(const std::vector<Corner>& corners) {
  std::set<int> out;
  for (Corner c : corners) out.insert(c.idx);
  return out;
}

// The straight tube through prism 30's caps folds in four pairs of triangles at resolution 16,
// at the corners of the bridge's ends (clean at 32: docs/method.md, "Quads split along the
// shorter diagonal"). The cube's half twist, its space-diagonal bridge "insert-edge 3@1 5@3",
// then its bent tunnel "insert-edge 1@1 6@3", prism 7's three-step twist "insert-edge 1@1 11@2",
// prism 9's four-step twist "insert-edge 1@1 14@2", prism 11's five-step twist "insert-edge 1@1
// 17@2" and then prism 14's half twist "insert-edge 1@1 22@2", which these tests used before, no
// longer fold.
constexpr const char* kFoldingEdit = "insert-edge 1@1 31@2";
constexpr int kFoldingPrism = 30;

TEST(LocalCheck, TheTwistedTubeFoldsWhereTheWholeCheckSaysSo) {
  HalfedgeMesh mesh = make_prism(kFoldingPrism);
  const std::vector<Corner> changed = edit(mesh, kFoldingEdit);
  const Surface surface(mesh, Method::mdc);
  const LocalCheckReport local = check_patches(mesh, surface, changed);
  EXPECT_FALSE(local.clean());
  EXPECT_GT(local.folds, 0);
  const WholeCheck whole = whole_check(mesh, surface, 16);
  EXPECT_FALSE(whole.report.clean());
  // On the prism the merged face reaches every patch, so both checks see the same triangles and
  // must count the same problems on the same patches.
  EXPECT_EQ(local.changed_patches, static_cast<int>(mesh.patch_corners().size()));
  EXPECT_EQ(local.triangles, whole.report.triangles);
  EXPECT_EQ(local.folds, whole.report.folds);
  EXPECT_EQ(local.self_intersections, whole.report.self_intersections);
  EXPECT_EQ(indices(local.problem_corners), whole.problem_corners);
  // The folds lie on the merged face's patches.
  for (const std::string& name : corner_names(mesh, local.problem_corners))
    EXPECT_NE(name.find("@1"), std::string::npos) << name;
}

TEST(LocalCheck, TheStraightTubeIsClean) {
  HalfedgeMesh mesh = make_cube();
  const std::vector<Corner> changed = edit(mesh, "insert-edge 1@1 5@2");
  const Surface surface(mesh, Method::mdc);
  const LocalCheckReport local = check_patches(mesh, surface, changed);
  EXPECT_TRUE(local.clean()) << local.folds << " folds, " << local.self_intersections
                             << " crossings";
  EXPECT_TRUE(local.problem_corners.empty());
  EXPECT_GT(local.triangles, 0);
  EXPECT_TRUE(whole_check(mesh, surface, 16).report.clean());
}

TEST(LocalCheck, FindsAFoldOnlyWhereItsPatchesAreInFocus) {
  // The twisted tube again, but only patches far from its folds in focus: two corners of a side
  // face do not touch the folded patches' triangles.
  HalfedgeMesh mesh = make_prism(kFoldingPrism);
  edit(mesh, kFoldingEdit);
  const Surface surface(mesh, Method::mdc);
  const std::vector<Corner> far = {parse_corner(mesh, "15@17"), parse_corner(mesh, "46@17")};
  const LocalCheckReport r = check_patches(mesh, surface, far);
  EXPECT_EQ(r.changed_patches, 2);
  EXPECT_GT(r.patches, 2);
  EXPECT_TRUE(r.clean());
  EXPECT_EQ(check_patches(mesh, surface, {}).triangles, 0);
}

TEST(LocalCheck, SkipsHolesAndDeletedCorners) {
  HalfedgeMesh mesh = make_cube();
  const Corner top = parse_corner(mesh, "5@2"), gone = parse_corner(mesh, "1@3");
  apply_operation(mesh, "open-face 2");
  apply_operation(mesh, "collapse-edge 1 2");
  ASSERT_TRUE(mesh.is_hole(top));
  ASSERT_TRUE(mesh.is_deleted(gone));
  const Surface surface(mesh, Method::mdc);
  int sampled = 0;
  const PatchGridSampler sample = [&](Corner c, int i, int j) {
    ++sampled;
    EXPECT_FALSE(mesh.is_hole(c) || mesh.is_deleted(c));
    return surface.evaluate(c, i / 4.0, j / 4.0).position;
  };
  LocalCheckOptions o;
  o.resolution = 4;
  const LocalCheckReport r = check_patches(mesh, {top, gone}, sample, o);
  EXPECT_EQ(r.changed_patches, 0);
  EXPECT_EQ(r.triangles, 0);
  EXPECT_EQ(sampled, 0);
  // A patch beside the hole is checked with its neighbours, none of which lie in the hole.
  const LocalCheckReport beside = check_patches(mesh, {parse_corner(mesh, "6@3")}, sample, o);
  EXPECT_EQ(beside.changed_patches, 1);
  EXPECT_GT(beside.patches, 1);
  EXPECT_GT(sampled, 0);
  EXPECT_TRUE(beside.clean());
}

/// The cube refined `steps` times by Catmull-Clark, and the corner numbers of the twisted edit
/// there: vertex 1 keeps its number on face 1; vertex 7's corner on the old top face is the
/// first quad of the quad at 7 of the step before (docs/editing.md, catmull-clark).
std::pair<HalfedgeMesh, std::string> refined_cube_edit(int steps) {
  HalfedgeMesh mesh = make_cube();
  int face_at_7 = 2;  // on the cube: 7@2 (vertex 7 is the third corner of face 2: 5 6 7 8)
  for (int s = 0; s < steps; ++s) {
    mesh = catmull_clark_step(mesh);
    face_at_7 = s == 0 ? 4 * (face_at_7 - 1) + 3 : 4 * (face_at_7 - 1) + 1;
  }
  return {std::move(mesh), fmt::format("insert-edge 1@1 7@{}", face_at_7)};
}

TEST(LocalCheck, WorkFollowsTheEditNotTheMesh) {
  // The same edit on the cube refined 3 and 5 times (384 and 6144 faces): the corners' rings
  // look alike, so the check tessellates the same number of patches and triangles.
  std::vector<LocalCheckReport> reports;
  std::vector<int> mesh_patches;
  for (int steps : {3, 5}) {
    auto [mesh, op] = refined_cube_edit(steps);
    SCOPED_TRACE(op);
    mesh_patches.push_back(static_cast<int>(mesh.patch_corners().size()));
    const std::vector<Corner> changed = edit(mesh, op);
    const Surface surface(mesh, Method::mdc);
    reports.push_back(check_patches(mesh, surface, changed));
  }
  EXPECT_EQ(mesh_patches[1], 16 * mesh_patches[0]);
  EXPECT_EQ(reports[0].changed_patches, reports[1].changed_patches);
  EXPECT_EQ(reports[0].patches, reports[1].patches);
  EXPECT_EQ(reports[0].triangles, reports[1].triangles);
  EXPECT_GT(reports[0].triangles, 0);
  EXPECT_LT(reports[1].patches * 20, mesh_patches[1]);
  EXPECT_EQ(reports[1].triangles, reports[1].patches * 2 * 16 * 16);
}

TEST(LocalCheck, PatchesTouchedCoverEveryPatchThatChanged) {
  // Every patch whose net differs after the edit is among those patches_touched returns.
  const HalfedgeMesh cube = catmull_clark_step(make_cube());
  // Vertex 1 (valence 3) and a neighbour (an edge point); face point 9 is on face 1.
  const int next = cube.target(cube.halfedge(Vertex(0))).idx + 1;
  for (const std::string& op :
       {std::string("extrude-face 3 0.5"), fmt::format("collapse-edge 1 {}", next),
        fmt::format("subdivide-edge 1 {}", next), fmt::format("delete-edge 1 {}", next),
        std::string("insert-edge 1@1 9@1"), std::string("open-face 4")}) {
    SCOPED_TRACE(op);
    HalfedgeMesh mesh = cube;
    const std::vector<Corner> touched = edit(mesh, op);
    const BezierSurface before = build_bezier_surface(cube), after = build_bezier_surface(mesh);
    const std::set<int> covered = indices(touched);
    int differing = 0;
    for (Corner c : mesh.patch_corners()) {
      const bool same = c.idx < cube.halfedge_capacity() && !cube.is_deleted(c) &&
                        !cube.is_hole(c) && before.nets[c.idx] == after.nets[c.idx];
      if (same) continue;
      ++differing;
      EXPECT_TRUE(covered.count(c.idx)) << "corner " << c.idx;
    }
    EXPECT_GT(differing, 0);
    EXPECT_LT(touched.size(), mesh.patch_corners().size());
  }
}

TEST(LocalCheck, CornerNamesNumberAsTheFileDoes) {
  HalfedgeMesh mesh = make_cube();
  apply_operation(mesh, "insert-edge 1@1 5@2");  // face 2 goes: faces above it shift down
  const Corner c = parse_corner(mesh, "2@3");
  EXPECT_EQ(corner_names(mesh, {c}), std::vector<std::string>{"2@3"});
  EXPECT_EQ(corner_names(mesh, {c}, true), std::vector<std::string>{"2@2"});
  const Corner twice = parse_corner(mesh, "1@1#2");
  EXPECT_EQ(corner_names(mesh, {twice}, true), std::vector<std::string>{"1@1#2"});
}

TEST(LocalCheckCli, EditCheckWarnsAboutTheTwistedTubeAndNotTheStraightTube) {
  testing::TempFolder dir;
  write_mesh(dir.file("cube.obj"), make_cube());
  write_mesh(dir.file("prism.obj"), make_prism(kFoldingPrism));
  // The tube's fitted K-gons fold; by default --check checks the surface stitch smooth makes,
  // whose K-gon controls are chosen where they fold (unfold_tubes): it says so and is clean.
  auto r = testing::stitch_cli(
      dir, "edit prism.obj --op \"" + std::string(kFoldingEdit) + "\" -o unfolded.obj --check");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("stitch: note: unfolded.obj: the tube of face 1 (bridge 1 31) folds with "
                       "its fitted K-gons (4 folded and 0 crossing pairs of triangles at "
                       "resolution 16); chosen instead: face K-gon scale 1.2 rotate 0"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.out.find("check: no folds or self-intersections near the edits"), std::string::npos)
      << r.out;

  // The fitted K-gons, as --no-unfold-tubes keeps them.
  r = testing::stitch_cli(dir, "edit prism.obj --op \"" + std::string(kFoldingEdit) +
                                   "\" -o twisted.obj --check --no-unfold-tubes");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("stitch: warning: the surface folds at patches "), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("(corners 1@1#2, 1@1#1, 31@1#2, 31@1#1 of twisted.obj)"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("see stitch check-surface"), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir.file("twisted.obj")));

  r = testing::stitch_cli(dir, "edit prism.obj --op \"" + std::string(kFoldingEdit) +
                                   "\" -o strict.obj --strict -q --no-unfold-tubes");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("folds"), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir.file("strict.obj")));
  EXPECT_TRUE(r.out.empty()) << r.out;

  r = testing::stitch_cli(dir, "edit cube.obj --op \"insert-edge 1@1 5@2\" -o holed.obj --strict");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("check: no folds or self-intersections near the edits (26 patches changed"),
            std::string::npos)
      << r.out;

  // Without --check nothing is checked.
  r = testing::stitch_cli(dir,
                          "edit prism.obj --op \"" + std::string(kFoldingEdit) + "\" -o plain.obj");
  EXPECT_EQ(r.status, 0);
  EXPECT_TRUE(r.err.empty()) << r.err;

  // The patch numbers are those of the written file read back: the whole check of its surface
  // finds the folds on those patches.
  r = testing::stitch_cli(dir, "edit prism.obj --op \"" + std::string(kFoldingEdit) +
                                   "\" -o twisted.obj --check --no-unfold-tubes");
  const size_t from = r.err.find("patches ") + 8, to = r.err.find(" (corners");
  ASSERT_LT(from, to) << r.err;
  std::set<int> numbers;
  std::istringstream list(r.err.substr(from, to - from));
  for (std::string n; std::getline(list, n, ',');) numbers.insert(std::stoi(n));
  const HalfedgeMesh back = read_mesh(dir.file("twisted.obj"));
  EXPECT_EQ(numbers, whole_check(back, Surface(back, Method::mdc), 16).problem_corners);
}

}  // namespace
}  // namespace stitch
