// After a topology edit that makes a tube whose surface folds, the session chooses K-gon controls
// for it (include/stitch/analysis/unfold_tubes.hpp) as part of the edit's undo step; a document
// opened with such a tube shows the surface build_surface builds for it.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "cli_run.hpp"
#include "incremental_check.hpp"
#include "printed_lines.hpp"
#include "stitch/analysis/build_surface.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/modeler/session.hpp"
#include "stitch/topology/primitives.hpp"
#include "temp_folder.hpp"

namespace stitch::modeler {
namespace {

// Prism 30's straight tube: the fitted placement of the merged face's K-gons folds at resolution
// 16 (the grid's folds: clean at 32; prism 16's half twist, used before, is clean with its
// fitted K-gons since quads are split along their shorter diagonal, but its axis is blocked).
constexpr const char* kTube = "insert-edge 1@1 31@2";
constexpr int kPrism = 30;

bool has_controls(const KgonOptions& k) {
  return !k.face.empty() || !k.vertex.empty() || !k.edge.empty();
}

/// The problem patches of the whole surface with the document's controls, from the library's
/// check of every patch.
std::vector<Corner> whole_surface_problems(const Session& s) {
  const HalfedgeMesh& mesh = s.document.mesh();
  return check_patches(mesh, Surface(mesh, Method::mdc, s.document.kgon_options()),
                       mesh.patch_corners())
      .problem_corners;
}

/// Prism 30 with the folding tube, saved as a mesh file (which has no K-gon controls).
std::string folding_tube_file(const stitch::testing::TempFolder& dir) {
  Document doc(make_prism(kPrism));
  doc.apply_operation(kTube);
  const std::string path = dir.file("tube.obj");
  write_mesh(path, doc.mesh());
  return path;
}

/// The mesh file as the modeler reads it.
HalfedgeMesh read_as_modeler(const std::string& path) {
  BuildOptions build;
  build.allow_two_gons = true;
  return read_mesh(path, build);
}

/// The session's live tessellation is tessellate() of `surface` (one grid per patch), bit for bit.
void expect_shows(const Session& s, const HalfedgeMesh& mesh, const Surface& surface) {
  TessellationOptions t;
  t.resolution = s.surface.resolution();
  t.welded = false;
  const TessellatedMesh expected = tessellate(mesh, surface, t);
  const TessellatedMesh& got = s.surface.tessellation();
  const int per = s.surface.vertices_per_patch();
  const auto corners = mesh.patch_corners();
  ASSERT_EQ(expected.num_vertices(), static_cast<int>(corners.size()) * per);
  int mismatches = 0;
  for (size_t k = 0; k < corners.size(); ++k)
    for (int i = 0; i < per; ++i) {
      const size_t a = k * per + i, b = static_cast<size_t>(corners[k].idx) * per + i;
      mismatches +=
          got.positions[b] == expected.positions[a] && got.normals[b] == expected.normals[a] ? 0
                                                                                             : 1;
    }
  EXPECT_EQ(mismatches, 0);
}

TEST(TubeUnfolding, AnOpenedDocumentShowsTheSurfaceOfTheRequest) {
  stitch::testing::TempFolder dir;
  const std::string path = folding_tube_file(dir);
  const HalfedgeMesh mesh = read_as_modeler(path);
  // mdc, whose search cleans this tube, and cc, which searches nothing (under asc no setting
  // cleans it: the search runs to its end, about 100 s on the 2-core VM).
  for (const Method method : {Method::mdc, Method::cc}) {
    const Choice<Method>& m = choice_of(method_table(), method);
    SCOPED_TRACE(std::string(m.name));
    Session s(make_cube());  // cc refuses an empty mesh
    ASSERT_FALSE(run_script(s, {fmt::format("method {}", m.name), "resolution 5"}, {}));
    Printed printed;
    const ScriptResult r = run_script_line(s, "open " + path, printed.hooks());
    ASSERT_TRUE(s.document.mesh() == mesh);
    const BuiltSurface built = build_surface(mesh, {m.value, {}, true});
    expect_shows(s, mesh, built.surface);
    // The chosen controls are the document's: what is shown, and what a project saves.
    EXPECT_EQ(s.document.kgon_options().face, built.kgons.face);
    EXPECT_EQ(s.document.kgon_options().edge, built.kgons.edge);
    EXPECT_FALSE(s.document.modified());  // the file gives the same document again
    EXPECT_FALSE(s.document.can_undo());
    EXPECT_EQ(s.tube_unfoldings().size(), built.tubes.size());
    if (m.value != Method::mdc) continue;
    ASSERT_EQ(s.tube_unfoldings().size(), 1u);
    EXPECT_GT(s.tube_unfoldings()[0].fitted.folds, 0);
    EXPECT_TRUE(s.tube_unfoldings()[0].unfolded());
    EXPECT_FALSE(s.document.kgon_options().face.empty());
    // Said as an edit's unfoldings are: in the line's message and printed.
    const std::string said = describe_unfoldings(mesh, s.tube_unfoldings());
    EXPECT_EQ(r.message, "opened " + path + "; " + said);
    EXPECT_EQ(printed.lines, std::vector<std::string>{said});
    ASSERT_FALSE(run_script(s, {"check"}, {}));
    EXPECT_TRUE(s.surface_problems().empty()) << s.surface_problems().summary();
  }
}

TEST(TubeUnfolding, OpenedWithTheSearchTurnedOffTheFittedKgonsStay) {
  stitch::testing::TempFolder dir;
  const std::string path = folding_tube_file(dir);
  const HalfedgeMesh mesh = read_as_modeler(path);
  Session s;
  const auto error = run_script(s, {"unfold-tubes off", "open " + path, "check"}, {});
  ASSERT_FALSE(error) << error->message;
  EXPECT_TRUE(s.tube_unfoldings().empty());
  EXPECT_TRUE(s.document.kgon_options().face.empty());
  EXPECT_GT(s.surface_problems().folds, 0);
  expect_shows(s, mesh, build_surface(mesh, {Method::mdc, {}, false}).surface);
}

TEST(TubeUnfolding, TheOpenedSurfaceIsTheOneStitchSmoothWrites) {
  stitch::testing::TempFolder dir;
  const std::string path = folding_tube_file(dir);
  Session s;
  ASSERT_FALSE(run_script(s,
                          {"resolution 5", "open " + path, "export " + dir.file("modeler.ply"),
                           "save " + dir.file("tube.stitch")},
                          {}));
  ASSERT_EQ(s.tube_unfoldings().size(), 1u);
  const auto smooth = stitch::testing::stitch_cli(dir, "smooth tube.obj -o cli.ply --resolution 5");
  ASSERT_EQ(smooth.status, 0) << smooth.err;
  EXPECT_NE(smooth.err.find("the tube of face 1"), std::string::npos) << smooth.err;
  EXPECT_EQ(stitch::testing::read_file(dir.file("cli.ply")),
            stitch::testing::read_file(dir.file("modeler.ply")));
  // The project keeps the controls shown: opened again, nothing is searched, the same surface.
  Session again;
  ASSERT_FALSE(run_script(again, {"open " + dir.file("tube.stitch")}, {}));
  EXPECT_TRUE(again.tube_unfoldings().empty());
  EXPECT_EQ(again.document.kgon_options().face, s.document.kgon_options().face);
  EXPECT_EQ(again.document.kgon_options().edge, s.document.kgon_options().edge);
  ASSERT_FALSE(run_script(again, {"export " + dir.file("project.ply")}, {}));
  EXPECT_EQ(stitch::testing::read_file(dir.file("project.ply")),
            stitch::testing::read_file(dir.file("modeler.ply")));
}

TEST(TubeUnfolding, TheTwistedTubeIsUnfoldedInTheEditsUndoStep) {
  Session s(make_prism(kPrism));
  const HalfedgeMesh prism = s.document.mesh();
  Printed printed;
  const ScriptResult r = run_script_line(s, kTube, printed.hooks());
  RecordProperty("unfold_ms", std::to_string(s.unfold_milliseconds()));

  EXPECT_TRUE(s.surface_problems().empty()) << s.surface_problems().summary();
  EXPECT_GT(s.surface_problems().checked_patches, 0);  // checked on the unfolded surface
  EXPECT_TRUE(whole_surface_problems(s).empty());
  // The live surface is the one built from scratch with the controls.
  test::expect_same_as_rebuild(s.surface, s.document.mesh(), s.document.kgon_options());

  ASSERT_EQ(s.tube_unfoldings().size(), 1u);
  const TubeUnfolding& u = s.tube_unfoldings()[0];
  EXPECT_EQ(u.face, Face(0));  // faces 1 and 2 merged into face 1
  EXPECT_GT(u.fitted.folds, 0);
  EXPECT_TRUE(u.unfolded());
  const KgonOptions& k = s.document.kgon_options();
  ASSERT_TRUE(k.face.contains(0));
  EXPECT_EQ(k.face.at(0), u.face_control);
  ASSERT_TRUE(k.edge.contains(u.bridge.idx));
  EXPECT_EQ(k.edge.at(u.bridge.idx), u.bridge_control);
  EXPECT_EQ(s.document.kgon_control({KgonKind::face, 0}), u.face_control);

  // "the tube of face 1 (bridge 1 31) folds with its fitted K-gons (4 folded and 0 crossing
  // pairs of triangles at resolution 16); chosen instead: face K-gon scale 1.2 rotate 0,
  // bridge K-gon scale 1 (clean)" when written; the setting is the library's to choose.
  const std::string said = describe_unfoldings(s.document.mesh(), s.tube_unfoldings());
  EXPECT_EQ(said.rfind(fmt::format("the tube of face 1 (bridge 1 31) folds with its fitted K-gons "
                                   "({} folded and 0 crossing pairs of triangles at resolution "
                                   "16); chosen instead: face K-gon scale ",
                                   u.fitted.folds),
                       0),
            0u)
      << said;
  EXPECT_TRUE(said.ends_with(" (clean)")) << said;
  EXPECT_NE(r.message.find("; " + said), std::string::npos) << r.message;
  ASSERT_EQ(printed.lines.size(), 2u);  // the edit, then the unfolding (no warning)
  EXPECT_EQ(printed.lines[1], said);

  // One step holds the edit and the controls.
  EXPECT_EQ(s.document.undo_labels(), std::vector<std::string>{kTube});
  ASSERT_FALSE(run_script(s, {"undo"}, {}));
  EXPECT_TRUE(s.document.mesh() == prism);
  EXPECT_FALSE(has_controls(s.document.kgon_options()));
  EXPECT_FALSE(s.document.can_undo());
  EXPECT_TRUE(s.surface_problems().empty());
  // Redo brings both back as they were, without searching again.
  ASSERT_FALSE(run_script(s, {"redo"}, {}));
  EXPECT_EQ(s.document.kgon_options().face.at(0), u.face_control);
  EXPECT_TRUE(s.tube_unfoldings().empty());
  EXPECT_TRUE(s.surface_problems().empty());
  test::expect_same_as_rebuild(s.surface, s.document.mesh(), s.document.kgon_options());
}

TEST(TubeUnfolding, TurnedOffTheFoldsStay) {
  Session s(make_prism(kPrism));
  Printed printed;
  EXPECT_EQ(run_script_line(s, "unfold-tubes off", {}).message, "unfolding of folding tubes off");
  EXPECT_FALSE(s.unfold_folding_tubes);
  run_script_line(s, kTube, printed.hooks());
  EXPECT_FALSE(s.surface_problems().empty());
  EXPECT_GT(s.surface_problems().folds, 0);
  EXPECT_TRUE(s.tube_unfoldings().empty());
  EXPECT_FALSE(has_controls(s.document.kgon_options()));
  ASSERT_EQ(printed.lines.size(), 2u);
  EXPECT_EQ(printed.lines[1].rfind("warning: surface folds at ", 0), 0u) << printed.lines[1];

  EXPECT_TRUE(run_script(s, {"unfold-tubes maybe"}, {}));
  EXPECT_TRUE(run_script(s, {"unfold-tubes"}, {}));
  ASSERT_FALSE(run_script(s, {"unfold-tubes on"}, {}));
  EXPECT_TRUE(s.unfold_folding_tubes);
}

TEST(TubeUnfolding, AnAppendedTubeIsUnfoldedUnlessItHasControls) {
  stitch::testing::TempFolder dir;
  Session twisted(make_prism(kPrism));
  ASSERT_FALSE(run_script(
      twisted, {kTube, "save " + dir.file("tube.stitch"), "save " + dir.file("tube.obj")}, {}));
  Session s(make_cube());
  // The project brings its tube's controls, which are the user's to keep: no search.
  ASSERT_FALSE(run_script(s, {"append " + dir.file("tube.stitch") + " --offset 5,0,0"}, {}));
  EXPECT_TRUE(s.tube_unfoldings().empty());
  EXPECT_TRUE(s.surface_problems().empty());
  const KgonOptions with_project = s.document.kgon_options();
  EXPECT_EQ(with_project.face.size(), 1u);
  // The mesh file has no controls: its tube folds and is unfolded, in the append's step.
  const ScriptResult r =
      run_script_line(s, "append " + dir.file("tube.obj") + " --offset -5,0,0", {});
  ASSERT_EQ(s.tube_unfoldings().size(), 1u);
  EXPECT_TRUE(s.tube_unfoldings()[0].unfolded());
  EXPECT_NE(r.message.find("; the tube of face "), std::string::npos) << r.message;
  EXPECT_TRUE(s.surface_problems().empty());
  EXPECT_EQ(s.document.kgon_options().face.size(), 2u);
  ASSERT_FALSE(run_script(s, {"undo"}, {}));
  EXPECT_EQ(s.document.kgon_options().face, with_project.face);
  EXPECT_EQ(s.document.kgon_options().edge, with_project.edge);
}

TEST(TubeUnfolding, NotForCatmullClark) {
  // cc does not use the K-gons: nothing to judge a setting by.
  Session s(make_prism(kPrism));
  ASSERT_FALSE(run_script(s, {"method cc", kTube}, {}));
  EXPECT_TRUE(s.tube_unfoldings().empty());
  EXPECT_FALSE(has_controls(s.document.kgon_options()));
}

TEST(TubeUnfolding, ACleanTubeGetsNoControls) {
  Session s(make_cube());
  const ScriptResult r = run_script_line(s, "insert-edge 1@1 5@2", {});
  EXPECT_TRUE(s.surface_problems().empty());
  EXPECT_TRUE(s.tube_unfoldings().empty());
  EXPECT_FALSE(has_controls(s.document.kgon_options()));
  EXPECT_EQ(r.message.find("tube"), std::string::npos) << r.message;
}

TEST(TubeUnfolding, TheRendererGetsTheBlocksOfBothUpdates) {
  // The unfolded edit updates the surface twice (the edit, then the controls' K-gons); the
  // blocks to upload again include what the first update changed.
  Session off(make_prism(kPrism)), on(make_prism(kPrism));
  ASSERT_FALSE(run_script(off, {"unfold-tubes off", kTube}, {}));
  ASSERT_FALSE(run_script(on, {kTube}, {}));
  ASSERT_FALSE(on.tube_unfoldings().empty());
  std::vector<int> edit = off.changed_blocks(), both = on.changed_blocks();
  std::sort(edit.begin(), edit.end());
  std::sort(both.begin(), both.end());
  EXPECT_TRUE(std::includes(both.begin(), both.end(), edit.begin(), edit.end()));
  EXPECT_FALSE(on.last_update.full);
  EXPECT_TRUE(on.last_update.layout_changed);
  EXPECT_GE(on.last_update.recomputed_patches, off.last_update.recomputed_patches);
}

TEST(TubeUnfolding, ControlsJoinOnlyATopologyEditJustMade) {
  Document doc(make_prism(kPrism));
  const std::vector<std::pair<KgonTarget, KgonControl>> controls{
      {{KgonKind::face, 0}, KgonControl{.scale = 1.2}}};
  EXPECT_THROW(doc.set_kgon_controls_in_last_edit(controls), Error);  // no step yet
  doc.apply_operation(kTube);
  EXPECT_THROW(doc.set_kgon_controls_in_last_edit({{KgonTarget{}, KgonControl{}}}), Error);
  EXPECT_THROW(doc.set_kgon_controls_in_last_edit({{{KgonKind::face, 1}, KgonControl{}}}),
               Error);  // face 2 was merged away
  EXPECT_FALSE(has_controls(doc.kgon_options()));
  const Change c = doc.set_kgon_controls_in_last_edit(controls);
  EXPECT_EQ(c.kind, Change::Kind::kgons);
  EXPECT_EQ(c.faces, std::vector<Face>{Face(0)});
  EXPECT_EQ(doc.undo_labels().size(), 1u);
  doc.undo();
  EXPECT_FALSE(has_controls(doc.kgon_options()));
  EXPECT_THROW(doc.set_kgon_controls_in_last_edit(controls), Error);  // undone
  doc.redo();
  EXPECT_EQ(doc.kgon_control({KgonKind::face, 0}).scale, 1.2);
  doc.move_vertices({Vertex(0)}, {Vec3(0, 0, 0)});
  EXPECT_THROW(doc.set_kgon_controls_in_last_edit(controls), Error);  // not a topology edit
}

}  // namespace
}  // namespace stitch::modeler
