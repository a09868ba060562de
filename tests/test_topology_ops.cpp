// The topology operators one by one: validity after each, the exact changes of V, E, F,
// components, genus and Euler characteristic, numbering, and refusals leaving the mesh as it was.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "stitch/mesh/build.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/topology/compare.hpp"
#include "stitch/topology/connect_faces.hpp"
#include "stitch/topology/delete_face.hpp"
#include "stitch/topology/edge_ops.hpp"
#include "stitch/topology/extrude.hpp"
#include "stitch/topology/insert_edge.hpp"
#include "stitch/topology/operation.hpp"
#include "stitch/topology/primitives.hpp"
#include "stitch/topology/remesh.hpp"
#include "test_support.hpp"

namespace stitch {
namespace {

using test::signed_volume;

struct Counts {
  int v, e, f, components, genus;
};

void expect_counts(const HalfedgeMesh& m, Counts c) {
  ASSERT_TRUE(find_problems(m).empty()) << find_problems(m).front();
  const TopologyStats s = topology_stats(m);
  EXPECT_EQ(s.vertices, c.v);
  EXPECT_EQ(s.edges, c.e);
  EXPECT_EQ(s.faces, c.f);
  EXPECT_EQ(s.components, c.components);
  EXPECT_EQ(s.genus, c.genus);
  EXPECT_EQ(s.euler, c.v - c.e + c.f);
}

/// Two meshes side by side in one (the second shifted by `offset` along x).
HalfedgeMesh disjoint_union(const HalfedgeMesh& a, const HalfedgeMesh& b, double offset) {
  PolygonSoup s = to_polygon_soup(a), t = to_polygon_soup(b);
  const int n = static_cast<int>(s.positions.size());
  for (Vec3 p : t.positions) s.positions.push_back(p + Vec3(offset, 0, 0));
  for (auto loop : t.faces) {
    for (int& v : loop) v += n;
    s.faces.push_back(loop);
  }
  return build_mesh(s);
}

Corner corner(const HalfedgeMesh& m, int v, int f) {
  return parse_corner(m, std::to_string(v) + "@" + std::to_string(f));
}

TEST(TopologyPrimitives, CountsAndOutwardOrientation) {
  expect_counts(make_tetrahedron(), {4, 6, 4, 1, 0});
  expect_counts(make_cube(), {8, 12, 6, 1, 0});
  expect_counts(make_octahedron(), {6, 12, 8, 1, 0});
  expect_counts(make_dodecahedron(), {20, 30, 12, 1, 0});
  expect_counts(make_icosahedron(), {12, 30, 20, 1, 0});
  expect_counts(make_prism(5), {10, 15, 7, 1, 0});
  expect_counts(make_prism(2), {4, 6, 4, 1, 0});
  expect_counts(make_torus(6, 4), {24, 48, 24, 1, 1});
  for (const HalfedgeMesh& m :
       {make_tetrahedron(), make_cube(), make_octahedron(), make_dodecahedron(), make_icosahedron(),
        make_prism(5), make_torus(6, 4)})
    EXPECT_GT(signed_volume(m), 0);
  EXPECT_NEAR(signed_volume(make_cube()), 8.0, 1e-12);  // [-1,1]^3
  for (const HalfedgeMesh& m : {make_dodecahedron(), make_icosahedron()})
    for (Face f : m.faces()) EXPECT_EQ(m.degree(f), m.degree(Face(0)));
}

TEST(TopologyPrimitives, CubeNumberingIsTheDocumentedOne) {
  const HalfedgeMesh cube = make_cube();
  EXPECT_EQ(cube.position(Vertex(0)), Vec3(-1, -1, -1));
  EXPECT_EQ(cube.position(Vertex(6)), Vec3(1, 1, 1));
  const PolygonSoup s = to_polygon_soup(cube);
  const std::vector<std::vector<int>> faces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                               {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  EXPECT_EQ(s.faces, faces);
}

TEST(TopologyPrimitives, ByNameAndRefusals) {
  EXPECT_EQ(make_primitive("prism", {6}).num_faces(), 8);
  EXPECT_EQ(make_primitive("torus", {5, 3}).num_faces(), 15);
  EXPECT_THROW(make_primitive("sphere", {}), Error);
  EXPECT_THROW(make_primitive("prism", {}), Error);
  EXPECT_THROW(make_primitive("prism", {1}), Error);
  EXPECT_THROW(make_primitive("torus", {2, 5}), Error);
  EXPECT_THROW(make_primitive("cube", {3}), Error);
}

TEST(TopologyInsertEdge, SameFaceSplits) {
  HalfedgeMesh m = make_cube();
  const InsertEdgeResult r = insert_edge(m, corner(m, 1, 1), corner(m, 3, 1));
  EXPECT_TRUE(r.split);
  EXPECT_EQ(r.edge.idx, 12);
  EXPECT_EQ(r.face.idx, 0);
  EXPECT_EQ(r.other.idx, 6);
  expect_counts(m, {8, 13, 7, 1, 0});
  EXPECT_EQ(m.degree(Face(0)), 3);
  EXPECT_EQ(m.degree(Face(6)), 3);
  // Face 1 keeps the part holding its first corner (vertex 1).
  EXPECT_EQ(m.origin(m.halfedge(Face(0))).idx, 0);
}

TEST(TopologyInsertEdge, AdjacentCornersGiveATwoSidedFace) {
  HalfedgeMesh m = make_cube();
  insert_edge(m, corner(m, 1, 1), corner(m, 4, 1));
  expect_counts(m, {8, 13, 7, 1, 0});
  int two_gons = 0;
  for (Face f : m.faces()) two_gons += m.degree(f) == 2;
  EXPECT_EQ(two_gons, 1);
}

TEST(TopologyInsertEdge, OppositeFacesOfACubeGiveGenusOneWithATenSidedFace) {
  HalfedgeMesh m = make_cube();
  const InsertEdgeResult r = insert_edge(m, corner(m, 1, 1), corner(m, 7, 2));
  EXPECT_FALSE(r.split);
  EXPECT_EQ(r.face.idx, 0);
  EXPECT_EQ(r.other.idx, 1);
  EXPECT_TRUE(m.is_deleted(Face(1)));
  expect_counts(m, {8, 13, 5, 1, 1});
  EXPECT_EQ(m.degree(Face(0)), 10);
  // The same through the operation line, as the docs show it.
  HalfedgeMesh n = make_cube();
  const OperationReport rep = apply_operation(n, "insert-edge 1@1 7@2");
  EXPECT_EQ(n, m);
  EXPECT_EQ(rep.stats.genus, 1);
  EXPECT_EQ(rep.summary("insert-edge 1@1 7@2"),
            "insert-edge 1@1 7@2: new edge 13 merged faces 1 and 2 into face 1 (10 sides); V 8 "
            "E 13 F 5, Euler 0, genus 1, components 1");
}

TEST(TopologyInsertEdge, TwoComponentsJoin) {
  HalfedgeMesh m = disjoint_union(make_cube(), make_cube(), 3);
  expect_counts(m, {16, 24, 12, 2, 0});
  // Face 4 (x = 1) of the first cube faces face 12 (x = -1) of the second.
  insert_edge(m, corner(m, 2, 4), corner(m, 12, 12));
  expect_counts(m, {16, 25, 11, 1, 0});
}

TEST(TopologyInsertEdge, RefusalsLeaveTheMeshUnchanged) {
  const HalfedgeMesh cube = make_cube();
  HalfedgeMesh m = cube;
  const Corner c = corner(m, 1, 1);
  EXPECT_THROW(insert_edge(m, c, c), Error);
  EXPECT_EQ(m, cube);
  try {
    insert_edge(m, corner(m, 1, 1), corner(m, 1, 3));
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("loop"), std::string::npos) << e.what();
  }
  EXPECT_EQ(m, cube);
  EXPECT_THROW(insert_edge(m, Corner(999), c), Error);
  EXPECT_EQ(m, cube);
}

TEST(TopologyDeleteEdge, UndoesASplitExactly) {
  const HalfedgeMesh cube = make_cube();
  HalfedgeMesh m = cube;
  const InsertEdgeResult r = insert_edge(m, corner(m, 2, 1), corner(m, 4, 1));
  const DeleteEdgeResult d = delete_edge(m, r.edge);
  EXPECT_FALSE(d.split);
  EXPECT_EQ(d.face.idx, 0);
  m.garbage_collection();
  EXPECT_EQ(m, cube);
}

TEST(TopologyDeleteEdge, SplittingAFaceLowersTheGenus) {
  HalfedgeMesh m = make_cube();
  const InsertEdgeResult r = insert_edge(m, corner(m, 1, 1), corner(m, 7, 2));
  const DeleteEdgeResult d = delete_edge(m, r.edge);
  EXPECT_TRUE(d.split);
  expect_counts(m, {8, 12, 6, 1, 0});
  EXPECT_TRUE(same_up_to_renumbering(m, make_cube()));
}

TEST(TopologyDeleteEdge, SplittingAFaceSeparatesComponents) {
  HalfedgeMesh m = disjoint_union(make_cube(), make_tetrahedron(), 4);
  const HalfedgeMesh before = m;
  const InsertEdgeResult r = insert_edge(m, corner(m, 2, 4), corner(m, 9, 7));
  expect_counts(m, {12, 19, 9, 1, 0});
  delete_edge(m, r.edge);
  expect_counts(m, {12, 18, 10, 2, 0});
  EXPECT_TRUE(same_up_to_renumbering(m, before));
}

TEST(TopologyDeleteEdge, RefusedAtAValenceTwoVertex) {
  HalfedgeMesh m = make_cube();
  const SubdivideEdgeResult s = subdivide_edge(m, Edge(0));
  const HalfedgeMesh before = m;
  try {
    delete_edge(m, s.edge);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("valence 2"), std::string::npos) << e.what();
  }
  EXPECT_EQ(m, before);
}

TEST(TopologyEdgeOps, SubdivideThenCollapse) {
  HalfedgeMesh m = make_cube();
  const Vertex a = m.origin(HalfedgeMesh::halfedge(Edge(3), 0));
  const Vertex b = m.origin(HalfedgeMesh::halfedge(Edge(3), 1));
  const SubdivideEdgeResult s = subdivide_edge(m, Edge(3));
  EXPECT_EQ(s.vertex.idx, 8);
  EXPECT_EQ(s.edge.idx, 12);
  expect_counts(m, {9, 13, 6, 1, 0});
  EXPECT_EQ(m.valence(s.vertex), 2);
  EXPECT_EQ(m.position(s.vertex), 0.5 * (m.position(a) + m.position(b)));
  EXPECT_EQ(m.origin(HalfedgeMesh::halfedge(Edge(3), 0)), a);  // edge 3 keeps its first end
  EXPECT_EQ(m.target(HalfedgeMesh::halfedge(s.edge, 0)), b);
  collapse_edge(m, s.edge, s.vertex);
  expect_counts(m, {8, 12, 6, 1, 0});
  EXPECT_TRUE(m.is_deleted(b));
}

TEST(TopologyEdgeOps, CollapseOnATriangleMakesATwoSidedFaceAndRefusesTheNext) {
  HalfedgeMesh m = make_tetrahedron();
  const Edge e = parse_edge(m, "1", "2");
  collapse_edge(m, e, Vertex(0));
  expect_counts(m, {3, 5, 4, 1, 0});
  EXPECT_EQ(m.position(Vertex(0)), Vec3(1, 0, 0));
  // Vertices 1 and 3 are now joined by two edges: collapsing either would leave a loop.
  const HalfedgeMesh before = m;
  const Edge twice = parse_edge(m, "1", "3@1");
  try {
    collapse_edge(m, twice, Vertex(0));
    FAIL();
  } catch (const Error& e2) {
    EXPECT_NE(std::string(e2.what()).find("more than one edge"), std::string::npos);
  }
  EXPECT_EQ(m, before);
}

TEST(TopologyExtrude, CountsAndNumbering) {
  HalfedgeMesh m = make_cube();
  const ExtrudeResult r = extrude_face(m, Face(1), 0.5);
  EXPECT_EQ(r.first_vertex, 8);
  EXPECT_EQ(r.first_face, 6);
  expect_counts(m, {12, 20, 10, 1, 0});
  EXPECT_EQ(m.position(Vertex(8)), Vec3(-1, -1, 1.5));  // above vertex 5, the top's first corner
  EXPECT_EQ(m.origin(m.halfedge(Face(1))).idx, 8);
  for (int f = 6; f < 10; ++f) EXPECT_EQ(m.degree(Face(f)), 4);
  EXPECT_GT(signed_volume(m), 8.0);
}

TEST(TopologyExtrude, RefusesAFaceWhoseLoopTouchesItself) {
  // Bottom and front merged by an edge from vertex 4 to vertex 6: the merged face runs along
  // the new edge twice and visits vertices 4 and 6 twice. Every corner would get its own new
  // vertex, so the top would have two vertices at the same point (a degenerate surface).
  HalfedgeMesh m = make_cube();
  apply_operation(m, "insert-edge 4@1 6@3");
  expect_counts(m, {8, 13, 5, 1, 1});
  ASSERT_EQ(m.degree(Face(0)), 10);
  const HalfedgeMesh before = m;
  try {
    extrude_face(m, Face(0), 0.2, 0.8);
    FAIL() << "extrude-face accepted a loop that visits a vertex twice";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("twice"), std::string::npos) << e.what();
  }
  EXPECT_EQ(m, before);
}

