// A second mesh appended to the document, joined to the first by one inserted edge (the paper's
// join) and separated again by deleting it (its separate), all undoable.
#include <gtest/gtest.h>

#include "stitch/mesh/io.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/modeler/session.hpp"
#include "stitch/tess/tessellate.hpp"
#include "stitch/topology/compare.hpp"
#include "stitch/topology/primitives.hpp"
#include "temp_folder.hpp"
#include "test_support.hpp"

namespace stitch::modeler {
namespace {

/// The live surface's blocks are those a from-scratch tessellation gives.
void expect_surface_rebuilt_exactly(const Session& s) {
  const HalfedgeMesh& mesh = s.document.mesh();
  const Surface fresh(mesh, s.surface.method(), s.document.kgon_options());
  TessellationOptions t;
  t.resolution = s.surface.resolution();
  t.welded = false;
  const TessellatedMesh expected = tessellate(mesh, fresh, t);
  const int per = s.surface.vertices_per_patch();
  const auto corners = mesh.patch_corners();
  ASSERT_EQ(expected.num_vertices(), static_cast<int>(corners.size()) * per);
  int mismatches = 0;
  for (size_t k = 0; k < corners.size(); ++k)
    for (int i = 0; i < per; ++i)
      mismatches += s.surface.tessellation().positions[corners[k].idx * per + i] ==
                            expected.positions[k * per + i]
                        ? 0
                        : 1;
  EXPECT_EQ(mismatches, 0);
}

TEST(ModelerAppend, JoinsTwoCubesByAnEdgeSeparatesThemAndUndoesBack) {
  stitch::testing::TempFolder dir;
  write_mesh(dir.file("cube.obj"), make_cube());
  Session s(make_cube());
  s.rebuild();

  // The second cube 4 to the right: vertices 9-16, faces 7-12 (face 12 its left side, x = 3).
  auto r = run_script_line(s, "append " + dir.file("cube.obj") + " --offset 4,0,0", {});
  EXPECT_NE(r.message.find("vertices 9 to 16, faces 7 to 12"), std::string::npos) << r.message;
  const HalfedgeMesh apart = s.document.mesh();
  EXPECT_EQ(topology_stats(apart).components, 2);
  EXPECT_EQ(apart.position(Vertex(8)), Vec3(3, -1, -1));
  // Only the new cube's 24 patches were evaluated; the first cube's stayed as they were.
  EXPECT_EQ(s.surface.recomputed().size(), 24u);
  expect_surface_rebuilt_exactly(s);

  // Join: an edge from corner 2@4 (the first cube's right side) to 9@12 merges the two facing
  // sides into one 10-sided face; that is examples/two_cubes.obj.
  ASSERT_FALSE(run_script(s, {"insert-edge 2@4 9@12"}, {}));
  const HalfedgeMesh joined = s.document.mesh();
  const TopologyStats t = topology_stats(joined);
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.genus, 0);
  EXPECT_EQ(t.degree_histogram.at(10), 1);
  EXPECT_TRUE(same_up_to_renumbering(
      joined, read_mesh(test::example_path("two_cubes.obj"), {false, true})));
  expect_surface_rebuilt_exactly(s);

  // Separate: deleting that edge splits the face again into the two cubes.
  ASSERT_FALSE(run_script(s, {"delete-edge 2 9"}, {}));
  EXPECT_EQ(topology_stats(s.document.mesh()).components, 2);
  EXPECT_TRUE(same_up_to_renumbering(s.document.mesh(), apart));
  expect_surface_rebuilt_exactly(s);

