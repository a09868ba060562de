// HalfedgeMesh::vertices(), edges(), halfedges() and faces(): ranges over the live elements that
// build no list, with the behaviour element_range.hpp promises when the mesh changes mid-loop.
#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <ranges>
#include <vector>

#include "stitch/mesh/halfedge_mesh.hpp"
#include "stitch/topology/edge_ops.hpp"
#include "stitch/topology/extrude.hpp"
#include "stitch/topology/insert_edge.hpp"
#include "stitch/topology/primitives.hpp"

namespace stitch {
namespace {

static_assert(std::ranges::forward_range<ElementRange<Face>>);
static_assert(std::forward_iterator<ElementRange<Halfedge>::iterator>);

/// The live elements by a plain pass over the flags, to compare the ranges with.
template <class H>
std::vector<H> live_by_index(const HalfedgeMesh& m, int capacity) {
  std::vector<H> out;
  for (int i = 0; i < capacity; ++i)
    if (!m.is_deleted(H(i))) out.emplace_back(i);
  return out;
}

TEST(ElementRange, VisitsTheLiveElementsInIndexOrder) {
  HalfedgeMesh m = make_cube();
  // Collapsing an edge deletes a vertex, edges and (here) no face; deleting an edge merges two
  // faces: both leave garbage in the middle of the arrays.
  const Vertex keep = m.origin(HalfedgeMesh::halfedge(Edge(3), 0));
  ASSERT_TRUE(can_collapse_edge(m, Edge(3), keep));
  collapse_edge(m, Edge(3), keep);
  const Edge merged = HalfedgeMesh::edge(m.halfedge(Face(5)));
  ASSERT_TRUE(can_delete_edge(m, merged));
  delete_edge(m, merged);
  ASSERT_TRUE(m.has_garbage());

  EXPECT_EQ(m.vertices().to_vector(), live_by_index<Vertex>(m, m.vertex_capacity()));
  EXPECT_EQ(m.edges().to_vector(), live_by_index<Edge>(m, m.edge_capacity()));
  EXPECT_EQ(m.faces().to_vector(), live_by_index<Face>(m, m.face_capacity()));
  std::vector<Halfedge> halfedges;
  for (Edge e : live_by_index<Edge>(m, m.edge_capacity())) {
    halfedges.push_back(HalfedgeMesh::halfedge(e, 0));
    halfedges.push_back(HalfedgeMesh::halfedge(e, 1));
  }
  EXPECT_EQ(m.halfedges().to_vector(), halfedges);

  EXPECT_EQ(m.vertices().size(), static_cast<size_t>(m.num_vertices()));
  EXPECT_EQ(m.edges().size(), static_cast<size_t>(m.num_edges()));
  EXPECT_EQ(m.halfedges().size(), static_cast<size_t>(m.num_halfedges()));
  EXPECT_EQ(m.faces().size(), static_cast<size_t>(m.num_faces()));
  EXPECT_EQ(std::ranges::distance(m.faces()), m.num_faces());
  EXPECT_FALSE(m.faces().empty());
  EXPECT_TRUE(HalfedgeMesh().faces().empty());
  EXPECT_EQ(HalfedgeMesh().faces().begin(), HalfedgeMesh().faces().end());
}

TEST(ElementRange, EqualityComparesTheLiveNumbers) {
  const HalfedgeMesh a = make_cube();
  HalfedgeMesh b = make_cube();
  EXPECT_TRUE(a.vertices() == b.vertices());
  collapse_edge(b, Edge(0), b.origin(HalfedgeMesh::halfedge(Edge(0), 0)));
  EXPECT_FALSE(a.vertices() == b.vertices());
  EXPECT_FALSE(a.edges() == b.edges());
}

TEST(ElementRange, ElementsAddedDuringTheLoopAreNotVisitedAndDeletedOnesAreSkipped) {
  HalfedgeMesh m = make_cube();
  const int faces_before = m.num_faces();
  // Extruding adds faces (and may reallocate the flags' vector) while the loop runs.
  int visited = 0;
  for (Face f : m.faces()) {
    ASSERT_LT(f.idx, faces_before) << "a face added during the loop was visited";
    extrude_face(m, f, 0.1, 0.5);
    ++visited;
  }
  EXPECT_EQ(visited, faces_before);
  EXPECT_GT(m.num_faces(), faces_before);

  // Deleting the next edge while at the current one: the deleted edge is not visited.
  HalfedgeMesh t = make_torus(4, 4);
  std::vector<Edge> seen;
  for (Edge e : t.edges()) {
    seen.push_back(e);
    if (e.idx == 0) {
      ASSERT_TRUE(can_delete_edge(t, Edge(1)));
      delete_edge(t, Edge(1));
    }
  }
  EXPECT_EQ(std::count(seen.begin(), seen.end(), Edge(1)), 0);
  EXPECT_EQ(seen.size(), static_cast<size_t>(t.num_edges()));
}

}  // namespace
}  // namespace stitch