TEST(TopologyExtrude, RefusesAFaceWithoutANormal) {
  HalfedgeMesh m = make_prism(2);  // its caps are 2-sided, with zero area
  const HalfedgeMesh before = m;
  EXPECT_THROW(extrude_face(m, Face(0), 1.0), Error);
  EXPECT_EQ(m, before);
  EXPECT_THROW(extrude_face(m, Face(2), std::nan("")), Error);
  EXPECT_EQ(m, before);
}

TEST(TopologyConnectFaces, HandleOnOneCube) {
  HalfedgeMesh m = make_cube();
  const ConnectFacesResult r = connect_faces(m, Face(0), Face(1), 0);
  EXPECT_EQ(r.first_edge, 12);
  expect_counts(m, {8, 16, 8, 1, 1});
  for (Face f : m.faces()) EXPECT_EQ(m.degree(f), 4);
  // Corner f_0 (vertex 1) is joined to g_0 (vertex 5): the new edge 13 is vertical.
  const Halfedge h = HalfedgeMesh::halfedge(Edge(12), 0);
  EXPECT_EQ(m.origin(h).idx, 0);
  EXPECT_EQ(m.target(h).idx, 4);
}

TEST(TopologyConnectFaces, TwistAndJoiningComponents) {
  HalfedgeMesh m = make_cube();
  connect_faces(m, Face(0), Face(1), 1);
  expect_counts(m, {8, 16, 8, 1, 1});
  HalfedgeMesh two = disjoint_union(make_cube(), make_cube(), 3);
  connect_faces(two, Face(3), Face(11), 2);
  expect_counts(two, {16, 28, 14, 1, 0});
}