  // Each step undoes exactly; the append is one step.
  ASSERT_FALSE(run_script(s, {"undo"}, {}));
  EXPECT_TRUE(s.document.mesh() == joined);
  ASSERT_FALSE(run_script(s, {"undo"}, {}));
  EXPECT_TRUE(s.document.mesh() == apart);
  ASSERT_FALSE(run_script(s, {"undo"}, {}));
  EXPECT_TRUE(s.document.mesh() == make_cube());
  EXPECT_FALSE(s.document.can_undo());
  expect_surface_rebuilt_exactly(s);
  ASSERT_FALSE(run_script(s, {"redo", "redo"}, {}));
  EXPECT_TRUE(s.document.mesh() == joined);
  expect_surface_rebuilt_exactly(s);
}

TEST(ModelerAppend, BringsAProjectsControlsRenumbered) {
  stitch::testing::TempFolder dir;
  Session first(make_cube());
  ASSERT_FALSE(run_script(first,
                          {"select face 2", "kgon scale 0.5", "select vertex 3", "kgon rotate 30",
                           "save " + dir.file("shaped.stitch")},
                          {}));
  Session s(make_torus(4, 3));  // 12 vertices, 12 faces
  ASSERT_FALSE(run_script(s, {"append " + dir.file("shaped.stitch") + " --offset 0,0,5"}, {}));
  const KgonOptions& k = s.document.kgon_options();
  ASSERT_EQ(k.face.size(), 1u);
  EXPECT_EQ(k.face.begin()->first, 12 + 1);  // face 2 of the cube is face 14 now (0-based 13)
  EXPECT_EQ(k.face.begin()->second.scale, 0.5);
  ASSERT_EQ(k.vertex.size(), 1u);
  EXPECT_EQ(k.vertex.begin()->first, 12 + 2);
  EXPECT_EQ(s.document.mesh().position(Vertex(14)), Vec3(1, 1, 4));
  expect_surface_rebuilt_exactly(s);
  ASSERT_FALSE(run_script(s, {"undo"}, {}));
  EXPECT_TRUE(s.document.kgon_options().face.empty());
  EXPECT_TRUE(s.document.mesh() == make_torus(4, 3));
}

TEST(ModelerAppend, RefusesBadLinesAndChangesNothing) {
  stitch::testing::TempFolder dir;
  write_mesh(dir.file("my cube.obj"), make_cube());
  Session s(make_cube());
  for (const std::string& line : {std::string("append"), "append " + dir.file("missing.obj"),
                                  "append " + dir.file("my cube.obj") + " --offset",
                                  "append " + dir.file("my cube.obj") + " --offset 1,2",
                                  "append " + dir.file("my cube.obj") + " --offset 1,x,2",
                                  "append " + dir.file("my cube.obj") + " --offset 1e300,0,0"}) {
    SCOPED_TRACE(line);
    EXPECT_TRUE(run_script(s, {line}, {}));
    EXPECT_TRUE(s.document.mesh() == make_cube());
    EXPECT_FALSE(s.document.can_undo());
  }
  // A path with blanks, and no offset.
  ASSERT_FALSE(run_script(s, {"append " + dir.file("my cube.obj")}, {}));
  EXPECT_EQ(s.document.mesh().num_vertices(), 16);
}

TEST(ModelerSave, WarnsThatAMeshFileDropsKgonControls) {
  stitch::testing::TempFolder dir;
  Session s(make_cube());
  auto r = run_script_line(s, "save " + dir.file("plain.obj"), {});
  EXPECT_EQ(r.message.find("K-gon"), std::string::npos) << r.message;
  EXPECT_FALSE(s.document.modified());
  ASSERT_FALSE(run_script(s, {"select face 1", "kgon scale 0.5"}, {}));
  std::vector<std::string> printed;
  ScriptHooks hooks;
  hooks.print = [&](const std::string& t) { printed.push_back(t); };
  r = run_script_line(s, "save " + dir.file("shaped.obj"), hooks);
  EXPECT_NE(r.message.find("K-gon controls are not stored in .obj; save as .stitch to keep them"),
            std::string::npos)
      << r.message;
  ASSERT_EQ(printed.size(), 1u);
  EXPECT_EQ(printed[0].rfind("warning: ", 0), 0u) << printed[0];
  // The controls live only in the document now: it stays modified (and so autosaved).
  EXPECT_TRUE(s.document.modified());
  r = run_script_line(s, "save " + dir.file("shaped.stitch"), {});
  EXPECT_EQ(r.message.find("K-gon"), std::string::npos) << r.message;
  EXPECT_FALSE(s.document.modified());
}

}  // namespace
}  // namespace stitch::modeler
