// The surface check on known geometry: crossing triangles, folded strips, degenerate and
// inconsistently oriented triangles are found, and nothing is found on clean closed surfaces.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <string>

#include "stitch/analysis/surface_check.hpp"
#include "stitch/mesh/build.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/polygon.hpp"
#include "stitch/tess/tessellate.hpp"
#include "stitch/topology/operation.hpp"
#include "stitch/topology/primitives.hpp"
#include "stitch/topology/remesh.hpp"

namespace stitch {
namespace {

TriangleSoup soup_of(std::vector<Vec3> positions, std::vector<std::array<int, 3>> triangles) {
  TriangleSoup s;
  s.positions = std::move(positions);
  s.triangles = std::move(triangles);
  for (size_t i = 0; i < s.triangles.size(); ++i) s.source.push_back(static_cast<int>(i));
  return s;
}

/// A sphere-like quad mesh: the icosahedron refined twice by Catmull-Clark, pushed onto the
/// unit sphere.
PolygonSoup sphere_soup() {
  HalfedgeMesh m = catmull_clark_step(catmull_clark_step(make_icosahedron()));
  for (Vertex v : m.vertices()) m.position(v).normalize();
  return to_polygon_soup(m);
}

TEST(SurfaceCheck, TriangleTriangleTest) {
  const Vec3 a0(0, 0, 0), a1(2, 0, 0), a2(0, 2, 0);
  // Piercing: a triangle standing through the first one.
  EXPECT_TRUE(triangles_intersect(a0, a1, a2, {0.5, 0.5, -1}, {0.5, 0.5, 1}, {3, 3, 0.5}));
  // Above it, parallel.
  EXPECT_FALSE(triangles_intersect(a0, a1, a2, {0, 0, 1}, {2, 0, 1}, {0, 2, 1}));
  // Crossing its plane outside it.
  EXPECT_FALSE(triangles_intersect(a0, a1, a2, {3, 3, -1}, {3, 3, 1}, {5, 5, 0}));
  // Touching at one point (a vertex on the interior) does not count as crossing.
  EXPECT_FALSE(triangles_intersect(a0, a1, a2, {0.5, 0.5, 0}, {0.5, 0.5, 1}, {1, 0.2, 1}));
  // Coplanar: overlapping and apart.
  EXPECT_TRUE(triangles_intersect(a0, a1, a2, {0.5, 0.5, 0}, {3, 0.5, 0}, {0.5, 3, 0}));
  EXPECT_FALSE(triangles_intersect(a0, a1, a2, {3, 3, 0}, {5, 3, 0}, {3, 5, 0}));
}

TEST(SurfaceCheck, FindsTwoCrossingTriangles) {
  const TriangleSoup s =
      soup_of({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, -1}, {0.5, 0.5, 1}, {3, 3, 0.5}},
              {{0, 1, 2}, {3, 4, 5}});
  const SurfaceCheckReport r = check_surface(s);
  EXPECT_EQ(r.self_intersections, 1);
  ASSERT_EQ(r.intersecting_pairs.size(), 1u);
  EXPECT_EQ(r.intersecting_pairs[0], (std::array<int, 2>{0, 1}));
  EXPECT_EQ(r.folds, 0);
  EXPECT_FALSE(r.clean());
}

TEST(SurfaceCheck, FindsCrossingTrianglesSharingAVertex) {
  // Both start at the origin; the second passes through the first's interior.
  const TriangleSoup s = soup_of({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, -1}, {0.5, 0.5, 1}},
                                 {{0, 1, 2}, {0, 3, 4}});
  EXPECT_EQ(check_surface(s).self_intersections, 1);
  // The same fan opened up so that they only meet at the shared vertex.
  const TriangleSoup t =
      soup_of({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {-1, -1, -1}, {-1, -1, 1}}, {{0, 1, 2}, {0, 3, 4}});
  EXPECT_EQ(check_surface(t).self_intersections, 0);
}