TEST(TopologyConnectFaces, Refusals) {
  HalfedgeMesh m = make_prism(3);
  const HalfedgeMesh before = m;
  EXPECT_THROW(connect_faces(m, Face(0), Face(2)), Error);  // 3 vs 4 sides
  EXPECT_THROW(connect_faces(m, Face(0), Face(0)), Error);
  HalfedgeMesh c = make_cube();
  try {
    connect_faces(c, Face(0), Face(2), 0);  // bottom and front share vertex 1 at f_0, g_0
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("loop"), std::string::npos) << e.what();
  }
  EXPECT_EQ(c, make_cube());
  EXPECT_EQ(m, before);
}

TEST(TopologyConnectFaces, LeastTwistJoinsTheCornersStraightAcross) {
  const HalfedgeMesh cube = make_cube();
  // Opposite faces: every joined pair differs along the line between the faces only. Face 3
  // (1 2 6 5) and face 5 (3 4 8 7) need twist 1 for that; bottom and top twist 0.
  for (const auto& [a, b, expected] :
       {std::array{1, 2, 0}, std::array{3, 5, 1}, std::array{6, 4, 1}}) {
    const Face f(a - 1), g(b - 1);
    const int twist = least_twist(cube, f, g);
    EXPECT_EQ(twist, expected) << a << " " << b;
    const auto lf = cube.face_loop(f), lg = cube.face_loop(g);
    for (int i = 0; i < 4; ++i) {
      const Vec3 d =
          cube.position(cube.origin(lg[(twist - i + 4) % 4])) - cube.position(cube.origin(lf[i]));
      EXPECT_NEAR(d.norm(), 2.0, 1e-12) << a << " " << b << " corner " << i;
    }
  }
  // Faces sharing an edge: the twists that would join a corner to itself are skipped.
  const int twist = least_twist(cube, Face(0), Face(2));
  EXPECT_NE(twist, 0);
  HalfedgeMesh m = cube;
  EXPECT_NO_THROW(connect_faces(m, Face(0), Face(2), HandleOptions{}));
}

