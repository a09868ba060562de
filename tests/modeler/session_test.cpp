// The script language, run on a window-free session.
#include "stitch/modeler/session.hpp"

#include <gtest/gtest.h>

#include "stitch/analysis/build_surface.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/tess/bezier_json.hpp"
#include "stitch/tess/export.hpp"
#include "stitch/tess/tessellate.hpp"
#include "stitch/topology/primitives.hpp"
#include "temp_folder.hpp"
#include "test_support.hpp"

namespace stitch::modeler {
namespace {

TEST(ModelerSession, ScriptBuildsTheCubeWithAHoleAndUndoes) {
  stitch::testing::TempFolder dir;
  Session s;
  std::vector<std::string> printed;
  ScriptHooks hooks;
  hooks.print = [&](const std::string& t) { printed.push_back(t); };
  bool quit = false;
  const auto error = run_script(
      s,
      {"open " + test::example_path("cube.obj"), "# a comment",
       "insert-edge 1@1 5@2   # the vertical bridge", "method asc", "mode zebra", "view front",
       "save " + dir.file("hole.obj"), "undo", "save " + dir.file("undone.obj"), "redo", "info",
       "quit", "this line is not reached"},
      hooks, &quit);
  ASSERT_FALSE(error) << error->line << ": " << error->message;
  EXPECT_TRUE(quit);
  const HalfedgeMesh hole = read_mesh(dir.file("hole.obj"), {false, true});
  const TopologyStats t = topology_stats(hole);
  EXPECT_EQ(t.genus, 1);
  EXPECT_EQ(t.degree_histogram.at(10), 1);
  EXPECT_TRUE(read_mesh(dir.file("undone.obj")) == read_mesh(test::example_path("cube.obj")));
  EXPECT_EQ(s.display.method, Method::asc);
  EXPECT_EQ(s.display.mode, ShadingMode::zebra);
  EXPECT_EQ(s.surface.method(), Method::asc);
  EXPECT_EQ(topology_stats(s.document.mesh()).genus, 1);
  ASSERT_FALSE(printed.empty());
  EXPECT_NE(printed.back().find("genus 1"), std::string::npos);
}

TEST(ModelerSession, ErrorsNameTheLineAndLeaveTheSessionUnchanged) {
  Session s(make_cube());
  const HalfedgeMesh before = s.document.mesh();
  auto error = run_script(s, {"view iso", "", "insert-edge 1@1 9@2"}, {});
  ASSERT_TRUE(error);
  EXPECT_EQ(error->line, 3);
  EXPECT_NE(error->message.find("vertex"), std::string::npos);
  EXPECT_TRUE(s.document.mesh() == before);
  for (const char* bad :
       {"method xyz", "mode glossy", "resolution 0", "view sideways", "frobnicate",
        "select face 99", "kgon scale big", "undo", "screenshot a.png", "save",
        "overlay mesh maybe", "open /nonexistent.obj"}) {
    SCOPED_TRACE(bad);
    error = run_script(s, {bad}, {});
    ASSERT_TRUE(error);
    EXPECT_EQ(error->line, 1);
    EXPECT_FALSE(error->message.empty());
  }
  EXPECT_TRUE(s.document.mesh() == before);
}

TEST(ModelerSession, CatmullClarkShowsTheCubeWithAHole) {
  Session s(make_cube());
  ASSERT_FALSE(run_script(s, {"insert-edge 1@1 5@2", "method cc", "undo", "redo"}, {}));
  EXPECT_EQ(topology_stats(s.document.mesh()).genus, 1);
  EXPECT_EQ(s.display.method, Method::cc);
  EXPECT_EQ(s.surface.method(), Method::cc);
  EXPECT_TRUE(s.warning.empty()) << s.warning;
}

// The split view's surface follows the document only through Session::take_changes, a batch of
// lines at a time; after each batch it must equal a surface built from scratch (bit for bit:
// the same code on the same numbers).
TEST(ModelerSession, ASecondSurfaceFollowsTheDocumentThroughTakenChanges) {
  Session s(make_cube());
  IncrementalSurface follower;
  follower.rebuild(s.document.mesh(), s.document.kgon_options(), Method::asc, 3);
  EXPECT_TRUE(s.take_changes().whole);  // the session's own first build
  const std::vector<std::vector<std::string>> batches = {
      {"insert-edge 1@1 5@2"},
      {"move-vertex 2 1.2 1.1 -1", "subdivide-edge 1 5@1", "extrude-face 3 0.3"},
      {"undo", "undo"},
      {"redo"},
      {"mode zebra"},
      {"catmull-clark", "undo"}};
  for (const auto& batch : batches) {
    SCOPED_TRACE(batch.front());
    ASSERT_FALSE(run_script(s, batch, {}));
    const Change missed = s.take_changes();
    follower.update(s.document.mesh(), s.document.kgon_options(), missed);
    IncrementalSurface fresh;
    fresh.rebuild(s.document.mesh(), s.document.kgon_options(), Method::asc, 3);
    ASSERT_EQ(follower.corners(), fresh.corners());
    const int per = fresh.vertices_per_patch();
    int mismatches = 0;
    for (Corner c : fresh.corners()) {
      mismatches += follower.nets()[c.idx] == fresh.nets()[c.idx] ? 0 : 1;
      for (int k = c.idx * per; k < (c.idx + 1) * per; ++k)
        mismatches += follower.tessellation().positions[k] == fresh.tessellation().positions[k] &&
                              follower.tessellation().normals[k] == fresh.tessellation().normals[k]
                          ? 0
                          : 1;
    }
    EXPECT_EQ(mismatches, 0);
  }
}

TEST(ModelerSession, SelectionDrivesKgonEdits) {
  Session s(make_cube());
  ASSERT_FALSE(run_script(s, {"select face 3", "kgon scale 0.5", "kgon rotate 20"}, {}));
  EXPECT_EQ(s.document.kgon_control({KgonKind::face, 2}).scale, 0.5);
  EXPECT_EQ(s.document.kgon_control({KgonKind::face, 2}).rotate_deg, 20.0);
  ASSERT_FALSE(run_script(s, {"kgon stretch 1.5 0 0 1"}, {}));
  EXPECT_EQ(s.document.kgon_control({KgonKind::face, 2}).stretch, 1.5);
  EXPECT_EQ(s.document.kgon_control({KgonKind::face, 2}).stretch_along, Vec3(0, 0, 1));
  EXPECT_TRUE(run_script(s, {"kgon stretch 1.5 0 0"}, {}));  // the direction needs three numbers
  // Each field of the control by its name, as files spell it.
  ASSERT_FALSE(run_script(s, {"kgon stretch_along 0 1 0", "kgon stretch 2"}, {}));
  EXPECT_EQ(s.document.kgon_control({KgonKind::face, 2}).stretch_along, Vec3(0, 1, 0));
  EXPECT_EQ(s.document.kgon_control({KgonKind::face, 2}).stretch, 2.0);
  const auto out_of_range = run_script(s, {"kgon stretch 0"}, {});
  ASSERT_TRUE(out_of_range);
  EXPECT_NE(out_of_range->message.find("the stretch must be a number from"), std::string::npos)
      << out_of_range->message;
  const auto unknown = run_script(s, {"kgon scael 2"}, {});
  ASSERT_TRUE(unknown);
  EXPECT_NE(unknown->message.find("'scael' (scale, rotate, offset, regularize, stretch, "
                                  "stretch_along, reset)"),
            std::string::npos)
      << unknown->message;
  for (int i = 0; i < 2; ++i) ASSERT_FALSE(run_script(s, {"undo"}, {}));
  ASSERT_FALSE(run_script(s, {"undo"}, {}));
  ASSERT_FALSE(run_script(s,
                          {"select edge 1 2", "kgon offset 0 0 0.1", "select corner 7@2",
                           "kgon regularize on", "select none", "kgon scale 0.8"},
                          {}));
  EXPECT_EQ(s.document.kgon_options().edge.size(), 1u);
  EXPECT_TRUE(s.document.kgon_control({KgonKind::face, 1}).regularize);  // corner 7@2 -> face 2
  EXPECT_EQ(s.document.kgon_options().global.scale, 0.8);
  // Every K-gon edit is one undo step, and the surface follows.
  for (int i = 0; i < 5; ++i) ASSERT_FALSE(run_script(s, {"undo"}, {}));
  EXPECT_TRUE(s.document.kgon_options().face.empty());
  const auto fresh = build_control_nets(s.document.mesh(), build_kgons(s.document.mesh()));
  for (Corner c : s.document.mesh().halfedges())
    EXPECT_TRUE(s.surface.nets()[c.idx] == fresh[c.idx]);
}

TEST(ModelerSession, VertexMovesAreLocalAndUndoable) {
  Session s(make_torus(12, 8));
  const HalfedgeMesh before = s.document.mesh();
  ASSERT_FALSE(run_script(s, {"translate-vertex 5 0 0 0.2"}, {}));
  EXPECT_FALSE(s.last_update.full);
  EXPECT_LT(s.last_update.recomputed_patches, s.surface.num_patches() / 4);
  ASSERT_FALSE(run_script(s, {"undo"}, {}));
  EXPECT_TRUE(s.document.mesh() == before);
}

TEST(ModelerSession, PathsMayContainBlanks) {
  stitch::testing::TempFolder dir;
  Session s(make_cube());
  const std::string path = dir.file("my model.obj");
  ASSERT_FALSE(run_script(s, {"save " + path + "   # a comment", "open " + path}, {}));
  EXPECT_EQ(s.path, path);
  EXPECT_TRUE(s.document.mesh() == make_cube());
}

TEST(ModelerSession, ProjectsKeepKgonsViewAndDisplay) {
  stitch::testing::TempFolder dir;
  Session s(make_cube());
  ASSERT_FALSE(run_script(s,
                          {"select vertex 3", "kgon scale 0.6", "method cc", "overlay kgons on",
                           "split asc", "view top", "save " + dir.file("p.stitch")},
                          {}));
  Session t;
  ASSERT_FALSE(run_script(t, {"open " + dir.file("p.stitch")}, {}));
  EXPECT_TRUE(t.document.mesh() == s.document.mesh());
  EXPECT_EQ(t.document.kgon_options().vertex, s.document.kgon_options().vertex);
  EXPECT_EQ(t.display, s.display);
  EXPECT_EQ(t.view, s.view);
  EXPECT_EQ(t.surface.method(), Method::cc);
  EXPECT_EQ(t.path, dir.file("p.stitch"));
}

TEST(ModelerSession, ExportWritesTheSurfaceAsShown) {
  stitch::testing::TempFolder dir;
  Session s;
  // K-gon controls, the method and the resolution shown are what is exported.
  ASSERT_FALSE(run_script(s,
                          {"open " + test::example_path("cube.obj"), "insert-edge 1@1 5@2",
                           "kgon global scale 0.8", "method asc", "resolution 3",
                           "export " + dir.file("shown.ply"), "export " + dir.file("shown.json")},
                          {}));
  KgonOptions controls;
  controls.global.scale = 0.8;
  const Surface expected_surface(s.document.mesh(), Method::asc, controls);
  const std::string expected = dir.file("expected.ply");
  write_smooth_surface(expected, MeshFileFormat::ply, s.document.mesh(), expected_surface, 3);
  EXPECT_EQ(stitch::testing::read_file(dir.file("shown.ply")),
            stitch::testing::read_file(expected));
  const PatchSet patches = read_bezier_json(dir.file("shown.json"));
  EXPECT_EQ(patches.method, Method::asc);
  EXPECT_EQ(patches.patches.size(), static_cast<size_t>(s.document.mesh().num_halfedges()));
  // A mesh export does not change the document or its file.
  EXPECT_FALSE(s.document.can_redo());
  EXPECT_TRUE(s.path.find("cube.obj") != std::string::npos) << s.path;
  const auto error = run_script(s, {"method cc", "export " + dir.file("cc.json")}, {});
  ASSERT_TRUE(error);
  EXPECT_NE(error->message.find("not a set of Bezier patches"), std::string::npos)
      << error->message;
  EXPECT_FALSE(std::filesystem::exists(dir.file("cc.json")));
  EXPECT_TRUE(run_script(s, {"export"}, {}));
}

TEST(ModelerSession, ScriptLoopRunsLinesThroughTheApplicationsHook) {
  // The application's lines go through hooks.run_line; the loop keeps the numbering, stops at
  // the first error and at quit.
  Session s(make_cube());
  std::vector<std::string> seen;
  ScriptHooks hooks;
  hooks.run_line = [&](std::string_view line) {
    seen.emplace_back(line);
    if (line == "window-only") return ScriptResult{};
    return run_script_line(s, line, hooks);
  };
  EXPECT_FALSE(run_script(s, {"window-only", "select face 1"}, hooks));
  EXPECT_EQ(seen, (std::vector<std::string>{"window-only", "select face 1"}));
  ASSERT_TRUE(s.selection);
  const auto error = run_script(s, {"window-only", "select face 99", "select none"}, hooks);
  ASSERT_TRUE(error);
  EXPECT_EQ(error->line, 2);
  EXPECT_TRUE(s.selection);  // the line after the error did not run
  bool quit = false;
  EXPECT_FALSE(run_script(s, {"quit", "select none"}, hooks, &quit));
  EXPECT_TRUE(quit);
  EXPECT_TRUE(s.selection);
}

TEST(ModelerSession, FramingFitsANarrowViewport) {
  // A viewport half as wide as high: the horizontal angle is the narrower one, so the model's
  // sphere must fit in it (tolerance 1e-9 on exact trigonometry).
  Session s(make_cube());
  s.viewport_width = 0.5;
  ASSERT_FALSE(run_script(s, {"frame all"}, {}));
  const double half_y = s.view.fov_y_deg * M_PI / 360.0;
  const double half_x = std::atan(std::tan(half_y) * 0.5);
  EXPECT_GE(s.view.distance * std::sin(half_x) + 1e-9, s.mesh_bounds().radius());
  const double narrow = s.view.distance;
  s.viewport_width = 2.0;  // wide: framed by the vertical angle, nearer
  ASSERT_FALSE(run_script(s, {"frame all"}, {}));
  EXPECT_LT(s.view.distance, narrow);
  EXPECT_GE(s.view.distance * std::sin(half_y) + 1e-9, s.mesh_bounds().radius());
  // Split, each half of the 1 x 1 viewport is 0.5 wide: framed as the narrow viewport was
  // (the same computation: exactly equal).
  s.viewport_width = 1.0;
  ASSERT_FALSE(run_script(s, {"split asc", "frame all"}, {}));
  EXPECT_EQ(s.view.distance, narrow);
}

}  // namespace
}  // namespace stitch::modeler