TEST(SurfaceCheck, FindsAFoldedStripAndNotAFlatOne) {
  // Two triangles on the edge (0,0,0)-(1,0,0); the second's far vertex swings around the edge.
  auto strip = [](double angle_deg) {
    const double a = angle_deg * 3.14159265358979323846 / 180;
    return soup_of({{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -std::cos(a), std::sin(a)}},
                   {{0, 1, 2}, {1, 0, 3}});
  };
  EXPECT_EQ(check_surface(strip(0)).folds, 0);    // flat
  EXPECT_EQ(check_surface(strip(60)).folds, 0);   // normals 60 degrees apart
  EXPECT_EQ(check_surface(strip(150)).folds, 1);  // folded back over the first
  SurfaceCheckOptions strict;
  strict.fold_angle_deg = 45;
  EXPECT_EQ(check_surface(strip(60), strict).folds, 1);
}

TEST(SurfaceCheck, FindsDegenerateAndInconsistentTriangles) {
  const TriangleSoup d =
      soup_of({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 1, 3}});
  const SurfaceCheckReport r = check_surface(d);
  EXPECT_EQ(r.degenerate, 1);
  ASSERT_EQ(r.degenerate_triangles.size(), 1u);
  EXPECT_EQ(r.degenerate_triangles[0], 0);
  const TriangleSoup flipped =
      soup_of({{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}}, {{0, 1, 2}, {0, 1, 3}});
  EXPECT_EQ(check_surface(flipped).inconsistent_edges, 1);
}

TEST(SurfaceCheck, CleanClosedSurfacesHaveNoProblems) {
  const TriangleSoup sphere = triangulate(sphere_soup());
  const SurfaceCheckReport r = check_surface(sphere);
  EXPECT_EQ(r.triangles, 480);  // 20 triangles -> 60 quads -> 240 quads, split in two
  EXPECT_TRUE(r.clean()) << r.describe(sphere);
  const TriangleSoup torus = triangulate(to_polygon_soup(make_torus(32, 16)));
  EXPECT_TRUE(check_surface(torus).clean()) << check_surface(torus).describe(torus);
}

// The progress told: from one thread at a time, never going back, ending at 1; the report is
// the one of a check without it.
TEST(SurfaceCheck, ProgressRisesToOneAndChangesNothing) {
  const TriangleSoup torus = triangulate(to_polygon_soup(make_torus(64, 32)));
  SurfaceCheckOptions options;
  std::vector<double> told;
  options.progress = [&told](double done) { told.push_back(done); };
  const SurfaceCheckReport r = check_surface(torus, options);
  ASSERT_FALSE(told.empty());
  EXPECT_TRUE(std::is_sorted(told.begin(), told.end()));
  EXPECT_GT(told.front(), 0.0);
  EXPECT_EQ(told.back(), 1.0);
  const SurfaceCheckReport plain = check_surface(torus);
  EXPECT_EQ(r.triangles, plain.triangles);
  EXPECT_TRUE(r.clean()) << r.describe(torus);
}

TEST(SurfaceCheck, SurfaceMeshQuadsAndAPushedThroughVertex) {
  const PolygonSoup sphere = sphere_soup();
  TessellatedMesh surface;
  surface.positions = sphere.positions;
  for (const auto& q : sphere.faces) surface.quads.push_back({q[0], q[1], q[2], q[3]});
  EXPECT_TRUE(check_surface(triangulate(surface)).clean());
  // Pull one vertex through the sphere to the other side: its triangles cross the far side.
  surface.positions[0] = -1.5 * surface.positions[0];
  const SurfaceCheckReport r = check_surface(triangulate(surface));
  EXPECT_GT(r.self_intersections, 0);
}