TEST(TopologyConnectFaces, OperationChoosesTheTwistUnlessGiven) {
  HalfedgeMesh chosen = make_cube(), given = make_cube();
  const OperationReport r = apply_operation(chosen, "connect-faces 3 5");
  EXPECT_NE(r.what.find("(twist 1)"), std::string::npos) << r.what;
  apply_operation(given, "connect-faces 3 5 1");
  EXPECT_EQ(chosen, given);
  HalfedgeMesh zero = make_cube();
  const OperationReport z = apply_operation(zero, "connect-faces 3 5 0");
  EXPECT_NE(z.what.find("(twist 0)"), std::string::npos) << z.what;
  EXPECT_FALSE(zero == given);
  HalfedgeMesh automatic = make_cube();
  apply_operation(automatic, "connect-faces 3 5 auto");
  EXPECT_EQ(automatic, given);
}

TEST(TopologyConnectFaces, SegmentsAddRingsAlongThePath) {
  for (int segments : {1, 2, 3, 5}) {
    HalfedgeMesh m = make_cube();
    apply_operation(m, fmt::format("connect-faces 1 2 auto {}", segments));
    // Each ring adds k = 4 vertices, 8 edges and 4 faces to connect-faces's E + 4, F + 2.
    const int rings = segments - 1;
    expect_counts(m, {8 + 4 * rings, 16 + 8 * rings, 8 + 4 * rings, 1, 1});
    // The rings lie inside the cube, each at its height along the straight path from the bottom
    // face's centre to the top's, shrunk by 1 - (1 - 0.5) 4t(1-t) about it.
    for (int j = 1; j <= rings; ++j) {
      const double t = static_cast<double>(j) / segments;
      for (int i = 0; i < 4; ++i) {
        const Vec3 p = m.position(Vertex(8 + 4 * (j - 1) + i));
        EXPECT_NEAR(p.z(), -1 + 2 * t, 1e-12);
        EXPECT_NEAR(std::abs(p.x()), 1 - 0.5 * 4 * t * (1 - t), 1e-12);
        EXPECT_NEAR(std::abs(p.y()), 1 - 0.5 * 4 * t * (1 - t), 1e-12);
      }
    }
  }
}

