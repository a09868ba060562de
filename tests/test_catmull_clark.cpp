// The Catmull-Clark comparison surface (OpenSubdiv Bfr) in stitch's per-corner parameterization.
#include <gtest/gtest.h>
#include <opensubdiv/far/primvarRefiner.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "stitch/eval/catmull_clark.hpp"
#include "stitch/mesh/build.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/opensubdiv_topology.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/net/control_net.hpp"
#include "stitch/topology/insert_edge.hpp"
#include "stitch/topology/primitives.hpp"
#include "test_support.hpp"

namespace stitch {
namespace {

namespace Osd = OpenSubdiv;

std::string shape(const std::string& name) {
  return std::string(STITCH_SHARED_DATA_DIR) + "/" + name + ".obj";
}

HalfedgeMesh load(const std::string& name) {
  return read_mesh(shape(name));
}

double mesh_size(const HalfedgeMesh& mesh) {
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (Vertex v : mesh.vertices()) {
    lo = lo.cwiseMin(mesh.position(v));
    hi = hi.cwiseMax(mesh.position(v));
  }
  return (hi - lo).norm();
}

Vec3 centroid(const HalfedgeMesh& mesh) {
  Vec3 sum = Vec3::Zero();
  for (Vertex v : mesh.vertices()) sum += mesh.position(v);
  return sum / mesh.num_vertices();
}

// Parameters along a patch side: the ends (vertex, edge midpoint, face centre) and inside.
const std::vector<double> kSideParams{0.0, 0.125, 0.3, 0.5, 0.77, 1.0};

/// The largest distance between two neighbouring patches' positions along their shared side,
/// over every side of every corner patch (at kSideParams).
double largest_side_gap(const HalfedgeMesh& mesh, const CatmullClarkSurface& cc) {
  double gap = 0;
  for (Corner c : mesh.halfedges())
    for (int side = 0; side < 4; ++side) {
      const PatchNeighbour nb = neighbour_across(mesh, c, side);
      for (double t : kSideParams) {
        const auto a = side_point(side, t);
        const auto b = side_point(nb.side, t);
        gap = std::max(
            gap, (cc.evaluate(c, a[0], a[1]).position - cc.evaluate(nb.corner, b[0], b[1]).position)
                     .norm());
      }
    }
  return gap;
}

class CatmullClarkShapes : public ::testing::TestWithParam<std::string> {};

// Neighbouring corner patches share their boundary curve. They come from different Bfr surfaces
// (different faces) or different parts of one face's domain, so they agree only up to the
// round-off of evaluating the limit surface twice: a few ulps of the coordinates times the
// size of the limit stencils' weights. 1e-9 of the mesh size leaves a wide margin over that
// (~1e-15) while any mistake in the corner mapping moves points by a fraction of an edge.
TEST_P(CatmullClarkShapes, PositionsAgreeAcrossEverySharedPatchSide) {
  const HalfedgeMesh mesh = load(GetParam());
  const CatmullClarkSurface cc(mesh);
  EXPECT_LT(largest_side_gap(mesh, cc), 1e-9 * mesh_size(mesh)) << GetParam();
}

// Without creases the Catmull-Clark limit surface is C1 away from extraordinary vertices and G1
// at them (and at the centres of non-quad faces), so the normals of two neighbouring patches
// along their shared side are the same unit vector up to round-off, both between the corner
// patches of one face and across mesh edges. Measured: below 1e-13; 1e-8 is far above that and
// far below any real kink (a wrong orientation or mapping gives differences of order 1).
TEST_P(CatmullClarkShapes, NormalsAreContinuousAcrossEveryPatchSide) {
  const HalfedgeMesh mesh = load(GetParam());
  const CatmullClarkSurface cc(mesh);
  for (Corner c : mesh.halfedges()) {
    for (int side = 0; side < 4; ++side) {
      const PatchNeighbour nb = neighbour_across(mesh, c, side);
      // Sides 1 and 2 join corner patches of one face; sides 0 and 3 cross a mesh edge.
      ASSERT_EQ(mesh.face(nb.corner) == mesh.face(c), side == 1 || side == 2);
      for (double t : kSideParams) {
        const auto a = side_point(side, t);
        const auto b = side_point(nb.side, t);
        const Vec3 n = cc.evaluate(c, a[0], a[1]).normal;
        const Vec3 m = cc.evaluate(nb.corner, b[0], b[1]).normal;
        ASSERT_NEAR(n.norm(), 1.0, 1e-12);
        ASSERT_LT((n - m).norm(), 1e-8)
            << GetParam() << ": corner " << c.idx << " side " << side << " t " << t;
      }
    }
  }
}

// The (0,0) corner of every patch is the limit point of its mesh vertex, which OpenSubdiv's
// Far::PrimvarRefiner::Limit computes by a different route (limit masks after one uniform
// refinement, which makes every face a quad). Same tolerance argument as for the patch sides.
TEST_P(CatmullClarkShapes, PatchCornersAreOpenSubdivsVertexLimitPositions) {
  const HalfedgeMesh mesh = load(GetParam());
  ASSERT_FALSE(mesh.has_garbage());  // soup vertex i is mesh vertex i
  const CatmullClarkSurface cc(mesh);
  const PolygonSoup soup = to_polygon_soup(mesh);

  const auto refiner = catmark_refiner(mesh);
  ASSERT_TRUE(refiner);
  Osd::Far::TopologyRefiner::UniformOptions uniform(1);
  uniform.fullTopologyInLastLevel = true;  // Limit() needs the vertex neighbourhoods
  refiner->RefineUniform(uniform);

  struct Point {
    Vec3 p = Vec3::Zero();
    void Clear() { p.setZero(); }
    void AddWithWeight(const Point& o, float w) { p += static_cast<double>(w) * o.p; }
    void AddWithWeight(const Point& o, double w) { p += w * o.p; }
  };
  std::vector<Point> level0(soup.positions.size());
  for (size_t i = 0; i < level0.size(); ++i) level0[i].p = soup.positions[i];
  std::vector<Point> level1(static_cast<size_t>(refiner->GetLevel(1).GetNumVertices()));
  const Osd::Far::PrimvarRefinerReal<double> primvar(*refiner);
  // PrimvarRefiner takes the buffers by reference to pointer.
  Point* src = level0.data();
  Point* dst = level1.data();
  primvar.Interpolate(1, src, dst);
  // Children of level-0 vertices come first at level 1, in the same order (the default
  // UniformOptions do not order vertices from faces first).
  std::vector<Point> limit(level1.size());
  Point* limit_dst = limit.data();
  primvar.Limit(dst, limit_dst);

  const double tol = 1e-9 * mesh_size(mesh);
  for (Corner c : mesh.halfedges()) {
    const Vertex v = mesh.origin(c);
    const Vec3 p = cc.evaluate(c, 0.0, 0.0).position;
    EXPECT_LT((p - limit[static_cast<size_t>(v.idx)].p).norm(), tol)
        << GetParam() << ": corner " << c.idx << " at vertex " << v.idx;
  }
}

INSTANTIATE_TEST_SUITE_P(SharedShapes, CatmullClarkShapes,
                         ::testing::Values("catmark_cube", "catmark_torus", "loop_tetrahedron",
                                           "catmark_pyramid", "loop_icosahedron"));

// du x dv points to the side the faces point to: outward on these closed, consistently oriented,
// convex meshes, where outward means away from the centroid.
TEST(CatmullClark, NormalsPointOutwardOnConvexShapes) {
  for (const std::string name : {"catmark_cube", "loop_tetrahedron", "catmark_pyramid"}) {
    const HalfedgeMesh mesh = load(name);
    const CatmullClarkSurface cc(mesh);
    const Vec3 centre = centroid(mesh);
    for (Corner c : mesh.halfedges()) {
      for (double u : {0.0, 0.4, 1.0}) {
        for (double v : {0.0, 0.7, 1.0}) {
          const SurfacePoint s = cc.evaluate(c, u, v);
          EXPECT_GT(s.normal.dot(s.position - centre), 0.0) << name << " corner " << c.idx;
          EXPECT_EQ(s.level, 0);
        }
      }
    }
  }
}

// The torus is not convex: outward there means away from the circle at the centre of its tube
// (the torus of OpenSubdiv's shapes runs around the y axis).
TEST(CatmullClark, NormalsPointOutwardOnTheTorus) {
  const HalfedgeMesh mesh = load("catmark_torus");
  const CatmullClarkSurface cc(mesh);
  double radius = 0.0;
  for (Vertex v : mesh.vertices()) radius += std::hypot(mesh.position(v).x(), mesh.position(v).z());
  radius /= mesh.num_vertices();
  for (Corner c : mesh.halfedges()) {
    const SurfacePoint s = cc.evaluate(c, 0.5, 0.5);
    const Vec3& p = s.position;
    const double r = std::hypot(p.x(), p.z());
    const Vec3 tube_centre(p.x() * radius / r, 0.0, p.z() * radius / r);
    EXPECT_GT(s.normal.dot(p - tube_centre), 0.0) << "corner " << c.idx;
  }
}

// du and dv are the derivatives in the corner patch's own (u, v): checked against central
// differences of positions (step 1e-5: truncation error ~1e-10, round-off ~1e-11 relative).
TEST(CatmullClark, DerivativesAreInThePatchParameters) {
  const HalfedgeMesh mesh = load("loop_tetrahedron");  // triangles: quad sub-faces
  const CatmullClarkSurface cc(mesh);
  const double h = 1e-5;
  for (Corner c : mesh.halfedges()) {
    const SurfacePoint s = cc.evaluate(c, 0.3, 0.6);
    const Vec3 du =
        (cc.evaluate(c, 0.3 + h, 0.6).position - cc.evaluate(c, 0.3 - h, 0.6).position) / (2 * h);
    const Vec3 dv =
        (cc.evaluate(c, 0.3, 0.6 + h).position - cc.evaluate(c, 0.3, 0.6 - h).position) / (2 * h);
    EXPECT_LT((s.du - du).norm(), 1e-6 * s.du.norm()) << "corner " << c.idx;
    EXPECT_LT((s.dv - dv).norm(), 1e-6 * s.dv.norm()) << "corner " << c.idx;
  }
}

TEST(CatmullClark, EvaluatesConcurrently) {
  const HalfedgeMesh mesh = load("catmark_torus");
  const CatmullClarkSurface cc(mesh);
  const auto corners = mesh.halfedges();
  std::vector<Vec3> serial;
  for (Corner c : corners) serial.push_back(cc.evaluate(c, 0.25, 0.75).position);
  std::vector<Vec3> parallel(corners.size());
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      for (size_t i = static_cast<size_t>(t); i < corners.size(); i += 4) {
        parallel[i] = cc.evaluate(corners[i], 0.25, 0.75).position;
      }
    });
  }
  for (auto& th : threads) th.join();
  EXPECT_EQ(serial, parallel);
}

