// The mesh's journal: what a sequence of edits touched, undone and redone exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>

#include "random_operation.hpp"
#include "stitch/mesh/mesh_journal.hpp"
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
    MeshJournal journal(m);
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
    ASSERT_TRUE(journal.attached()) << "trial " << trial << ": an operator replaced the mesh";
    const MeshDelta delta = journal.finish();
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
    apply_delta(replay, delta, false);
    EXPECT_TRUE(replay == start) << "trial " << trial << ": undo is not exact";
    apply_delta(replay, delta, true);
    EXPECT_TRUE(replay == m) << "trial " << trial << ": redo is not exact";
  }
  EXPECT_GT(edited, 40);  // the sample is only useful if most trials change the mesh
}

TEST(MeshJournal, RefusesADeltaThatDoesNotStartHere) {
  HalfedgeMesh m = make_cube();
  MeshJournal journal(m);
  apply_operation(m, "subdivide-edge 1 2");
  const MeshDelta delta = journal.finish();
  EXPECT_THROW(apply_delta(m, delta, true), std::logic_error);  // m is already at the after end
  HalfedgeMesh cube = make_cube();
  apply_delta(cube, delta, true);
  EXPECT_TRUE(cube == m);
}

/// Whether `f` throws std::logic_error with `words` in its message.
template <class F>
::testing::AssertionResult logic_error_saying(F f, const std::string& words) {
  try {
    f();
  } catch (const std::logic_error& e) {
    if (std::string(e.what()).find(words) != std::string::npos)
      return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "the message is: " << e.what();
  }
  return ::testing::AssertionFailure() << "nothing was thrown";
}

TEST(MeshJournal, AttachesToOneMeshAtATimeAndDetachesWhenFinishedOrDestroyed) {
  HalfedgeMesh m = make_cube();
  EXPECT_FALSE(m.observed());
  {
    MeshJournal journal(m);
    EXPECT_TRUE(m.observed());
    EXPECT_TRUE(journal.attached());
    EXPECT_TRUE(logic_error_saying([&] { MeshJournal second(m); }, "observed by another journal"));
    // The refused second journal left the first in place.
    EXPECT_TRUE(m.observed());
    apply_operation(m, "subdivide-edge 1 2");
    EXPECT_TRUE(logic_error_saying([&] { m.garbage_collection(); }, "journal observes"));
  }  // destroyed unfinished: the edits stay, the mesh is free again
  EXPECT_FALSE(m.observed());
  EXPECT_EQ(m.num_vertices(), 9);

  MeshJournal journal(m);
  apply_operation(m, "subdivide-edge 1 9");  // 9: the vertex the first split made
  const MeshDelta delta = journal.finish();
  EXPECT_FALSE(m.observed());
  EXPECT_FALSE(journal.attached());
  EXPECT_FALSE(delta.vertices.empty());
  EXPECT_TRUE(logic_error_saying([&] { journal.finish(); }, "not attached"));
  apply_operation(m, "subdivide-edge 1 10");  // after finish(): nothing records, nothing breaks
  MeshJournal next(m);
  EXPECT_TRUE(next.attached());
}

TEST(MeshJournal, CopiesOfTheMeshAreNotObserved) {
  HalfedgeMesh m = make_cube();
  const HalfedgeMesh start = m;
  MeshJournal journal(m);
  HalfedgeMesh copy = m;
  HalfedgeMesh assigned = make_tetrahedron();
  assigned = m;
  EXPECT_FALSE(copy.observed());
  EXPECT_FALSE(assigned.observed());
  EXPECT_TRUE(copy == m);  // observing is not part of the mesh's value
  // Edits of the copies are theirs alone: the journal of m sees none of them.
  apply_operation(copy, "subdivide-edge 1 2");
  apply_operation(assigned, "delete-face 1");
  EXPECT_TRUE(m.observed());
  const MeshDelta delta = journal.finish();
  EXPECT_TRUE(delta.vertices.empty());
  EXPECT_TRUE(delta.edges.empty());
  EXPECT_TRUE(delta.faces.empty());
  EXPECT_TRUE(m == start);
}

// A mesh replaced wholesale (destroyed, assigned to, moved from) cannot be described by the
// elements its journal recorded: the journal detaches and refuses to give a delta.
TEST(MeshJournal, IsLostWhenItsMeshIsDestroyedAssignedToOrMovedFrom) {
  {
    std::optional<HalfedgeMesh> m(make_cube());
    MeshJournal journal(*m);
    apply_operation(*m, "subdivide-edge 1 2");
    m.reset();
    EXPECT_FALSE(journal.attached());
    EXPECT_TRUE(logic_error_saying([&] { journal.finish(); }, "destroyed, assigned to or moved"));
  }  // the journal's destructor must not reach for the destroyed mesh
  {
    HalfedgeMesh m = make_cube();
    MeshJournal journal(m);
    HalfedgeMesh moved = std::move(m);
    EXPECT_FALSE(journal.attached());
    EXPECT_FALSE(m.observed());
    EXPECT_FALSE(moved.observed());
    EXPECT_THROW(journal.finish(), std::logic_error);
  }
  {
    HalfedgeMesh m = make_cube();
    MeshJournal journal(m);
    HalfedgeMesh target = make_cube();
    target = std::move(m);
    EXPECT_FALSE(journal.attached());
    EXPECT_FALSE(target.observed());
  }
  {
    HalfedgeMesh m = make_cube();
    const HalfedgeMesh other = make_tetrahedron();
    MeshJournal journal(m);
    m = other;
    EXPECT_FALSE(journal.attached());
    EXPECT_FALSE(m.observed());
    EXPECT_THROW(journal.finish(), std::logic_error);
  }
  {
    HalfedgeMesh m = make_cube();
    MeshJournal journal(m);
    m = make_cube();  // move-assigned: replaced as surely as by a copy
    EXPECT_FALSE(journal.attached());
    EXPECT_THROW(journal.finish(), std::logic_error);
  }
  {
    HalfedgeMesh m = make_cube();
    MeshJournal journal(m);
    HalfedgeMesh& same = m;
    m = same;  // assigning a mesh to itself replaces nothing
    EXPECT_TRUE(journal.attached());
  }
}

TEST(MeshJournal, AnObservedMeshTakesOnlyDeltasThatAddElements) {
  HalfedgeMesh m = make_cube();
  MeshJournal first(m);
  apply_operation(m, "subdivide-edge 1 2");
  const MeshDelta grows = first.finish();
  MeshJournal second(m);
  EXPECT_TRUE(logic_error_saying([&] { apply_delta(m, grows, false); }, "cannot remove"));
  HalfedgeMesh cube = make_cube();
  MeshJournal third(cube);
  apply_delta(cube, grows, true);
  const MeshDelta replayed = third.finish();
  EXPECT_EQ(replayed.vertices, grows.vertices);
  EXPECT_EQ(replayed.edges, grows.edges);
  EXPECT_EQ(replayed.faces, grows.faces);
}

}  // namespace
}  // namespace stitch
