// K-gons, control nets and the continuity of the evaluated surface (method.md sections 2-6).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "stitch/analysis/continuity.hpp"
#include "stitch/eval/surface.hpp"
#include "stitch/mesh/polygon.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/topology/operation.hpp"
#include "stitch/topology/primitives.hpp"
#include "test_support.hpp"

namespace stitch {
namespace {

TEST(DooSabin, WeightsSumToOne) {
  for (int n = 2; n <= 12; ++n) {
    const auto a = doo_sabin_weights(n);
    double sum = 0;
    for (double w : a) sum += w;
    EXPECT_NEAR(sum, 1.0, 1e-15) << n;
  }
  EXPECT_DOUBLE_EQ(doo_sabin_weights(4)[0], 0.25 + 5.0 / 16.0);
  EXPECT_DOUBLE_EQ(doo_sabin_weights(4)[2], 1.0 / 16.0);
}

TEST(Kgons, EveryCornerHasFourPointsAndExtraordinaryKgonsArePlanar) {
  const HalfedgeMesh mesh = read_mesh(test::opensubdiv_shape("catmark_pyramid.obj"));
  const KgonSet k = build_kgons(mesh);
  for (Halfedge h : mesh.halfedges()) {
    EXPECT_GE(k.in_face[h.idx], 0);
    EXPECT_GE(k.in_vertex[h.idx], 0);
    EXPECT_GE(k.in_next_edge[h.idx], 0);
    EXPECT_GE(k.in_prev_edge[h.idx], 0);
  }
  auto check_planar = [](const Kgon& g) {
    if (g.size() == 4) return;
    for (const Vec3& p : g.points) EXPECT_LT(std::abs((p - g.centroid).dot(g.normal)), 1e-13);
  };
  for (Face f : mesh.faces()) check_planar(k.face[f.idx]);
  for (Vertex v : mesh.vertices()) check_planar(k.vertex[v.idx]);
}

TEST(Kgons, FourGonAndTriangleNormalsAreNewellNormalsAndPlanarOnesTheFitsNormal) {
  // 4-gons are not flattened and not fitted (kgon.hpp): the normal is the normalized Newell
  // normal. On the pyramid, every K-gon of a quad face is planar (the shrink of a planar quad),
  // so there it is also the least-squares plane's normal: each point's distance from the plane
  // through the centroid is round-off of the coordinates' size (about 1, so 1e-13 allows a few
  // hundred ulps). Triangles (its base vertices have valence 3) are their own plane: the normal
  // is their Newell normal and the points are the shrink of the corner points, not moved.
  const HalfedgeMesh mesh = read_mesh(test::opensubdiv_shape("catmark_pyramid.obj"));
  const KgonSet k = build_kgons(mesh);
  int planar = 0, triangles = 0;
  auto check = [&](const Kgon& g, bool is_planar) {
    if (g.size() == 3) {
      ++triangles;
      EXPECT_EQ(g.normal, newell_normal(g.points).normalized());
      std::vector<Vec3> corner_points;
      for (Corner c : g.corners) corner_points.push_back(k.corner_point[c.idx]);
      EXPECT_EQ(g.points, doo_sabin_shrink(corner_points));
      return;
    }
    if (g.size() != 4) return;
    EXPECT_EQ(g.normal, newell_normal(g.points).normalized());
    if (!is_planar) return;
    ++planar;
    for (const Vec3& p : g.points) EXPECT_LT(std::abs((p - g.centroid).dot(g.normal)), 1e-13);
  };
  for (Face f : mesh.faces()) check(k.face[f.idx], true);
  for (Vertex v : mesh.vertices()) check(k.vertex[v.idx], false);
  for (Edge e : mesh.edges()) check(k.edge[e.idx], false);
  EXPECT_GT(planar, 0);
  EXPECT_GT(triangles, 0);
}
TEST(Kgons, ControlsScaleRotateAndRegularize) {
  const HalfedgeMesh mesh = test::cube_mesh();
  const KgonSet plain = build_kgons(mesh);
  KgonOptions opt;
  opt.global.scale = 0.5;
  opt.global.rotate_deg = 90;
  const KgonSet changed = build_kgons(mesh, opt);
  const Kgon& a = plain.vertex[0];
  const Kgon& b = changed.vertex[0];
  ASSERT_EQ(a.size(), 3);
  for (int i = 0; i < 3; ++i) {
    const Vec3 ra = a.points[i] - a.centroid, rb = b.points[i] - b.centroid;
    EXPECT_NEAR(rb.norm(), 0.5 * ra.norm(), 1e-14);
    EXPECT_NEAR(angle_deg(ra, rb), 90.0, 1e-9);
    EXPECT_GT(ra.cross(rb).dot(a.normal), 0);  // counter-clockwise about the normal
  }
  // Quads (the cube's faces) are not extraordinary: the global controls leave them alone.
  EXPECT_EQ(plain.face[0].points, changed.face[0].points);
  // A regular triangle is already affinely regular: regularizing keeps it.
  KgonOptions reg;
  reg.global.regularize = true;
  const KgonSet r = build_kgons(mesh, reg);
  for (int i = 0; i < 3; ++i) EXPECT_LT((r.vertex[0].points[i] - a.points[i]).norm(), 1e-14);
}

TEST(Kgons, StretchScalesAlongOneDirectionOfThePlane) {
  // The cube's vertex 0 K-gon is a triangle in a plane with normal along a space diagonal. A
  // stretch of 2 along a direction with a component along the normal acts on the direction's
  // projection d into the plane: each point's offset from the centroid keeps its part across d
  // and doubles its part along d. Along the normal itself nothing changes. Tolerances: a few
  // units of round-off on coordinates of size 1.
  const HalfedgeMesh mesh = test::cube_mesh();
  const Kgon plain = build_kgons(mesh).vertex[0];
  const Vec3 n = plain.normal;
  const Vec3 direction(1, 0, 0);
  const Vec3 d = (direction - direction.dot(n) * n).normalized();
  KgonOptions opt;
  opt.vertex[0] = KgonControl{.stretch = 2, .stretch_along = direction};
  const Kgon stretched = build_kgons(mesh, opt).vertex[0];
  ASSERT_EQ(stretched.size(), 3);
  for (int i = 0; i < 3; ++i) {
    const Vec3 before = plain.points[i] - plain.centroid;
    const Vec3 after = stretched.points[i] - stretched.centroid;
    EXPECT_NEAR(after.dot(d), 2 * before.dot(d), 1e-14);
    EXPECT_NEAR((after - after.dot(d) * d).norm(), (before - before.dot(d) * d).norm(), 1e-14);
    EXPECT_NEAR(after.dot(n), 0, 1e-14);  // still in the plane
  }
  opt.vertex[0] = KgonControl{.stretch = 2, .stretch_along = n};
  const Kgon along_normal = build_kgons(mesh, opt).vertex[0];
  for (int i = 0; i < 3; ++i) EXPECT_LT((along_normal.points[i] - plain.points[i]).norm(), 1e-14);
}

TEST(ControlNets, BoundaryPointsAreMidpointsAndNeighboursShareCurves) {
  const HalfedgeMesh mesh = read_mesh(test::opensubdiv_shape("catmark_pyramid.obj"));
  const BezierSurface s = build_bezier_surface(mesh);
  for (Halfedge h : mesh.halfedges()) {
    const ControlNet& n = s.nets[h.idx];
    for (int side = 0; side < 4; ++side) {
      const PatchNeighbour nb = neighbour_across(mesh, h, side);
      for (double t : {0.0, 0.25, 0.5, 1.0}) {
        const auto [u0, v0] = side_point(side, t);
        const auto [u1, v1] = side_point(nb.side, t);
        const Vec3 a = evaluate_polynomial(n, u0, v0).position;
        const Vec3 b = evaluate_polynomial(s.nets[nb.corner.idx], u1, v1).position;
        EXPECT_LT((a - b).norm(), 1e-12) << "corner " << h.idx << " side " << side;
      }
    }
    // C1 structure: P10 is the midpoint of P11 and the neighbour's P11 across side 0.
    const ControlNet& n0 = s.nets[mesh.rotate_cw(h).idx];
    EXPECT_LT((n.at(1, 0) - 0.5 * (n.at(1, 1) + n0.at(1, 1))).norm(), 1e-14);
  }
}

TEST(Surface, NormalsPointOutwardOnConvexMeshes) {
  for (const char* name : {"catmark_cube.obj", "loop_tetrahedron.obj", "loop_icosahedron.obj"}) {
    const HalfedgeMesh mesh = read_mesh(test::opensubdiv_shape(name));
    Vec3 centre = Vec3::Zero();
    for (Vertex v : mesh.vertices()) centre += mesh.position(v);
    centre /= mesh.num_vertices();
    for (Method m : {Method::mdc, Method::asc}) {
      const Surface s(mesh, m);
      for (Corner c : s.corners())
        for (double u : {0.0, 0.3, 1.0})
          for (double v : {0.0, 0.6, 1.0}) {
            const SurfacePoint p = s.evaluate(c, u, v);
            EXPECT_GT(p.normal.dot(p.position - centre), 0) << name;
          }
    }
  }
}

// The paper's claim as numbers (method.md section 6). mdc: exact evaluation makes the normal
// jump across every boundary a matter of round-off; 1e-8 degrees is ~1e-10 rad, some 10^5 times
// double epsilon, leaving room for the ~40 nested splits at t = 2^-12 but nothing more.
TEST(Continuity, MdcIsC1AcrossEveryBoundaryOfEveryClosedSharedMesh) {
  for (const std::string& name : test::closed_opensubdiv_shapes()) {
    const HalfedgeMesh mesh = read_mesh(test::opensubdiv_shape(name));
    const ContinuityReport r = analyze_continuity(mesh, Surface(mesh, Method::mdc));
    EXPECT_LT(r.touching_ev.max_deg, 1e-8) << name;
    EXPECT_LT(r.away_from_ev.max_deg, 1e-8) << name;
    EXPECT_LT(r.max_gap, 1e-12) << name;
    EXPECT_LT(r.ev_normal_spread_deg, 1e-8) << name;
  }
}

TEST(Continuity, MdcIsC1OnTheBundledExamples) {
  for (const char* name :
       {"cube.obj", "tetrahedron.obj", "torus.obj", "cube_hole.obj", "two_cubes.obj"}) {
    const HalfedgeMesh mesh = read_mesh(test::example_path(name));
    const ContinuityReport r = analyze_continuity(mesh, Surface(mesh, Method::mdc));
    EXPECT_LT(r.touching_ev.max_deg, 1e-8) << name;
    EXPECT_LT(r.away_from_ev.max_deg, 1e-8) << name;
  }
}

TEST(Continuity, AscKinksNearExtraordinaryPoints) {
  for (const HalfedgeMesh& mesh : {test::cube_mesh(), test::tetrahedron_mesh()}) {
    const ContinuityReport r = analyze_continuity(mesh, Surface(mesh, Method::asc));
    EXPECT_GT(r.touching_ev.max_deg, 1.0);
    // Still G1 at the extraordinary points themselves (planar K-gons).
    EXPECT_LT(r.ev_normal_spread_deg, 1e-8);
  }
}

TEST(Surface, TwoGonsGiveFiniteOutput) {
  // A "pillow": two triangles glued along... instead, a valence-2 vertex: subdivide-like
  // polygon soup of a tetrahedron with one edge split by a vertex of valence 2.
  PolygonSoup s;
  s.positions = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, 0, 0}};
  s.faces = {{0, 4, 1, 2}, {0, 2, 3}, {0, 3, 1, 4}, {1, 3, 2}};
  const HalfedgeMesh mesh = build_mesh(s);
  ASSERT_EQ(mesh.valence(Vertex(4)), 2);
  for (Method m : {Method::mdc, Method::asc}) {
    const Surface surf(mesh, m);
    for (Corner c : surf.corners())
      for (double u : {0.0, 0.5, 1.0})
        for (double v : {0.0, 0.5, 1.0}) {
          const SurfacePoint p = surf.evaluate(c, u, v);
          EXPECT_TRUE(p.position.allFinite());
          EXPECT_TRUE(p.normal.allFinite());
          EXPECT_NEAR(p.normal.norm(), 1.0, 1e-12);
        }
  }
}