TEST(SurfaceCheck, SegmentsThroughAndPastTheSurface) {
  const TriangleSoup sphere = triangulate(sphere_soup());
  // Off the axis, so the line meets no vertex or edge (a hit there counts once per triangle).
  const auto through = segment_hits(sphere, {0.1, 0.2, -3}, {0.1, 0.2, 3});
  ASSERT_EQ(through.size(), 2u);
  EXPECT_LT(through[0].t, through[1].t);
  EXPECT_TRUE(segment_hits(sphere, {2, 0, -3}, {2, 0, 3}).empty());
  // The torus hole is open along its axis; a line through the tube is not.
  const TriangleSoup torus = triangulate(to_polygon_soup(make_torus(32, 16)));
  EXPECT_TRUE(segment_hits(torus, {0, 0, -3}, {0, 0, 3}).empty());
  EXPECT_EQ(segment_hits(torus, {2, 0.01, -3}, {2, 0.01, 3}).size(), 2u);
}

TEST(SurfaceCheck, QuadsAreSplitAlongTheirShorterDiagonal) {
  using Tri = std::array<int, 3>;
  // A flat square: both diagonals are as long, and a-c is kept.
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(1, 1, 0), d(0, 1, 0);
  EXPECT_EQ((quad_triangles(std::array{0, 1, 2, 3}, a, b, c, d)),
            (std::array<Tri, 2>{Tri{0, 1, 2}, Tri{0, 2, 3}}));
  // A thin rhombus whose a-c diagonal is the long one (a wedge's cell next to an extraordinary
  // point of high valence), lifted at c: split along b-d, and both triangles keep the quad's
  // orientation (their normals point as the flat rhombus's does, +z).
  const Vec3 p0(0, 0, 0), p1(1, -0.1, 0), p2(2, 0, 0.05), p3(1, 0.1, 0);
  const auto split = quad_triangles(std::array{10, 11, 12, 13}, p0, p1, p2, p3);
  EXPECT_EQ(split, (std::array<Tri, 2>{Tri{10, 11, 13}, Tri{11, 12, 13}}));
  const std::array<Vec3, 4> at = {p0, p1, p2, p3};
  for (const Tri& t : split) {
    const Vec3 n = (at[t[1] - 10] - at[t[0] - 10]).cross(at[t[2] - 10] - at[t[0] - 10]);
    EXPECT_GT(n.z(), 0) << t[0] << " " << t[1] << " " << t[2];
  }
  // check_surface's triangulate() of a tessellation and of a file's quads split the same way.
  PolygonSoup soup;
  soup.positions = {p0, p1, p2, p3};
  soup.faces = {{0, 1, 2, 3}};
  const TriangleSoup triangles = triangulate(soup);
  EXPECT_EQ(triangles.triangles, (std::vector<Tri>{Tri{0, 1, 3}, Tri{1, 2, 3}}));
}

TEST(SurfaceCheck, FoldsAreBeyondTheFoldAngleNotAtIt) {
  // Two triangles on the edge (0,0,0)-(1,0,0) at exactly a right angle, as a box's faces meet:
  // their normals are perpendicular to the bit, which is no fold; a little further is one.
  const auto wedge = [](double lean) {
    return soup_of({{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, lean, 1}}, {{0, 1, 2}, {1, 0, 3}});
  };
  EXPECT_EQ(check_surface(wedge(0)).folds, 0);
  EXPECT_EQ(check_surface(wedge(0.01)).folds, 1);
}

/// The pairs a check should find, pair by pair over all of them: crossings of triangles that
/// share at most a vertex (the tests check_surface runs, without its grid).
int brute_force_crossings(const TriangleSoup& s) {
  int found = 0;
  for (size_t i = 0; i < s.triangles.size(); ++i)
    for (size_t j = i + 1; j < s.triangles.size(); ++j) {
      const auto &a = s.triangles[i], &b = s.triangles[j];
      int shared = 0;
      for (int x : a)
        for (int y : b) shared += x == y;
      if (shared > 0) continue;
      const auto& P = s.positions;
      found += triangles_intersect(P[a[0]], P[a[1]], P[a[2]], P[b[0]], P[b[1]], P[b[2]]);
    }
  return found;
}

