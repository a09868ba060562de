// The Catmull-Clark comparison surface (--method cc) with the mesh's feature tags: holes as the
// surface's boundary, crease and corner sharpness, and the boundary interpolation option, all
// as OpenSubdiv defines them.
#include <gtest/gtest.h>
#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/primvarRefiner.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "mesh/opensubdiv_topology.hpp"
#include "stitch/eval/catmull_clark.hpp"
#include "stitch/mesh/build.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/topology/primitives.hpp"
#include "stitch/topology/remesh.hpp"
#include "test_support.hpp"
#include "topology/catmark_refinement.hpp"

namespace stitch {
namespace {

namespace Osd = OpenSubdiv;
using BI = BoundaryInterpolation;

const std::vector<std::string> kBoundaryShapes{"catmark_pawn", "catmark_bishop", "catmark_rook",
                                               "catmark_car", "catmark_nonquads"};
const std::vector<double> kSamples{0.0, 0.25, 0.5, 0.8, 1.0};

HalfedgeMesh load(const std::string& name) {
  return read_mesh(test::opensubdiv_shape(name + ".obj"));
}

using test::mesh_size;

bool finite(const SurfacePoint& p) {
  return p.position.allFinite() && p.du.allFinite() && p.dv.allFinite() && p.normal.allFinite();
}

bool has_hole(const HalfedgeMesh& mesh) {
  return mesh.surface_faces().size() < static_cast<size_t>(mesh.num_faces());
}

std::vector<int> surface_face_numbers(const HalfedgeMesh& mesh) {
  std::vector<int> number(static_cast<size_t>(mesh.face_capacity()), -1);
  const auto faces = mesh.surface_faces();
  for (size_t i = 0; i < faces.size(); ++i) number[faces[i].idx] = static_cast<int>(i);
  return number;
}

// An n x n grid of quads in the xy plane, bumped in z so that no rule is hidden by flatness; its
// boundary loop becomes a hole face. Vertex (i, j) is j * (n + 1) + i.
HalfedgeMesh grid(int n) {
  PolygonSoup soup;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      soup.positions.emplace_back(i, j, 0.3 * std::sin(1.7 * i + 0.9 * j));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      soup.faces.push_back({a, a + 1, a + n + 2, a + n + 1});
    }
  return build_mesh(soup);
}

struct Point {
  Vec3 p = Vec3::Zero();
  void Clear() { p.setZero(); }
  void AddWithWeight(const Point& o, double w) { p += w * o.p; }
};

// OpenSubdiv's own uniform level 1 of the mesh, from its face-vertex description (catmark_refiner:
// Vtr finds the boundary, sharpens it and places the tags itself), and optionally the limit
// positions of the level-1 vertices (PrimvarRefiner::Limit).
struct FarLevel1 {
  std::unique_ptr<Osd::Far::TopologyRefiner> refiner;
  std::vector<Point> points, limit;
};

FarLevel1 far_level1(const HalfedgeMesh& mesh, BI boundary, bool with_limit) {
  FarLevel1 out;
  out.refiner = catmark_refiner(mesh, boundary);
  Osd::Far::TopologyRefiner::UniformOptions uniform(1);
  uniform.fullTopologyInLastLevel = with_limit;  // Limit() needs the vertex neighbourhoods
  out.refiner->RefineUniform(uniform);
  std::vector<Point> level0(static_cast<size_t>(mesh.num_vertices()));
  for (Vertex v : mesh.vertices()) level0[v.idx].p = mesh.position(v);
  out.points.resize(static_cast<size_t>(out.refiner->GetLevel(1).GetNumVertices()));
  const Osd::Far::PrimvarRefinerReal<double> primvar(*out.refiner);
  Point* src = level0.data();
  Point* dst = out.points.data();
  primvar.Interpolate(1, src, dst);
  if (with_limit) {
    out.limit.resize(out.points.size());
    Point* limit = out.limit.data();
    primvar.Limit(dst, limit);
  }
  return out;
}

// Where corner c's patch has its vertex, edge midpoint and face centre in OpenSubdiv's level 1.
std::array<int, 3> level1_points(const HalfedgeMesh& mesh, const Osd::Far::TopologyLevel& level0,
                                 const std::vector<int>& face_number, Corner c) {
  const int v = mesh.origin(c).idx, w = mesh.target(c).idx;
  return {level0.GetVertexChildVertex(v), level0.GetEdgeChildVertex(level0.FindEdge(v, w)),
          level0.GetFaceChildVertex(face_number[mesh.face(c).idx])};
}

// OpenSubdiv's Bfr surface of the mesh's face-vertex description, at corner c's (u, v): the
// same corner-patch mapping as CatmullClarkSurface (checked against the patch sides in
// test_catmull_clark.cpp), but with the topology, the boundary and the tags found by Vtr
// from the description instead of given in full.
class DescriptorSurface {
 public:
  DescriptorSurface(const HalfedgeMesh& mesh, BI boundary)
      : mesh_(mesh),
        refiner_(catmark_refiner(mesh, boundary)),
        face_number_(surface_face_numbers(mesh)) {
    const Osd::Bfr::RefinerSurfaceFactory<> factory(*refiner_);
    const auto faces = mesh.surface_faces();
    surfaces_.resize(faces.size());
    points_.resize(faces.size());
    std::vector<double> xyz;
    for (Vertex v : mesh.vertices())
      for (int k = 0; k < 3; ++k) xyz.push_back(mesh.position(v)[k]);
    for (size_t f = 0; f < faces.size(); ++f) {
      if (!factory.InitVertexSurface(static_cast<int>(f), &surfaces_[f]))
        throw Error("Bfr gives face " + std::to_string(faces[f].idx + 1) + " no surface");
      points_[f].resize(3 * static_cast<size_t>(surfaces_[f].GetNumPatchPoints()));
      surfaces_[f].PreparePatchPoints(xyz.data(), kXyz, points_[f].data(), kXyz);
    }
  }