// Edits leave deleted elements behind and may move a face's start half-edge: cc numbers the live
// elements densely for OpenSubdiv and maps each corner by its own position in its face, so the
// same topology gives the same patches. Inserting and deleting a diagonal restores the cube's
// topology with a deleted edge and face in the arrays; the patches equal the untouched cube's up
// to round-off (1e-12 of the size: both evaluate the same Bfr surfaces, possibly with the face's
// vertices rotated).
TEST(CatmullClark, IgnoresDeletedElementsAndFaceStarts) {
  const HalfedgeMesh cube = make_cube();
  HalfedgeMesh edited = cube;
  const Corner a = edited.halfedge(Face(0));
  const InsertEdgeResult diagonal = insert_edge(edited, a, edited.next(edited.next(a)));
  ASSERT_TRUE(diagonal.split);
  delete_edge(edited, diagonal.edge);
  ASSERT_TRUE(edited.has_garbage());
  ASSERT_EQ(edited.num_faces(), cube.num_faces());
  const CatmullClarkSurface before(cube), after(edited);
  const double tol = 1e-12 * mesh_size(cube);
  for (Corner c : cube.halfedges()) {
    ASSERT_FALSE(edited.is_deleted(c));
    for (double u : {0.0, 0.3, 1.0}) {
      for (double v : {0.0, 0.6, 1.0}) {
        EXPECT_LT((before.evaluate(c, u, v).position - after.evaluate(c, u, v).position).norm(),
                  tol)
            << "corner " << c.idx;
      }
    }
  }
  EXPECT_THROW((void)after.evaluate(HalfedgeMesh::halfedge(diagonal.edge, 0), 0.5, 0.5), MeshError);
}

