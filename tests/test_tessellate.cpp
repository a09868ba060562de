// The tessellated surface: welded output is a closed, oriented 2-manifold with the input's
// topology; unwelded output keeps every patch's own grid.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "stitch/mesh/build.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/tess/tessellate.hpp"
#include "stitch/topology/operation.hpp"
#include "stitch/topology/primitives.hpp"
#include "tess/layout.hpp"
#include "test_support.hpp"

namespace stitch {
namespace {

PolygonSoup as_soup(const TessellatedMesh& s) {
  PolygonSoup soup;
  soup.positions = s.positions;
  for (const auto& q : s.quads) soup.faces.push_back({q[0], q[1], q[2], q[3]});
  return soup;
}

Vec3 quad_normal(const TessellatedMesh& s, const std::array<int, 4>& q) {
  return (s.positions[q[2]] - s.positions[q[0]]).cross(s.positions[q[3]] - s.positions[q[1]]);
}

void expect_welded_surface_ok(const HalfedgeMesh& input, Method method, int resolution,
                              const std::string& name) {
  const Surface surface(input, method);
  const TessellatedMesh s = tessellate(input, surface, {resolution, true});
  for (int i = 0; i < s.num_vertices(); ++i) {
    ASSERT_TRUE(s.positions[i].allFinite()) << name;
    ASSERT_TRUE(s.normals[i].allFinite()) << name;
  }
  // Closed, manifold and consistently oriented: build_mesh refuses anything else.
  const HalfedgeMesh out = build_mesh(as_soup(s));
  const TopologyStats a = topology_stats(input), b = topology_stats(out);
  EXPECT_EQ(b.euler, a.euler) << name;
  EXPECT_EQ(b.components, a.components) << name;
  EXPECT_EQ(b.genus, a.genus) << name;
  // Every sample is used: nothing dangles.
  EXPECT_EQ(out.num_vertices(), s.num_vertices()) << name;
  // The quads wind the way the analytic normals point.
  int against = 0;
  for (const auto& q : s.quads) {
    const Vec3 n = quad_normal(s, q);
    Vec3 vn = Vec3::Zero();
    for (int v : q) vn += s.normals[v];
    if (n.dot(vn) <= 0) ++against;
  }
  EXPECT_EQ(against, 0) << name;
}

TEST(Tessellate, WeldedOutputIsAClosedOrientedManifoldWithTheInputsTopology) {
  for (const std::string& name : test::closed_opensubdiv_shapes())
    expect_welded_surface_ok(read_mesh(test::opensubdiv_shape(name)), Method::mdc, 4, name);
  for (const char* name :
       {"cube.obj", "tetrahedron.obj", "torus.obj", "cube_hole.obj", "two_cubes.obj"})
    expect_welded_surface_ok(read_mesh(test::example_path(name)), Method::mdc, 3, name);
  expect_welded_surface_ok(test::cube_mesh(), Method::asc, 1, "cube asc, resolution 1");
}

TEST(Tessellate, NormalsPointOutwardOnAConvexShape) {
  const HalfedgeMesh cube = test::cube_mesh();
  const TessellatedMesh s = tessellate(cube, Surface(cube, Method::mdc), {6, true});
  for (int i = 0; i < s.num_vertices(); ++i) EXPECT_GT(s.normals[i].dot(s.positions[i]), 0);
}

TEST(Tessellate, UnweldedKeepsEveryPatchGridWithItsParameters) {
  const HalfedgeMesh tet = test::tetrahedron_mesh();
  const int n = 5;
  const TessellatedMesh s =
      tessellate(tet, Surface(tet, Method::mdc),
                 {.resolution = n, .welded = false, .uv = true, .level = true});
  ASSERT_EQ(s.num_vertices(), 12 * (n + 1) * (n + 1));
  ASSERT_EQ(static_cast<int>(s.quads.size()), 12 * n * n);
  for (int i = 0; i < s.num_vertices(); ++i) {
    const int k = i % ((n + 1) * (n + 1));
    EXPECT_DOUBLE_EQ(s.uv[i].x(), static_cast<double>(k / (n + 1)) / n);
    EXPECT_DOUBLE_EQ(s.uv[i].y(), static_cast<double>(k % (n + 1)) / n);
  }
  // Samples near an extraordinary corner come from deeper sub-patches.
  int deepest = 0;
  for (int l : s.level) deepest = std::max(deepest, l);
  EXPECT_GE(deepest, 3);  // (1/5, 0) needs 3 splits before it leaves the corner's child
}

// Extraordinary vertices of valence 3 and 5, a 10-sided face, triangles, regular patches; the
// same with a boundary (without its last face); and the same with creases (every edge of its
// first face and of one more sharp).
std::array<HalfedgeMesh, 3> closed_and_open_meshes() {
  HalfedgeMesh closed = make_cube();
  apply_operation(closed, "insert-edge 1@1 5@2");
  apply_operation(closed, "insert-edge 2@3 5@3");
  apply_operation(closed, "vertex-insertion");
  PolygonSoup soup = to_polygon_soup(closed);
  soup.faces.pop_back();
  HalfedgeMesh open = build_mesh(soup);
  HalfedgeMesh creased = closed;
  for (const Face f : {Face(0), Face(7)})
    for (const Halfedge h : creased.face_loop(f))
      creased.set_sharpness(HalfedgeMesh::edge(h), infinitely_sharp);
  return {std::move(closed), std::move(open), std::move(creased)};
}

TEST(Tessellate, EveryVertexIsItsSamplesEvaluatedOneByOneAndQuadsAreTheLayouts) {
  for (const HalfedgeMesh& m : closed_and_open_meshes()) {
    const HalfedgeMesh* mesh = &m;
    for (const Method method : {Method::mdc, Method::asc})
      for (const int n : {1, 2, 3, 8})
        for (const bool welded : {true, false}) {
          const Surface surface(*mesh, method);
          TessellationOptions options{n, welded};
          options.uv = options.patch = options.level = true;
          const TessellatedMesh s = tessellate(*mesh, surface, options);
          const TessellationLayout layout(*mesh, surface.corners(), n, welded);
          ASSERT_EQ(s.num_vertices(), layout.num_vertices());
          std::vector<GridSample> sharing;
          for (int v = 0; v < s.num_vertices(); ++v) {
            // The first sample's point; the normalized sum of all sharing samples' normals at
            // patch corners (mesh vertices, face centres, edge midpoints), on sharp edges (side
            // j = 0 lies on edge(c), side i = 0 on edge(prev(c))) and under asc; else the first
            // sample's normal.
            layout.samples(v, sharing);
            const GridSample& g0 = sharing[0];
            const Corner c0 = surface.corners()[g0.corner];
            const KgonSet& kgons = surface.bezier().kgons;
            const bool on_patch_corner = (g0.i == 0 || g0.i == n) && (g0.j == 0 || g0.j == n);
            const bool mean = welded && sharing.size() > 1 &&
                              (on_patch_corner || method == Method::asc ||
                               (g0.j == 0 && kgons.sharp(HalfedgeMesh::edge(c0))) ||
                               (g0.i == 0 && kgons.sharp(HalfedgeMesh::edge(mesh->prev(c0)))));
            Vec3 normal = Vec3::Zero();
            SurfacePoint first;
            for (size_t k = 0; k < (mean ? sharing.size() : 1); ++k) {
              const GridSample& g = sharing[k];
              const SurfacePoint p =
                  surface.evaluate(surface.corners()[g.corner], static_cast<double>(g.i) / n,
                                   static_cast<double>(g.j) / n);
              normal += p.normal;
              if (k == 0) first = p;
            }
            if (mean) normal.normalize();
            const std::string where =
                fmt::format("{} n={} welded={} vertex {}", to_string(method), n, welded, v);
            ASSERT_EQ(s.positions[v], first.position) << where;
            ASSERT_EQ(s.normals[v], normal) << where;
            ASSERT_EQ(s.level[v], first.level) << where;
            ASSERT_EQ(s.patch[v], surface.corners()[sharing[0].corner].idx) << where;
            ASSERT_EQ(s.uv[v], Eigen::Vector2d(static_cast<double>(sharing[0].i) / n,
                                               static_cast<double>(sharing[0].j) / n))
                << where;
          }
          // Quads walked corner by corner, from any start, are quad(q)'s.
          ASSERT_EQ(static_cast<std::int64_t>(s.quads.size()), layout.num_quads());
          for (const std::int64_t begin : {std::int64_t{0}, layout.num_quads() / 3 + 1}) {
            std::vector<int> walked(static_cast<size_t>(4 * (layout.num_quads() - begin)));
            layout.quads(begin, layout.num_quads(), walked.data());
            for (std::int64_t q = begin; q < layout.num_quads(); ++q)
              for (int m = 0; m < 4; ++m) {
                ASSERT_EQ(walked[static_cast<size_t>(4 * (q - begin) + m)], layout.quad(q)[m])
                    << to_string(method) << " n=" << n << " welded=" << welded << " quad " << q;
                if (begin == 0) {
                  ASSERT_EQ(s.quads[static_cast<size_t>(q)][m], layout.quad(q)[m]);
                }
              }
          }
        }
  }
}

// Any split of the output vertices into ranges gives the same bits as one range for everything,
// attributes included: ranges of single vertices, and ranges that cut corner blocks in different
// places.
TEST(Tessellate, EveryRangeSplitGivesTheSameSamples) {
  for (const HalfedgeMesh& m : closed_and_open_meshes()) {
    const HalfedgeMesh* mesh = &m;
    for (const int n : {2, 3, 8}) {
      const Surface surface(*mesh, Method::mdc);
      const TessellationLayout layout(*mesh, surface.corners(), n, true);
      const auto count = static_cast<size_t>(layout.num_vertices());
      std::vector<Vec3> positions(count), normals(count);
      std::vector<Eigen::Vector2d> uvs(count);
      std::vector<int> patches(count), levels(count);
      layout.evaluate(surface, 0, layout.num_vertices(), positions.data(), normals.data(),
                      {uvs.data(), patches.data(), levels.data()});
      const std::int64_t block = static_cast<std::int64_t>(n) * n - 1;
      for (const std::int64_t step :
           {std::int64_t{1}, std::int64_t{7}, block, block + 1, 3 * block - 1}) {
        std::vector<Vec3> p(count), nm(count);
        std::vector<Eigen::Vector2d> uv(count);
        std::vector<int> patch(count), l(count);
        for (std::int64_t b = 0; b < layout.num_vertices(); b += step) {
          const std::int64_t e = std::min(b + step, layout.num_vertices());
          layout.evaluate(surface, b, e, p.data() + b, nm.data() + b,
                          {uv.data() + b, patch.data() + b, l.data() + b});
        }
        EXPECT_EQ(p, positions) << "n=" << n << " step " << step;
        EXPECT_EQ(nm, normals) << "n=" << n << " step " << step;
        EXPECT_EQ(uv, uvs) << "n=" << n << " step " << step;
        EXPECT_EQ(patch, patches) << "n=" << n << " step " << step;
        EXPECT_EQ(l, levels) << "n=" << n << " step " << step;
      }
    }
  }
}

// tessellate_blocks: the blocks, put one after the other (their quads moved by the vertices
// before them), are the unwelded tessellation to the bit, whatever the block size; a block's
// quads stay within it.
TEST(Tessellate, BlocksOfPatchesMakeTheUnweldedTessellation) {
  for (const HalfedgeMesh& mesh : closed_and_open_meshes()) {
    const Surface surface(mesh, Method::mdc);
    const TessellationOptions options{
        .resolution = 3, .welded = false, .uv = true, .patch = true, .level = true};
    const TessellatedMesh whole = tessellate(mesh, surface, options);
    const int patches = static_cast<int>(surface.corners().size());
    for (const int per_block : {1, 4, patches, patches + 3}) {
      TessellatedMesh joined;
      int next = 0;
      tessellate_blocks(mesh, surface, options, per_block,
                        [&](const TessellatedMesh& block, int first) {
                          EXPECT_EQ(first, next);
                          next += std::min(per_block, patches - first);
                          const int base = joined.num_vertices();
                          for (auto q : block.quads) {
                            for (int& v : q) {
                              EXPECT_TRUE(v >= 0 && v < block.num_vertices());
                              v += base;
                            }
                            joined.quads.push_back(q);
                          }
                          const auto append = [](auto& to, const auto& from) {
                            to.insert(to.end(), from.begin(), from.end());
                          };
                          append(joined.positions, block.positions);
                          append(joined.normals, block.normals);
                          append(joined.uv, block.uv);
                          append(joined.patch, block.patch);
                          append(joined.level, block.level);
                        });
      EXPECT_EQ(next, patches);
      EXPECT_EQ(joined.positions, whole.positions) << per_block;
      EXPECT_EQ(joined.normals, whole.normals) << per_block;
      EXPECT_EQ(joined.uv, whole.uv) << per_block;
      EXPECT_EQ(joined.patch, whole.patch) << per_block;
      EXPECT_EQ(joined.level, whole.level) << per_block;
      EXPECT_EQ(joined.quads, whole.quads) << per_block;
    }
    const auto nothing = [](const TessellatedMesh&, int) {};
    EXPECT_THROW(tessellate_blocks(mesh, surface, {.resolution = 3}, 4, nothing),
                 std::invalid_argument);
    EXPECT_THROW(tessellate_blocks(mesh, surface, options, 0, nothing), std::invalid_argument);
  }
}

// Tessellating into a TessellatedMesh that already holds another tessellation (larger, then
// smaller, with and without attributes) gives exactly the fresh result: nothing of the old one
// survives in the reused storage.
TEST(Tessellate, IntoReusedArraysEqualsAFreshTessellation) {
  const HalfedgeMesh big = make_primitive("torus", {8, 6});
  const HalfedgeMesh small = test::tetrahedron_mesh();
  const Surface big_surface(big, Method::mdc), small_surface(small, Method::mdc);
  TessellatedMesh reused;
  const auto expect_fresh = [&](const HalfedgeMesh& mesh, const Surface& surface,
                                const TessellationOptions& options) {
    tessellate(mesh, surface, options, reused);
    const TessellatedMesh fresh = tessellate(mesh, surface, options);
    EXPECT_EQ(reused.positions, fresh.positions);
    EXPECT_EQ(reused.normals, fresh.normals);
    EXPECT_EQ(reused.uv, fresh.uv);
    EXPECT_EQ(reused.patch, fresh.patch);
    EXPECT_EQ(reused.level, fresh.level);
    EXPECT_EQ(reused.quads, fresh.quads);
    EXPECT_EQ(reused.uv.empty(), !options.uv);
    EXPECT_EQ(reused.patch.empty(), !options.patch);
    EXPECT_EQ(reused.level.empty(), !options.level);
  };
  const auto all = [](int n, bool welded) {
    return TessellationOptions{
        .resolution = n, .welded = welded, .uv = true, .patch = true, .level = true};
  };
  expect_fresh(big, big_surface, all(5, true));
  const void* storage = reused.positions.data();
  expect_fresh(small, small_surface, {.resolution = 3});
  EXPECT_EQ(reused.positions.data(), storage) << "smaller output reallocated";
  expect_fresh(small, small_surface, all(4, false));
  expect_fresh(small, small_surface, {.resolution = 4, .welded = false, .patch = true});
  expect_fresh(big, big_surface, all(6, true));
}

// Kept quads (index_buffer = false): after every vertex of a torus moved (fixed offsets, no
// randomness), tessellating into the kept output without rewriting its quads gives exactly the
// fresh tessellation, welded and unwelded, since the quads depend on the connectivity, the
// resolution and the welding alone. A kept output of another size is refused before anything in
// it changes.
TEST(Tessellate, KeptQuadsAfterVertexMovesEqualAFreshTessellation) {
  HalfedgeMesh mesh = make_primitive("torus", {8, 6});
  for (const bool welded : {true, false}) {
    const TessellationOptions full{.resolution = 5, .welded = welded, .uv = true},
        keep{.resolution = 5, .welded = welded, .uv = true, .index_buffer = false};
    TessellatedMesh kept = tessellate(mesh, Surface(mesh, Method::mdc), full);
    for (Vertex v : mesh.vertices())
      mesh.position(v) += Vec3(0.01 * (v.idx % 3), -0.02 * (v.idx % 5), 0.015 * (v.idx % 7));
    const Surface moved(mesh, Method::mdc);
    tessellate(mesh, moved, keep, kept);
    const TessellatedMesh fresh = tessellate(mesh, moved, full);
    EXPECT_EQ(kept.positions, fresh.positions) << "welded " << welded;
    EXPECT_EQ(kept.normals, fresh.normals) << "welded " << welded;
    EXPECT_EQ(kept.uv, fresh.uv) << "welded " << welded;
    EXPECT_EQ(kept.quads, fresh.quads) << "welded " << welded;
    // Another resolution has another number of quads: refused, `kept` unchanged.
    const TessellatedMesh before = kept;
    EXPECT_THROW(
        tessellate(mesh, moved, {.resolution = 6, .welded = welded, .index_buffer = false}, kept),
        std::invalid_argument);
    // The other welding has as many quads but not as many vertices: refused too.
    EXPECT_THROW(
        tessellate(mesh, moved, {.resolution = 5, .welded = !welded, .index_buffer = false}, kept),
        std::invalid_argument);
    EXPECT_EQ(kept.positions, before.positions);
    EXPECT_EQ(kept.quads, before.quads);
  }
}

// Where the welded output keeps the first patch's normal (averages_normals is false), the other
// patch's normal there is the same up to round-off: under mdc and cc the patches meet with C1
// inside faces and on smooth edges (and G1 at extraordinary points). The bound, 1e-12 rad, is a
// few thousand ulps of a unit vector's components: room for the round-off of a dozen levels of
// splits near an extraordinary corner, and far below any visible shading difference or a crease.
TEST(Tessellate, PatchesThatShareASmoothSampleAgreeOnItsNormal) {
  for (const HalfedgeMesh& mesh : closed_and_open_meshes())
    for (const Method method : {Method::mdc, Method::cc}) {
      const Surface surface(mesh, method);
      const int n = 8;
      const TessellationLayout layout(mesh, surface.corners(), n, true);
      std::vector<GridSample> sharing;
      double largest = 0;
      int compared = 0;
      for (std::int64_t v = 0; v < layout.num_vertices(); ++v) {
        layout.samples(v, sharing);
        if (sharing.size() < 2 || layout.averages_normals(v, surface)) continue;
        const auto normal = [&](const GridSample& g) {
          return surface
              .evaluate(surface.corners()[g.corner], static_cast<double>(g.i) / n,
                        static_cast<double>(g.j) / n)
              .normal;
        };
        const Vec3 first = normal(sharing[0]);
        for (size_t k = 1; k < sharing.size(); ++k) {
          const double a =
              std::atan2(first.cross(normal(sharing[k])).norm(), first.dot(normal(sharing[k])));
          largest = std::max(largest, a);
          ++compared;
        }
      }
      EXPECT_GT(compared, 0);
      EXPECT_LT(largest, 1e-12) << to_string(method);
    }
}

// A K-gon moved to NaN (only a control can do that: the input limits refuse such meshes) spoils
// the patches of its face. The error names a sample of one of them, whichever range of samples
// holds it; unwelded, every sample belongs to one patch.
TEST(Tessellate, RefusesASurfaceThatIsNotFiniteNamingTheSample) {
  const HalfedgeMesh cube = test::cube_mesh();
  KgonOptions options;
  options.face[2].offset = Vec3(std::nan(""), 0.0, 0.0);
  const Surface spoiled(cube, Method::mdc, options);
  for (const bool welded : {false, true}) {
    SCOPED_TRACE(welded ? "welded" : "unwelded");
    try {
      (void)tessellate(cube, spoiled, {4, welded});
      ADD_FAILURE() << "a NaN K-gon was tessellated";
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("not finite at sample"), std::string::npos) << message;
      if (welded) continue;  // a shared sample's first patch may be a neighbour's
      const auto at = message.find("corner half-edge ");
      ASSERT_NE(at, std::string::npos) << message;
      const int corner = std::stoi(message.substr(at + 17));
      EXPECT_EQ(cube.face(Corner(corner)).idx, 2) << message;
    }
  }
  EXPECT_NO_THROW((void)tessellate(cube, Surface(cube, Method::mdc), {4, false}));
}

TEST(Tessellate, RefusesAResolutionBelowOne) {
  const HalfedgeMesh tet = test::tetrahedron_mesh();
  EXPECT_THROW(tessellate(tet, Surface(tet, Method::mdc), {0, true}), Error);
}

}  // namespace
}  // namespace stitch