TEST(TopologyConnectFaces, HandleRefusals) {
  for (const char* op :
       {"connect-faces 1 2 auto 0", "connect-faces 1 2 auto 1001", "connect-faces 1 2 auto 3 0",
        "connect-faces 1 2 auto 3 -1", "connect-faces 1 2 auto 3 nan", "connect-faces 1 2 x 3",
        "connect-faces 1 2 0 3 0.5 1"}) {
    HalfedgeMesh m = make_cube();
    EXPECT_THROW(apply_operation(m, op), Error) << op;
    EXPECT_EQ(m, make_cube()) << op;
  }
}

TEST(TopologyDeleteFace, CubeTopBecomesAPillow) {
  HalfedgeMesh m = make_cube();
  delete_face(m, Face(1));
  expect_counts(m, {4, 4, 2, 1, 0});
  EXPECT_FALSE(m.is_deleted(Face(0)));
  EXPECT_EQ(m.degree(Face(0)), 4);
  // Deleting either face of the pillow would leave nothing.
  const HalfedgeMesh before = m;
  EXPECT_THROW(delete_face(m, Face(0)), Error);
  EXPECT_EQ(m, before);
}

TEST(TopologyDeleteFace, OnATorusMergesItsNeighbours) {
  HalfedgeMesh m = make_torus(6, 4);
  delete_face(m, Face(0));
  ASSERT_TRUE(find_problems(m).empty());
  const TopologyStats s = topology_stats(m);
  EXPECT_EQ(s.vertices, 24);
  EXPECT_EQ(s.edges, 44);
  EXPECT_EQ(s.faces, 20);  // face 0 and its 4 neighbours became one face
  EXPECT_EQ(s.genus, 1);
}