// Inserting an edge between two opposite faces of a cube gives one 10-sided face whose loop runs
// along the new edge twice; OpenSubdiv cannot represent that, so cc must refuse it cleanly.
TEST(CatmullClark, RefusesAFaceThatRunsAlongAnEdgeTwice) {
  PolygonSoup soup = read_polygon_soup(shape("catmark_cube"));
  ASSERT_EQ(soup.faces.size(), 6U);
  // catmark_cube's faces 0 and 2 are opposite (no shared vertex).
  std::vector<int> a = soup.faces[0], b = soup.faces[2];
  for (int x : a) ASSERT_EQ(std::count(b.begin(), b.end(), x), 0);
  std::vector<int> merged = a;
  merged.push_back(a[0]);
  merged.insert(merged.end(), b.begin(), b.end());
  merged.push_back(b[0]);
  soup.faces.erase(soup.faces.begin() + 2);
  soup.faces.erase(soup.faces.begin());
  soup.faces.push_back(merged);
  soup.face_lines.clear();
  const HalfedgeMesh mesh = build_mesh(soup);
  const std::string message = test::error_of([&] { const CatmullClarkSurface cc(mesh); });
  ASSERT_FALSE(message.empty()) << "cc accepted a face that runs along an edge twice";
  EXPECT_NE(message.find("cannot handle"), std::string::npos) << message;
}