// A rebuilt surface is the one a new Surface would be, bit for bit, whatever the rebuilt one held
// before: a larger or smaller mesh, with or without unused half-edge indices and boundaries.
TEST(Surface, RebuildMakesTheSurfaceANewOneWouldBe) {
  HalfedgeMesh gaps = make_torus(8, 6);
  apply_operation(gaps, "delete-face 1");
  ASSERT_LT(gaps.num_halfedges(), static_cast<size_t>(gaps.halfedge_capacity()));
  PolygonSoup grid;  // four quads: a boundary, whose hole's corners make no patch
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) grid.positions.emplace_back(i, j, 0.1 * i * j);
  grid.faces = {{0, 1, 4, 3}, {1, 2, 5, 4}, {3, 4, 7, 6}, {4, 5, 8, 7}};
  const HalfedgeMesh boundary = build_mesh(grid);
  const std::vector<HalfedgeMesh> meshes = {make_torus(12, 8), gaps, make_torus(9, 5), boundary,
                                            test::cube_mesh()};
  for (Method method : {Method::mdc, Method::asc, Method::cc}) {
    Surface rebuilt(make_torus(16, 10), method);
    for (const HalfedgeMesh& mesh : meshes) {
      rebuilt.rebuild(mesh);
      const Surface fresh(mesh, method);
      ASSERT_EQ(rebuilt.corners(), fresh.corners());
      EXPECT_TRUE(rebuilt.bezier().nets == fresh.bezier().nets) << to_string(method);
      for (Corner c : fresh.corners())
        for (double u : {0.0, 0.3, 1.0})
          for (double v : {0.0, 0.7}) {
            EXPECT_EQ(rebuilt.evaluate(c, u, v).position, fresh.evaluate(c, u, v).position);
            EXPECT_EQ(rebuilt.evaluate(c, u, v).normal, fresh.evaluate(c, u, v).normal);
          }
    }
  }
}

// A mesh the surface cannot be built on is refused before the surface changes.
TEST(Surface, RebuildRefusesATinyMeshAndKeepsTheSurface) {
  const HalfedgeMesh cube = test::cube_mesh();
  HalfedgeMesh tiny = cube;
  for (Vertex v : tiny.vertices()) tiny.position(v) *= 1e-300;
  Surface surface(cube, Method::mdc);
  const std::vector<ControlNet> before = surface.bezier().nets;
  EXPECT_THROW(surface.rebuild(tiny), InputError);
  EXPECT_TRUE(surface.bezier().nets == before);
}

}  // namespace
}  // namespace stitch