TEST(TopologyRemesh, CountsOnTheCube) {
  const HalfedgeMesh cube = make_cube();
  expect_counts(dual(cube), {6, 12, 8, 1, 0});
  expect_counts(vertex_insertion(cube), {14, 24, 12, 1, 0});
  expect_counts(doo_sabin(cube), {24, 48, 26, 1, 0});
  expect_counts(catmull_clark_step(cube), {26, 48, 24, 1, 0});
  EXPECT_GT(signed_volume(dual(cube)), 0);
  EXPECT_GT(signed_volume(doo_sabin(cube)), 0);
  EXPECT_GT(signed_volume(vertex_insertion(cube)), 0);
  EXPECT_GT(signed_volume(catmull_clark_step(cube)), 0);
}

TEST(TopologyRemesh, KeepsGenusOnATorusAndAfterEdits) {
  HalfedgeMesh m = make_cube();
  insert_edge(m, corner(m, 1, 1), corner(m, 7, 2));  // genus 1, a face running along an edge twice
  for (const HalfedgeMesh& r : {vertex_insertion(m), doo_sabin(m)}) {
    ASSERT_TRUE(find_problems(r).empty());
    EXPECT_EQ(topology_stats(r).genus, 1);
  }
  EXPECT_THROW(dual(m), Error);  // the 10-sided face runs along the new edge twice
  const HalfedgeMesh t = make_torus(5, 4);
  for (const HalfedgeMesh& r :
       {dual(t), vertex_insertion(t), doo_sabin(t), catmull_clark_step(t)}) {
    ASSERT_TRUE(find_problems(r).empty());
    EXPECT_EQ(topology_stats(r).genus, 1);
  }
}

TEST(TopologyRemesh, CatmullClarkKeepsOldVertexNumbersAndTakesAnyTopology) {
  const HalfedgeMesh cube = make_cube();
  const HalfedgeMesh cc = catmull_clark_step(cube);
  // Catmull-Clark moves a cube corner (+-1,+-1,+-1) to (+-5/9, ...) on the same diagonal.
  for (Vertex v : cube.vertices())
    EXPECT_NEAR((cc.position(v) - cube.position(v) * 5.0 / 9.0).norm(), 0, 1e-12);
  // 2-sided faces, several edges between two vertices and faces running along an edge twice:
  // OpenSubdiv's rules applied to them still give a valid all-quad mesh with the same genus.
  HalfedgeMesh bridged = make_cube();
  insert_edge(bridged, corner(bridged, 1, 1), corner(bridged, 7, 2));
  for (const HalfedgeMesh& m : {make_prism(2), bridged}) {
    const TopologyStats before = topology_stats(m);
    const HalfedgeMesh r = catmull_clark_step(m);
    ASSERT_TRUE(find_problems(r).empty());
    const TopologyStats after = topology_stats(r);
    EXPECT_EQ(after.vertices, before.vertices + before.edges + before.faces);
    EXPECT_EQ(after.edges, 4 * before.edges);  // 2E halves + one spoke per corner (2E corners)
    EXPECT_EQ(after.faces, 2 * before.edges);
    EXPECT_EQ(after.genus, before.genus);
    for (Face f : r.faces()) EXPECT_EQ(r.degree(f), 4);
  }
  // A dual of a dual is the mesh again, topologically.
  const HalfedgeMesh dd = dual(dual(make_dodecahedron()));
  EXPECT_EQ(topology_stats(dd).faces, 12);
}