// A 2-sided face doubling one edge of a cube (what the topology operators create): OpenSubdiv's
// Bfr gives the faces around it no limit surface, so cc must refuse the mesh cleanly.
TEST(CatmullClark, RefusesTwoSidedFaces) {
  HalfedgeMesh mesh = load("catmark_cube");
  // Edge (h, t) keeps h in its face and lends t to the 2-gon; a new edge (h2, t2) gives t2 to
  // t's old face and h2 to the 2-gon.
  const Halfedge h = mesh.halfedge(Face(0));
  const Halfedge t = HalfedgeMesh::twin(h);
  const Face other = mesh.face(t);
  const Halfedge before = mesh.prev(t), after = mesh.next(t);
  const Halfedge h2 = mesh.add_edge(mesh.origin(h), mesh.target(h));
  const Halfedge t2 = HalfedgeMesh::twin(h2);
  mesh.link(before, t2);
  mesh.link(t2, after);
  mesh.set_face(t2, other);
  mesh.set_halfedge(other, t2);
  const Face two_gon = mesh.add_face();
  mesh.link(t, h2);
  mesh.link(h2, t);
  mesh.assign_loop(t, two_gon);
  ASSERT_TRUE(find_problems(mesh).empty());
  const std::string message = test::error_of([&] { const CatmullClarkSurface cc(mesh); });
  ASSERT_FALSE(message.empty()) << "cc accepted a mesh with a 2-sided face";
  EXPECT_NE(message.find("2-sided"), std::string::npos) << message;
}

// A handle on a cube made of two edges between the same two vertices (insert an edge between
// two opposite faces, then a second one between the same corners, which splits the merged face
// in two): both new faces visit a vertex twice. cc must either give a watertight surface or
// refuse the mesh with a MeshError; it may never return a surface that comes apart. (With
// OpenSubdiv 3.5 it refuses: Bfr's surfaces there leave gaps of a fifth of the cube's size.)
TEST(CatmullClark, NeverReturnsASurfaceThatComesApartAroundMultiEdges) {
  HalfedgeMesh mesh = make_cube();
  const InsertEdgeResult merged =
      insert_edge(mesh, mesh.halfedge(Face(1)), mesh.halfedge(Face(0)));  // top to bottom
  ASSERT_FALSE(merged.split);
  const InsertEdgeResult split = insert_edge(mesh, HalfedgeMesh::halfedge(merged.edge, 0),
                                             HalfedgeMesh::halfedge(merged.edge, 1));
  ASSERT_TRUE(split.split);
  ASSERT_TRUE(find_problems(mesh).empty());
  std::unique_ptr<CatmullClarkSurface> cc;
  try {
    cc = std::make_unique<CatmullClarkSurface>(mesh);
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot handle"), std::string::npos) << e.what();
    return;
  }
  EXPECT_LT(largest_side_gap(mesh, *cc), 1e-9 * mesh_size(mesh));  // as for the shapes above
}

}  // namespace
}  // namespace stitch