TEST(SurfaceCheck, TheGridFindsEveryCrossingOnceWhateverTheTrianglesSizes) {
  // A sphere of small triangles cut by two large ones (each over many cells and tiles of the
  // grid) and by a small one through its side: every crossing pair once.
  TriangleSoup s = triangulate(sphere_soup());
  const int base = static_cast<int>(s.positions.size());
  for (const Vec3& p :
       {Vec3(-3, -3, 0.1), Vec3(3, -3, 0.1), Vec3(0, 3, 0.1), Vec3(-3, 0.2, -3), Vec3(3, 0.2, -3),
        Vec3(0, 0.2, 3), Vec3(0.9, 0, 0), Vec3(1.2, 0.1, 0), Vec3(1.1, -0.1, 0.1)})
    s.positions.push_back(p);
  for (int t = 0; t < 3; ++t) {
    s.triangles.push_back({base + 3 * t, base + 3 * t + 1, base + 3 * t + 2});
    s.source.push_back(static_cast<int>(s.source.size()));
  }
  const int expected = brute_force_crossings(s);
  ASSERT_GT(expected, 100);
  const SurfaceCheckReport r = check_surface(s);
  EXPECT_EQ(r.self_intersections, expected);
  EXPECT_EQ(r.folds, 0);
  // The pairs listed are the first by triangle number.
  ASSERT_EQ(r.intersecting_pairs.size(), 20u);
  EXPECT_TRUE(std::is_sorted(r.intersecting_pairs.begin(), r.intersecting_pairs.end()));
}

/// Meshes for the checks of a surface: extraordinary points, a hole made by insert-edge
/// (a face along one edge twice, deleted elements), a tube whose fitted K-gons fold, and a torus
/// with a vertex pushed through it.
std::vector<std::pair<std::string, HalfedgeMesh>> surfaces_to_check() {
  std::vector<std::pair<std::string, HalfedgeMesh>> out;
  HalfedgeMesh holed = make_cube();
  apply_operation(holed, "insert-edge 1@1 5@2");
  out.emplace_back("holed cube", std::move(holed));
  HalfedgeMesh tube = make_prism(30);
  apply_operation(tube, "insert-edge 1@1 31@2");
  out.emplace_back("folding tube", std::move(tube));
  HalfedgeMesh pushed = make_torus(12, 8);
  pushed.position(Vertex(0)) *= 0.1;
  out.emplace_back("pushed torus", std::move(pushed));
  return out;
}

TEST(SurfaceCheck, TheSurfacesCheckIsTheCheckOfItsTessellation) {
  for (const auto& [name, mesh] : surfaces_to_check())
    for (const Method method : {Method::mdc, Method::cc})
      for (const int n : {3, 8}) {
        const Surface surface(mesh, method);
        const TessellatedMesh t = tessellate(mesh, surface, {.resolution = n});
        const SurfaceCheckReport whole = check_surface(triangulate(t));
        const SurfaceCheckReport streamed = check_surface(mesh, surface, n);
        const std::string what = name + " " + to_string(method) + " " + std::to_string(n);
        EXPECT_EQ(streamed.triangles, whole.triangles) << what;
        EXPECT_EQ(streamed.self_intersections, whole.self_intersections) << what;
        EXPECT_EQ(streamed.folds, whole.folds) << what;
        EXPECT_EQ(streamed.degenerate, whole.degenerate) << what;
        EXPECT_EQ(streamed.inconsistent_edges, whole.inconsistent_edges) << what;
        // No quad collapses here, so triangle 2q + s of the one is triangle 2q + s of the other.
        EXPECT_EQ(streamed.intersecting_pairs, whole.intersecting_pairs) << what;
        EXPECT_EQ(streamed.folded_pairs, whole.folded_pairs) << what;
        if (name == "folding tube" && method == Method::mdc) {
          EXPECT_GT(whole.folds, 0) << what;
        }
        if (name == "pushed torus") {
          EXPECT_GT(whole.self_intersections, 0) << what;
        }
      }
}

