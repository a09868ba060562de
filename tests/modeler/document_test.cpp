// The document's commands: every change undoes to the exact earlier mesh and redoes exactly.
#include "stitch/modeler/document.hpp"

#include <gtest/gtest.h>

#include "stitch/mesh/validate.hpp"
#include "stitch/topology/primitives.hpp"

namespace stitch::modeler {
namespace {

TEST(ModelerDocument, TopologyEditUndoesAndRedoesExactly) {
  Document doc(make_cube());
  const HalfedgeMesh before = doc.mesh();
  const Change c = doc.apply_operation("insert-edge 1@1 5@2");
  EXPECT_EQ(c.kind, Change::Kind::topology);
  const HalfedgeMesh after = doc.mesh();
  EXPECT_EQ(topology_stats(after).genus, 1);
  EXPECT_TRUE(doc.modified());
  doc.undo();
  EXPECT_TRUE(doc.mesh() == before);  // operator==: numbering and positions exactly
  EXPECT_FALSE(doc.modified());
  doc.redo();
  EXPECT_TRUE(doc.mesh() == after);
  EXPECT_THROW(doc.redo(), Error);
}

TEST(ModelerDocument, RefusedOperationChangesNothingAndRecordsNothing) {
  Document doc(make_cube());
  const HalfedgeMesh before = doc.mesh();
  EXPECT_THROW(doc.apply_operation("insert-edge 1@1 1@3"), Error);  // a loop edge
  EXPECT_THROW(doc.apply_operation("no-such-op 1"), Error);
  EXPECT_TRUE(doc.mesh() == before);
  EXPECT_FALSE(doc.can_undo());
  EXPECT_TRUE(doc.apply_operation("  # only a comment").empty());
  EXPECT_FALSE(doc.can_undo());
}

TEST(ModelerDocument, LongHistoryUndoesToTheStart) {
  Document doc(make_cube());
  std::vector<HalfedgeMesh> states{doc.mesh()};
  doc.apply_operation("subdivide-edge 1 2");
  states.push_back(doc.mesh());
  doc.move_vertices({Vertex(8)}, {Vec3(0.1, -1.5, -1.0)});
  states.push_back(doc.mesh());
  doc.apply_operation("extrude-face 2 0.5");
  states.push_back(doc.mesh());
  doc.apply_operation("catmull-clark");
  states.push_back(doc.mesh());
  for (int i = static_cast<int>(states.size()) - 2; i >= 0; --i) {
    doc.undo();
    EXPECT_TRUE(doc.mesh() == states[i]) << "after undoing to state " << i;
  }
  EXPECT_FALSE(doc.can_undo());
  for (size_t i = 1; i < states.size(); ++i) {
    doc.redo();
    EXPECT_TRUE(doc.mesh() == states[i]) << "after redoing to state " << i;
  }
}

TEST(ModelerDocument, MergedMovesAreOneUndoStep) {
  Document doc(make_cube());
  const Vec3 start = doc.mesh().position(Vertex(0));
  doc.move_vertices({Vertex(0)}, {Vec3(-1.1, -1, -1)});
  doc.move_vertices({Vertex(0)}, {Vec3(-1.2, -1, -1)}, true);
  doc.move_vertices({Vertex(0)}, {Vec3(-1.3, -1, -1)}, true);
  EXPECT_EQ(doc.undo_labels().size(), 1u);
  EXPECT_EQ(doc.mesh().position(Vertex(0)), Vec3(-1.3, -1, -1));
  const Change c = doc.undo();
  EXPECT_EQ(c.kind, Change::Kind::geometry);
  ASSERT_EQ(c.moved.size(), 1u);
  EXPECT_EQ(doc.mesh().position(Vertex(0)), start);
  EXPECT_THROW(doc.move_vertices({Vertex(99)}, {Vec3::Zero()}), Error);
  EXPECT_THROW(doc.move_vertices({Vertex(0)}, {Vec3(NAN, 0, 0)}), Error);
}

TEST(ModelerDocument, KgonControlsUndoAndArePrunedWithTheirElements) {
  Document doc(make_cube());
  KgonControl c;
  c.scale = 0.5;
  doc.set_kgon_control({KgonKind::face, 1}, c);
  doc.set_kgon_control({KgonKind::vertex, 4}, c);
  EXPECT_EQ(doc.kgon_control({KgonKind::face, 1}).scale, 0.5);
  EXPECT_THROW(doc.set_kgon_control({KgonKind::edge, 99}, c), Error);
  // Merging face 2 (index 1) into face 1 removes face 2: its control goes, vertex 5's stays.
  doc.apply_operation("insert-edge 1@1 5@2");
  EXPECT_EQ(doc.kgon_options().face.count(1), 0u);
  EXPECT_EQ(doc.kgon_options().vertex.count(4), 1u);
  doc.undo();
  EXPECT_EQ(doc.kgon_options().face.count(1), 1u);
  doc.undo();
  doc.undo();
  EXPECT_TRUE(doc.kgon_options().face.empty());
  EXPECT_TRUE(doc.kgon_options().vertex.empty());
  // Remeshing renumbers everything, so per-element controls are dropped.
  doc.set_kgon_control({KgonKind::face, 0}, c);
  doc.apply_operation("dual");
  EXPECT_TRUE(doc.kgon_options().face.empty());
}

}  // namespace
}  // namespace stitch::modeler