TEST(TopologyOperation, ParsesAndRefusesWithReasons) {
  const HalfedgeMesh cube = make_cube();
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"frobnicate 1", "unknown operation"},
      {"insert-edge 1@1", "takes two corners"},
      {"insert-edge 1@1 7@9", "no face 9"},
      {"insert-edge 7@1 1@1", "vertex 7 is not on face 1"},
      {"insert-edge 1 7@2", "not a corner"},
      {"insert-edge x@1 7@2", "not a valid vertex number"},
      {"delete-edge 1 7", "no edge joins vertices 1 and 7"},
      {"delete-edge 1 2@2", "no edge joining vertices 1 and 2 lies on face 2"},
      {"extrude-face 1 abc", "not a valid distance"},
      {"extrude-face 0 1", "not a valid face number"},
      {"connect-faces 1 3 x", "not a valid twist"},
      {"doo-sabin 3", "takes no arguments"},
      {"collapse-edge 1 9", "there is no vertex 9"},
  };
  for (const auto& [line, why] : bad) {
    HalfedgeMesh m = cube;
    try {
      apply_operation(m, line);
      ADD_FAILURE() << line << " was accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << line << " -> " << e.what();
    }
    EXPECT_EQ(m, cube) << line;
  }
  HalfedgeMesh m = cube;
  EXPECT_TRUE(apply_operation(m, "   # only a comment").what.empty());
  EXPECT_TRUE(apply_operation(m, "").what.empty());
  EXPECT_EQ(m, cube);
  apply_operation(m, "subdivide-edge 1 2  # with a comment");
  EXPECT_EQ(m.num_vertices(), 9);
}

TEST(TopologyOperation, AmbiguousCornersAndEdges) {
  HalfedgeMesh m = make_cube();
  apply_operation(m, "insert-edge 1@1 7@2");  // face 1 now visits vertices 1 and 7 twice
  const HalfedgeMesh before = m;
  try {
    apply_operation(m, "insert-edge 1@1 3@5");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("ambiguous"), std::string::npos) << e.what();
  }
  EXPECT_EQ(m, before);
  // #k picks the occurrence: the second visit of vertex 1 along face 1.
  const Corner c1 = parse_corner(m, "1@1#1"), c2 = parse_corner(m, "1@1#2");
  EXPECT_NE(c1, c2);
  EXPECT_EQ(m.origin(c1), m.origin(c2));
  EXPECT_THROW(parse_corner(m, "1@1#3"), Error);
  // '#' right after a corner picks an occurrence; after a blank it starts a comment.
  const OperationReport r = apply_operation(m, "insert-edge 1@1#2 3@5  # to the back face");
  EXPECT_EQ(r.stats.genus, 2);
  // A 2-sided face: both its edges join the same vertices; @F with direction V -> W picks one.
  HalfedgeMesh p = make_cube();
  apply_operation(p, "insert-edge 1@1 4@1");
  EXPECT_THROW(parse_edge(p, "1", "4"), Error);
  ASSERT_EQ(p.degree(Face(0)), 2);  // face 1 kept its first corner: it is the 2-sided part
  const Edge e1 = parse_edge(p, "1", "4@1"), e2 = parse_edge(p, "4", "1@1");
  EXPECT_NE(e1, e2);
  apply_operation(p, "delete-edge 1 4@1");
  EXPECT_TRUE(same_up_to_renumbering(p, make_cube()));
}

TEST(TopologyOperation, EverySummaryHasTheCounts) {
  HalfedgeMesh m = make_cube();
  for (const char* line :
       {"extrude-face 2 0.5", "connect-faces 1 2", "subdivide-edge 1 2", "collapse-edge 1 13",
        "catmull-clark", "delete-face 3", "vertex-insertion", "doo-sabin", "dual"}) {
    SCOPED_TRACE(line);
    const OperationReport r = apply_operation(m, line);
    ASSERT_TRUE(find_problems(m).empty());
    const std::string s = r.summary(line);
    EXPECT_NE(s.find(fmt::format("Euler {}, genus {}, components {}", r.stats.euler, r.stats.genus,
                                 r.stats.components)),
              std::string::npos)
        << s;
  }
}

}  // namespace
}  // namespace stitch
