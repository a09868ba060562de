// The mesh's journal: what a sequence of edits touched, undone and redone exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "random_operation.hpp"
#include "stitch/topology/operation.hpp"
#include "stitch/topology/primitives.hpp"

namespace stitch {
namespace {

bool same_vertex(const HalfedgeMesh& a, const HalfedgeMesh& b, Vertex v) {
  return a.position(v) == b.position(v) && a.halfedge(v) == b.halfedge(v) &&
         a.is_deleted(v) == b.is_deleted(v);
}

bool same_edge(const HalfedgeMesh& a, const HalfedgeMesh& b, Edge e) {
  for (int side = 0; side < 2; ++side) {
    const Halfedge h = HalfedgeMesh::halfedge(e, side);
    if (a.next(h) != b.next(h) || a.prev(h) != b.prev(h) || a.origin(h) != b.origin(h) ||
        a.face(h) != b.face(h))
      return false;
  }
  return a.is_deleted(e) == b.is_deleted(e);
}

bool same_face(const HalfedgeMesh& a, const HalfedgeMesh& b, Face f) {
  return a.halfedge(f) == b.halfedge(f) && a.is_deleted(f) == b.is_deleted(f);
}

/// Every element that differs between `before` and `after`, or is new in `after`, is listed,
/// and the list is strictly increasing.
template <class H, class Same>
void expect_listed(const std::vector<H>& listed, int old_capacity, int capacity, Same same,
                   const char* what) {
  EXPECT_TRUE(std::adjacent_find(listed.begin(), listed.end(), [](H x, H y) { return x >= y; }) ==
              listed.end())
      << what;
  for (int i = 0; i < capacity; ++i) {
    if (i < old_capacity && same(H(i))) continue;
    EXPECT_TRUE(std::binary_search(listed.begin(), listed.end(), H(i)))
        << what << " " << i << " changed but is not in the delta";
  }
}

// Random operator sequences (fixed seed) on every primitive, including delete-face, which edits
// a copy and commits it through a delta of its own, and collapse-edge, which moves a vertex.
TEST(MeshJournal, UndoesAndRedoesRandomEditsExactlyAndListsEveryChange) {
  std::mt19937 rng(2024);
  const char* primitives[] = {"tetrahedron", "cube", "octahedron", "icosahedron", "dodecahedron"};
  int edited = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const HalfedgeMesh start = make_primitive(primitives[trial % 5], {});
    HalfedgeMesh m = start;
    m.begin_journal();
    const int ops = 1 + static_cast<int>(rng() % 6);
    for (int k = 0; k < ops; ++k) {
      std::string line = test::random_operation(m, rng);
      const auto faces = m.faces().to_vector();
      const Face f = faces[rng() % faces.size()];
      const Halfedge h = m.halfedge(f);
      if (rng() % 4 == 0) line = fmt::format("delete-face {}", f.idx + 1);
      if (rng() % 4 == 0)
        line = fmt::format("collapse-edge {} {}@{}", m.origin(h).idx + 1, m.target(h).idx + 1,
                           f.idx + 1);
      try {
        apply_operation(m, line);
      } catch (const Error&) {
      }
    }
    ASSERT_TRUE(m.journal_open()) << "trial " << trial << ": an operator replaced the mesh";
    const HalfedgeMesh::Delta delta = m.end_journal();
    if (!(m == start)) ++edited;

    expect_listed(
        delta.vertices, start.vertex_capacity(), m.vertex_capacity(),
        [&](Vertex v) { return same_vertex(start, m, v); }, "vertex");
    expect_listed(
        delta.edges, start.edge_capacity(), m.edge_capacity(),
        [&](Edge e) { return same_edge(start, m, e); }, "edge");
    expect_listed(
        delta.faces, start.face_capacity(), m.face_capacity(),
        [&](Face f) { return same_face(start, m, f); }, "face");

    HalfedgeMesh replay = m;
    replay.apply(delta, false);
    EXPECT_TRUE(replay == start) << "trial " << trial << ": undo is not exact";
    replay.apply(delta, true);
    EXPECT_TRUE(replay == m) << "trial " << trial << ": redo is not exact";
  }
  EXPECT_GT(edited, 40);  // the sample is only useful if most trials change the mesh
}

TEST(MeshJournal, BelongsToOneMeshObject) {
  HalfedgeMesh m = make_cube();
  m.begin_journal();
  EXPECT_THROW(m.begin_journal(), std::logic_error);
  const HalfedgeMesh copy = m;
  EXPECT_FALSE(copy.journal_open());
  EXPECT_TRUE(copy == m);
  EXPECT_THROW(m.garbage_collection(), std::logic_error);
  m = make_cube();  // replaced: the journal is gone with the old contents
  EXPECT_THROW(m.end_journal(), std::logic_error);
}

TEST(MeshJournal, RefusesADeltaThatDoesNotStartHere) {
  HalfedgeMesh m = make_cube();
  m.begin_journal();
  apply_operation(m, "subdivide-edge 1 2");
  const HalfedgeMesh::Delta delta = m.end_journal();
  EXPECT_THROW(m.apply(delta, true), std::logic_error);  // m is already at the after end
  HalfedgeMesh cube = make_cube();
  cube.apply(delta, true);
  EXPECT_TRUE(cube == m);
}

}  // namespace
}  // namespace stitch