namespace stitch::modeler {
namespace {

TEST(ModelerSession, OpeningAMeshSaysWhatReadingRepaired) {
  // OpenSubdiv's fan: three faces on one edge; reading splits the edge (repair.hpp) and the
  // modeler says so on load, as the command line warns.
  Session s;
  const std::string path = test::opensubdiv_shape("catmark_fan.obj");
  const std::string message = open_file(s, path);
  EXPECT_EQ(message.rfind("opened " + path, 0), 0u) << message;
  EXPECT_NE(message.find("; repaired: "), std::string::npos) << message;
  EXPECT_NE(message.find("non-manifold edge"), std::string::npos) << message;
  // A clean mesh opens with nothing to say.
  EXPECT_EQ(open_file(s, test::example_path("cube.obj")),
            "opened " + test::example_path("cube.obj"));
}

/// The live surface's samples equal those build_surface's surface gives for the same request,
/// block for block (exact: the same refinement and K-gons, the same evaluation).
void expect_live_surface_is_built_surface(const Session& s) {
  const HalfedgeMesh& input = s.document.mesh();
  const BuiltSurface built =
      build_surface(input, {s.display.method, s.document.kgon_options(), false});
  const HalfedgeMesh& mesh = built.mesh(input);
  ASSERT_EQ(s.surface.num_patches(), static_cast<int>(mesh.patch_corners().size()));
  ASSERT_EQ(s.surface.corners(), mesh.patch_corners());
  TessellationOptions t;
  t.resolution = s.surface.resolution();
  t.welded = false;
  const TessellatedMesh expected = tessellate(mesh, built.surface, t);
  const int per = s.surface.vertices_per_patch();
  const std::vector<Corner> corners = s.surface.corners();
  for (size_t k = 0; k < corners.size(); ++k)
    for (int i = 0; i < per; ++i)
      ASSERT_EQ(s.surface.tessellation().positions[corners[k].idx * per + i],
                expected.positions[static_cast<int>(k) * per + i])
          << "patch " << corners[k].idx << " sample " << i;
}

TEST(ModelerSession, OpeningSemiSharpTagsHonoursThemAsStitchSmoothDoes) {
  Session s;
  const std::string message = open_file(s, test::opensubdiv_shape("catmark_cube_creases0.obj"));
  EXPECT_NE(message.find("2 levels of uniform refinement: 96 faces, 384 patches"),
            std::string::npos)
      << message;
  EXPECT_EQ(s.surface.num_patches(), 384);
  expect_live_surface_is_built_surface(s);
  // A move refines the points again: still build_surface's surface.
  ASSERT_FALSE(run_script(s, {"translate-vertex 1 0.1 0.2 0.3"}, {}));
  EXPECT_FALSE(s.last_update.layout_changed);
  expect_live_surface_is_built_surface(s);
}

TEST(ModelerSession, SharpnessSetsTheSelectedEdgesCreaseLiveAndIsSaved) {
  stitch::testing::TempFolder dir;
  Session s(make_cube());
  ASSERT_EQ(s.surface.num_patches(), 24);
  // Refused without an edge or a vertex selected, and for a sharpness that is not a number.
  EXPECT_TRUE(run_script(s, {"sharpness 2"}, {}));
  EXPECT_TRUE(run_script(s, {"select edge 1 2", "sharpness two"}, {}));
  const Edge e = HalfedgeMesh::edge(Halfedge(s.selection->index));
  // Semi-sharp: refined 2 levels, 16 patches per corner, the edge still selected for the next.
  ASSERT_FALSE(run_script(s, {"sharpness 1.5"}, {}));
  EXPECT_EQ(s.document.mesh().sharpness(e), 1.5);
  EXPECT_EQ(s.surface.refinement().levels, 2);
  EXPECT_EQ(s.surface.num_patches(), 24 * 16);
  expect_live_surface_is_built_surface(s);
  ASSERT_TRUE(s.selection);
  ASSERT_FALSE(run_script(s, {"sharpness 3.5"}, {}));
  EXPECT_EQ(s.surface.refinement().levels, 4);
  expect_live_surface_is_built_surface(s);
  // Infinitely sharp, and smooth: one patch per corner again.
  ASSERT_FALSE(run_script(s, {"sharpness 10"}, {}));
  EXPECT_EQ(s.surface.num_patches(), 24);
  EXPECT_TRUE(s.document.mesh().is_sharp(e));
  ASSERT_FALSE(run_script(s, {"sharpness 0", "undo"}, {}));
  EXPECT_EQ(s.document.mesh().sharpness(e), 10.0);
  // Kept in the project, and in an OBJ file's crease tag.
  ASSERT_FALSE(
      run_script(s, {"undo", "save " + dir.file("p.stitch"), "save " + dir.file("p.obj")}, {}));
  const auto tagged = [](const HalfedgeMesh& m) {
    int n = 0;
    for (Edge x : m.edges()) n += m.sharpness(x) == 3.5 ? 1 : 0;
    return n;
  };
  Session t;
  ASSERT_FALSE(run_script(t, {"open " + dir.file("p.stitch")}, {}));
  EXPECT_EQ(tagged(t.document.mesh()), 1);
  EXPECT_EQ(t.surface.num_patches(), 24 * 256);
  EXPECT_EQ(tagged(read_mesh(dir.file("p.obj"))), 1);
}

// A slider's drag is one undo step: `sharpness S drag` extends the last step when that set the
// same element's sharpness, and makes a step of its own otherwise.
TEST(ModelerSession, SharpnessDragIsOneUndoStep) {
  Session s(make_cube());
  ASSERT_FALSE(run_script(s, {"select edge 1 2", "sharpness 0.5"}, {}));
  const Edge e = HalfedgeMesh::edge(Halfedge(s.selection->index));
  const size_t steps = s.document.undo_labels().size();
  ASSERT_FALSE(run_script(s, {"sharpness 1 drag", "sharpness 2.5 drag"}, {}));
  EXPECT_EQ(s.document.undo_labels().size(), steps);
  EXPECT_EQ(s.document.mesh().sharpness(e), 2.5);
  expect_live_surface_is_built_surface(s);
  EXPECT_TRUE(run_script(s, {"sharpness 2 dragged"}, {}));
  // Another element's drag is a step of its own, and so is a drag after an undo.
  ASSERT_FALSE(run_script(s, {"select vertex 1", "sharpness 3 drag"}, {}));
  EXPECT_EQ(s.document.undo_labels().size(), steps + 1);
  ASSERT_FALSE(run_script(s, {"undo", "select edge 1 2", "sharpness 4 drag"}, {}));
  EXPECT_EQ(s.document.undo_labels().size(), steps + 1);
  // One undo takes the drag back to where it started, one redo to where it ended.
  ASSERT_FALSE(run_script(s, {"undo"}, {}));
  EXPECT_EQ(s.document.mesh().sharpness(e), 2.5);
  ASSERT_FALSE(run_script(s, {"undo"}, {}));
  EXPECT_EQ(s.document.mesh().sharpness(e), 0.0);
  ASSERT_FALSE(run_script(s, {"redo"}, {}));
  EXPECT_EQ(s.document.mesh().sharpness(e), 2.5);
  expect_live_surface_is_built_surface(s);
}

}  // namespace
}  // namespace stitch::modeler