// The check of nets kept apart from a Surface (as an IncrementalSurface keeps them) is the
// Surface's check: the same patches, the same K-gons' creases and cone points.
TEST(SurfaceCheck, NetsKeptApartAreCheckedAsTheirSurface) {
  for (const auto& [name, mesh] : surfaces_to_check())
    for (const Method method : {Method::mdc, Method::asc}) {
      const Surface surface(mesh, method);
      const SurfaceCheckReport expected = check_surface(mesh, surface, 6);
      const SurfaceCheckReport apart =
          check_surface(mesh, method, surface.bezier().kgons, surface.bezier().nets, 6);
      const std::string what = name + " " + to_string(method);
      EXPECT_EQ(apart.triangles, expected.triangles) << what;
      EXPECT_EQ(apart.folded_pairs, expected.folded_pairs) << what;
      EXPECT_EQ(apart.intersecting_pairs, expected.intersecting_pairs) << what;
      EXPECT_EQ(apart.degenerate, expected.degenerate) << what;
    }
  const HalfedgeMesh cube = make_cube();
  const Surface surface(cube, Method::mdc);
  EXPECT_THROW(
      (void)check_surface(cube, Method::cc, surface.bezier().kgons, surface.bezier().nets, 4),
      UsageError);
}

TEST(SurfaceCheck, TheSurfacesCheckDoesNotDependOnThreads) {
  const HalfedgeMesh mesh = surfaces_to_check()[2].second;
  const Surface surface(mesh, Method::mdc);
  const auto run = [&](int threads) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return check_surface(mesh, surface, 8);
  };
  const SurfaceCheckReport one = run(1), two = run(2);
  EXPECT_EQ(one.self_intersections, two.self_intersections);
  EXPECT_EQ(one.intersecting_pairs, two.intersecting_pairs);
  EXPECT_GT(one.self_intersections, 0);
}

TEST(SurfaceCheck, CreasesAndConePointsAreNoFolds) {
  // Infinitely sharp edges: the top loop of a cube, every edge of OpenSubdiv's cubes (corners:
  // cone points), every edge of a tetrahedron (creases sharper than a right angle).
  HalfedgeMesh tetrahedron = make_tetrahedron();
  for (Edge e : tetrahedron.edges()) tetrahedron.set_sharpness(e, 10);
  std::vector<std::pair<std::string, HalfedgeMesh>> creased;
  creased.emplace_back("cube_creased",
                       read_mesh(std::string(STITCH_SOURCE_DIR) + "/examples/cube_creased.obj"));
  creased.emplace_back("catmark_cubes_infsharp",
                       read_mesh(std::string(STITCH_TEST_DATA_DIR) +
                                 "/opensubdiv-shapes/catmark_cubes_infsharp.obj"));
  creased.emplace_back("creased tetrahedron", std::move(tetrahedron));
  for (const auto& [name, mesh] : creased) {
    const Surface surface(mesh, Method::mdc);
    const SurfaceCheckReport r = check_surface(mesh, surface, 8);
    EXPECT_EQ(r.folds, 0) << name << "\n" << r.describe_quads();
    // A file has no crease tags: there the rule is the fold angle, which faces meeting at a right
    // angle (the cubes' creases) pass and sharper creases (the tetrahedron's) do not.
    const SurfaceCheckReport file =
        check_surface(triangulate(tessellate(mesh, surface, {.resolution = 8})));
    EXPECT_EQ(file.folds > 0, name == "creased tetrahedron") << name << "\n" << file.folds;
  }
}

}  // namespace
}  // namespace stitch