  [[nodiscard]] Vec3 position(Corner c, double u, double v) const {
    const auto f = static_cast<size_t>(face_number_[mesh_.face(c).idx]);
    const int k = mesh_.index_in_face(c);
    const Osd::Bfr::Parameterization param = surfaces_[f].GetParameterization();
    double st[2];
    if (param.GetType() == Osd::Bfr::Parameterization::QUAD) {
      static constexpr double kCorner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      for (int i = 0; i < 2; ++i)
        st[i] = kCorner[k][i] + 0.5 * u * (kCorner[(k + 1) % 4][i] - kCorner[k][i]) +
                0.5 * v * (kCorner[(k + 3) % 4][i] - kCorner[k][i]);
    } else {
      const double sub[2] = {u, v};
      param.ConvertNormalizedSubFaceToCoord(k, sub, st);
    }
    double p[3];
    surfaces_[f].Evaluate(st, points_[f].data(), kXyz, p);
    return {p[0], p[1], p[2]};
  }

 private:
  static inline const Osd::Bfr::Surface<double>::PointDescriptor kXyz{3};
  const HalfedgeMesh& mesh_;
  std::unique_ptr<Osd::Far::TopologyRefiner> refiner_;
  std::vector<int> face_number_;
  std::vector<Osd::Bfr::Surface<double>> surfaces_;
  std::vector<std::vector<double>> points_;
};

// The largest distance between cc and OpenSubdiv's Bfr surface of the face-vertex description,
// over a grid of points of every patch.
double largest_difference_from_descriptor(const HalfedgeMesh& mesh, BI boundary) {
  const CatmullClarkSurface cc(mesh, boundary);
  const DescriptorSurface osd(mesh, boundary);
  double largest = 0;
  for (Corner c : mesh.patch_corners())
    for (double u : kSamples)
      for (double v : kSamples)
        largest = std::max(largest, (cc.evaluate(c, u, v).position - osd.position(c, u, v)).norm());
  return largest;
}

class CcBoundaryShapes : public ::testing::TestWithParam<std::string> {};

TEST_P(CcBoundaryShapes, EveryPatchCornerEvaluatesFinitely) {
  const HalfedgeMesh mesh = load(GetParam());
  ASSERT_TRUE(has_hole(mesh)) << GetParam();
  for (BI boundary : {BI::edge_and_corner, BI::edge_only}) {
    const CatmullClarkSurface cc(mesh, boundary);
    for (Corner c : mesh.patch_corners())
      for (double u : kSamples)
        for (double v : kSamples)
          ASSERT_TRUE(finite(cc.evaluate(c, u, v))) << GetParam() << " corner " << c.idx;
  }
}

// The patch corners at a vertex, an edge midpoint and a face centre are limit points of
// OpenSubdiv's level-1 vertices, which Far::PrimvarRefiner::Limit computes by another route
// (limit masks, Vtr's own boundary sharpening). Limit masks are exact only where no semi-sharp
// tag is left to decay, so the shapes' creases (sharpness 6) are cleared here; the tagged shapes
// are compared with Bfr below. The two routes agree up to the round-off of stencils of
// different length: measured ~1e-15 of the size; 1e-9 of the size (as in test_catmull_clark.cpp)
// is far from any rule mistake, which moves boundary points by a fraction of an edge.
TEST_P(CcBoundaryShapes, BoundaryLimitPointsAreOpenSubdivsLimitPositions) {
  HalfedgeMesh mesh = load(GetParam());
  ASSERT_FALSE(mesh.has_garbage());
  for (Edge e : mesh.edges()) mesh.set_sharpness(e, 0.0);
  for (Vertex v : mesh.vertices()) mesh.set_sharpness(v, 0.0);
  const double tol = 1e-9 * mesh_size(mesh);
  const std::vector<int> face_number = surface_face_numbers(mesh);
  for (BI boundary : {BI::edge_and_corner, BI::edge_only}) {
    const CatmullClarkSurface cc(mesh, boundary);
    const FarLevel1 far = far_level1(mesh, boundary, true);
    const Osd::Far::TopologyLevel& level0 = far.refiner->GetLevel(0);
    ASSERT_EQ(level0.GetNumFaces(), static_cast<int>(mesh.surface_faces().size()));
    int boundary_points = 0;
    for (Corner c : mesh.patch_corners()) {
      const auto ids = level1_points(mesh, level0, face_number, c);
      const bool on_boundary = mesh.is_boundary(HalfedgeMesh::edge(c));
      boundary_points += on_boundary ? 1 : 0;
      const std::array<std::array<double, 2>, 3> uv{{{0, 0}, {1, 0}, {1, 1}}};
      for (int i = 0; i < 3; ++i) {
        const Vec3 p = cc.evaluate(c, uv[i][0], uv[i][1]).position;
        ASSERT_LT((p - far.limit[static_cast<size_t>(ids[i])].p).norm(), tol)
            << GetParam() << " corner " << c.idx << " point " << i << " boundary edge "
            << on_boundary;
      }
    }
    EXPECT_GT(boundary_points, 0) << GetParam();
  }
}

// With the shapes' creases: cc gives its topology to OpenSubdiv in full (holes left out, tags
// attached to the edges), the reference lets OpenSubdiv infer it from faces and vertex pairs.
// Both evaluate the same Bfr patches, so they agree to round-off (measured: identical); 1e-12 of
// the size allows for different orders of the same sums.
TEST_P(CcBoundaryShapes, SurfaceIsBfrsOfTheFaceVertexDescription) {
  const HalfedgeMesh mesh = load(GetParam());
  for (BI boundary : {BI::edge_and_corner, BI::edge_only})
    EXPECT_LT(largest_difference_from_descriptor(mesh, boundary), 1e-12 * mesh_size(mesh))
        << GetParam() << " edge_only " << (boundary == BI::edge_only);
}

// The step the refinement route takes for topology OpenSubdiv cannot hold must be Far's uniform
// level 1 at every point of the surface: vertex points by Sdc's crease, corner and boundary
// masks (fractional sharpness blended), edge points by the crease mask, and the tags handed
// on. Same sums in possibly different order: 1e-12 of the size.
TEST_P(CcBoundaryShapes, RefinementWithFeaturesIsFarsLevel1) {
  HalfedgeMesh mesh = load(GetParam());
  // Fractional tags (blended masks) besides the shapes' own creases of sharpness 6.
  const auto edges = mesh.edges().to_vector();
  for (size_t i = 0; i < edges.size(); i += 7)
    if (!mesh.is_boundary(edges[i]))
      mesh.set_sharpness(edges[i], 0.3 + 0.1 * static_cast<double>(i % 23));
  const auto vertices = mesh.vertices().to_vector();
  for (size_t i = 0; i < vertices.size(); i += 11) mesh.set_sharpness(vertices[i], 0.5 + (i % 3));
  const double tol = 1e-12 * mesh_size(mesh);
  const std::vector<int> face_number = surface_face_numbers(mesh);
  for (BI boundary : {BI::edge_and_corner, BI::edge_only}) {
    const CatmullClarkRefinement step = catmark_refinement_with_features(mesh, boundary);
    const HalfedgeMesh& fine = step.mesh;
    const FarLevel1 far = far_level1(mesh, boundary, false);
    const Osd::Far::TopologyLevel& level0 = far.refiner->GetLevel(0);
    for (Corner c : mesh.halfedges()) {
      const Face quad = step.corner_quad[c.idx];
      ASSERT_EQ(fine.is_hole(quad), mesh.is_hole(c));
      if (mesh.is_hole(c)) continue;
      const auto ids = level1_points(mesh, level0, face_number, c);
      const Halfedge h = fine.halfedge(quad);
      const Vertex ours[3] = {fine.origin(h), fine.origin(fine.next(h)),
                              fine.origin(fine.next(fine.next(h)))};
      for (int i = 0; i < 3; ++i)
        ASSERT_LT((fine.position(ours[i]) - far.points[static_cast<size_t>(ids[i])].p).norm(), tol)
            << GetParam() << " corner " << c.idx << " point " << i;
      // Uniform creasing: one less per step, down to smooth; infinite stays infinite.
      const double s = mesh.sharpness(HalfedgeMesh::edge(c));
      const double child = s >= infinitely_sharp ? infinitely_sharp : std::max(0.0, s - 1.0);
      if (!mesh.is_boundary(HalfedgeMesh::edge(c))) {
        ASSERT_NEAR(fine.sharpness(HalfedgeMesh::edge(h)), child, 1e-6);  // float in Sdc
      }
      ASSERT_NEAR(fine.sharpness(ours[0]), std::max(0.0, mesh.sharpness(mesh.origin(c)) - 1.0),
                  1e-6);
    }
  }
}

// The refinement route's surface (one step, then Bfr with its approximation levels reduced by
// the step) is the direct route's: corner c's patch is its refined quad, whose corner patch at
// quad corner 0 is c's patch scaled by one half. Measured below 1e-14 of the size; 1e-10 allows
// for the different stencils and is far below what a wrong rule gives (a fraction of an edge).
TEST_P(CcBoundaryShapes, RefinementRouteGivesTheSameSurface) {
  const HalfedgeMesh mesh = load(GetParam());
  const double tol = 1e-10 * mesh_size(mesh);
  for (BI boundary : {BI::edge_and_corner, BI::edge_only}) {
    const CatmullClarkSurface direct(mesh, boundary);
    const CatmullClarkRefinement step = catmark_refinement_with_features(mesh, boundary);
    const CatmullClarkSurface refined(step.mesh, 1, boundary);
    for (Corner c : mesh.patch_corners()) {
      const Corner q = step.mesh.halfedge(step.corner_quad[c.idx]);
      for (double u : kSamples)
        for (double v : kSamples)
          ASSERT_LT(
              (direct.evaluate(c, 0.5 * u, 0.5 * v).position - refined.evaluate(q, u, v).position)
                  .norm(),
              tol)
              << GetParam() << " corner " << c.idx << " at " << u << ", " << v;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(OpenSubdivShapes, CcBoundaryShapes, ::testing::ValuesIn(kBoundaryShapes));

// The cube [-1,1]^3 with every edge infinitely sharp is the cube: every vertex has three sharp
// edges (a corner), every edge point is the edge's midpoint and every face is refined from its
// own four vertices only, so each face's surface lies in its plane up to round-off (1e-12 of
// the size; a smooth face bulges by a tenth of it).
void expect_flat_faces_and_corners(const HalfedgeMesh& mesh, const std::vector<Face>& faces,
                                   const char* what) {
  const CatmullClarkSurface cc(mesh);
  const double tol = 1e-12 * mesh_size(mesh);
  for (Face f : faces) {
    const auto loop = mesh.face_loop(f);
    const Vec3 a = mesh.position(mesh.origin(loop[0]));
    const Vec3 n = (mesh.position(mesh.origin(loop[1])) - a)
                       .cross(mesh.position(mesh.origin(loop[2])) - a)
                       .normalized();
    for (Corner c : loop) {
      EXPECT_LT((cc.evaluate(c, 0, 0).position - mesh.position(mesh.origin(c))).norm(), tol)
          << what << " vertex " << mesh.origin(c).idx;
      for (double u : kSamples)
        for (double v : kSamples)
          ASSERT_LT(std::abs(n.dot(cc.evaluate(c, u, v).position - a)), tol)
              << what << " face " << f.idx << " corner " << c.idx << " at " << u << ", " << v;
    }
  }
}

TEST(CcFeatures, CubeWithAllEdgesInfinitelySharpHasFlatFaces) {
  HalfedgeMesh cube = make_cube();
  ASSERT_EQ(cube.num_edges(), 12);
  for (Edge e : cube.edges()) cube.set_sharpness(e, infinitely_sharp);
  expect_flat_faces_and_corners(cube, cube.faces().to_vector(), "sharp cube");

  // Without the tags the faces bulge: the check above can fail.
  const CatmullClarkSurface smooth(make_cube());
  const SurfacePoint centre = smooth.evaluate(cube.halfedge(Face(0)), 1, 1);
  EXPECT_GT(std::abs(std::abs(centre.position.z()) - 1.0), 0.1);
}

// The same through the refinement route: a 2-sided face doubling one sharp edge (what the
// topology operators create) sends cc through its own Catmull-Clark step, which must apply the
// crease and corner rules too.
TEST(CcFeatures, SharpCubeWithATwoSidedFaceHasFlatFacesThroughTheRefinementRoute) {
  HalfedgeMesh mesh = make_cube();
  const Face two_gon = test::double_with_two_gon(mesh, mesh.halfedge(Face(0)));
  for (Edge e : mesh.edges()) mesh.set_sharpness(e, infinitely_sharp);
  std::vector<Face> cube_faces = mesh.faces().to_vector();
  std::erase(cube_faces, two_gon);
  ASSERT_EQ(cube_faces.size(), 6U);
  expect_flat_faces_and_corners(mesh, cube_faces, "sharp cube with a 2-gon");
}

// An infinitely sharp vertex is a corner: the surface passes through it (to round-off, 1e-12 of
// the size); untagged, the limit point of a cube vertex lies well inside.
TEST(CcFeatures, CornerTagMakesTheSurfacePassThroughTheVertex) {
  HalfedgeMesh cube = make_cube();
  const Vertex v(0);
  const Corner c = cube.halfedge(v);
  const double size = mesh_size(cube);
  const Vec3 smooth = CatmullClarkSurface(cube).evaluate(c, 0, 0).position;
  EXPECT_GT((smooth - cube.position(v)).norm(), 0.1 * size);
  cube.set_sharpness(v, infinitely_sharp);
  const CatmullClarkSurface cc(cube);
  for (Corner k : cube.vertex_fan(v))
    EXPECT_LT((cc.evaluate(k, 0, 0).position - cube.position(v)).norm(), 1e-12 * size);
  // The other vertices keep their smooth limit points away from the mesh.
  EXPECT_GT(
      (cc.evaluate(cube.halfedge(Vertex(6)), 0, 0).position - cube.position(Vertex(6))).norm(),
      0.1 * size);
}

// A boundary vertex with a single face: edge-and-corner interpolates it; edge-only puts it on
// the boundary's cubic B-spline, whose limit point is (a + 4v + b) / 6 for its boundary
// neighbours a and b. Boundary vertices with two faces follow the B-spline either way. Exact
// formulas, so round-off tolerances (1e-12 of the size).
void expect_boundary_interpolation(const HalfedgeMesh& mesh, const char* what) {
  const double tol = 1e-12 * mesh_size(mesh);
  const CatmullClarkSurface corners(mesh, BI::edge_and_corner), edges(mesh, BI::edge_only);
  int single_face = 0;
  for (Vertex v : mesh.vertices()) {
    const SurfaceRing ring = surface_ring(mesh, v);
    if (!ring.boundary()) continue;
    const Corner c = ring.faces.front();
    const Vec3 a = mesh.position(mesh.target(ring.edges.front()));
    const Vec3 b = mesh.position(mesh.target(ring.edges.back()));
    const Vec3 spline = (a + 4 * mesh.position(v) + b) / 6;
    const Vec3 p_corner = corners.evaluate(c, 0, 0).position;
    const Vec3 p_edge = edges.evaluate(c, 0, 0).position;
    EXPECT_LT((p_edge - spline).norm(), tol) << what << " vertex " << v.idx;
    if (ring.faces.size() == 1) {
      ++single_face;
      EXPECT_LT((p_corner - mesh.position(v)).norm(), tol) << what << " vertex " << v.idx;
      EXPECT_GT((p_corner - p_edge).norm(), 1e-3 * mesh_size(mesh)) << what;
    } else {
      EXPECT_LT((p_corner - spline).norm(), tol) << what << " vertex " << v.idx;
    }
  }
  EXPECT_GT(single_face, 0) << what;
}

TEST(CcFeatures, EdgeOnlyAndEdgeAndCornerDifferAtSingleFaceBoundaryVertices) {
  expect_boundary_interpolation(grid(3), "3x3 grid");
  PolygonSoup quad;
  quad.positions = {{0, 0, 0}, {2, 0, 0.5}, {2, 1, 0}, {0, 1.5, 0.2}};
  quad.faces = {{0, 1, 2, 3}};
  const HalfedgeMesh one_face = build_mesh(quad);
  ASSERT_EQ(one_face.surface_faces().size(), 1U);
  expect_boundary_interpolation(one_face, "one quad");
}

// A semi-sharp crease lies between smooth and infinitely sharp: it pulls the surface towards
// the edge, less than a crease does, and is OpenSubdiv's own semi-sharp surface (compared with
// Bfr of the face-vertex description as above, 1e-12 of the size).
TEST(CcFeatures, SemiSharpCreasesChangeTheSurface) {
  HalfedgeMesh cube = make_cube();
  const Corner c = cube.halfedge(Face(0));
  const Edge e = HalfedgeMesh::edge(c);
  const Vec3 midpoint = 0.5 * (cube.position(cube.origin(c)) + cube.position(cube.target(c)));
  auto distance_at = [&](double sharpness) {
    cube.set_sharpness(e, sharpness);
    return (CatmullClarkSurface(cube).evaluate(c, 1, 0).position - midpoint).norm();
  };
  const double smooth = distance_at(0.0), semi = distance_at(1.5),
               sharp = distance_at(infinitely_sharp);
  const double size = mesh_size(cube);
  EXPECT_GT(smooth - semi, 1e-3 * size);
  EXPECT_GT(semi - sharp, 1e-3 * size);
  for (double s : {0.4, 1.5, 3.2}) {
    cube.set_sharpness(e, s);
    EXPECT_LT(largest_difference_from_descriptor(cube, BI::edge_and_corner), 1e-12 * size) << s;
  }
  // Semi-sharp tags on the boundary shapes' refinement route are checked in
  // RefinementWithFeaturesIsFarsLevel1; here a semi-sharp corner.
  cube.set_sharpness(e, 0.0);
  cube.set_sharpness(Vertex(3), 2.5);
  EXPECT_LT(largest_difference_from_descriptor(cube, BI::edge_and_corner), 1e-12 * size);
}

// A grid with a 2-sided face inside takes the refinement route; its boundary curve depends on
// the boundary vertices only (the crease rule), so it is the grid's: boundary limit points and
// edge midpoints as on the direct route, to round-off (1e-12 of the size).
TEST(CcFeatures, BoundaryOnTheRefinementRouteIsTheBoundaryCurve) {
  const HalfedgeMesh plain = grid(4);
  HalfedgeMesh mesh = plain;
  // Double the interior edge between vertices (2, 1) and (2, 2) with a 2-gon.
  Halfedge h;
  for (Halfedge x : mesh.halfedges())
    if (mesh.origin(x).idx == 7 && mesh.target(x).idx == 12) h = x;
  ASSERT_TRUE(h.valid());
  test::double_with_two_gon(mesh, h);
  const double tol = 1e-12 * mesh_size(plain);
  for (BI boundary : {BI::edge_and_corner, BI::edge_only}) {
    const CatmullClarkSurface a(plain, boundary), b(mesh, boundary);
    int checked = 0;
    for (Corner c : plain.patch_corners()) {
      if (!plain.is_boundary(HalfedgeMesh::edge(c))) continue;
      ++checked;
      for (double u : kSamples)
        EXPECT_LT((a.evaluate(c, u, 0).position - b.evaluate(c, u, 0).position).norm(), tol)
            << "corner " << c.idx << " u " << u;
    }
    EXPECT_EQ(checked, 16);
    // Inside, the 2-gon does change the surface: the two routes are not trivially the same.
    const Corner inner = plain.next(h);
    EXPECT_GT((a.evaluate(inner, 0, 0).position - b.evaluate(inner, 0, 0).position).norm(), 1e-6);
  }
}

TEST(CcFeatures, HoleCornersHaveNoPatch) {
  const HalfedgeMesh mesh = grid(2);
  const CatmullClarkSurface cc(mesh);
  int holes = 0;
  for (Corner c : mesh.halfedges()) {
    if (!mesh.is_hole(c)) continue;
    ++holes;
    EXPECT_NE(test::error_of([&] { (void)cc.evaluate(c, 0, 0); }).find("outside holes"),
              std::string::npos);
  }
  EXPECT_EQ(holes, 8);
}

// Two holes meeting at one vertex: OpenSubdiv would make it a non-manifold corner, which is not
// the surface of these tags; refused, naming the vertex.
TEST(CcFeatures, BoundaryLoopsMeetingAtAVertexAreRefused) {
  HalfedgeMesh octahedron = make_octahedron();
  // Faces containing +z (vertex 5 in files) on opposite sides share only that vertex.
  const Vertex top(4);
  std::vector<Face> around;
  for (Corner c : octahedron.vertex_fan(top)) around.push_back(octahedron.face(c));
  ASSERT_EQ(around.size(), 4U);
  octahedron.set_hole(around[0], true);
  octahedron.set_hole(around[2], true);
  for (BI boundary : {BI::edge_and_corner, BI::edge_only}) {
    const std::string message =
        test::error_of([&] { const CatmullClarkSurface cc(octahedron, boundary); });
    EXPECT_NE(message.find("vertex 5 "), std::string::npos) << message;
    EXPECT_NE(message.find("boundary"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace stitch
