// Every method on meshes made by random operator sequences: every method builds and gives finite
// output (cc once wrote past OpenSubdiv's buffers around 2-sided faces, and refused faces that
// run along an edge twice), the cc surface is watertight, and the modified de Casteljau surface
// stays C1 (parametrically) across every patch boundary.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <random>

#include "random_operation.hpp"
#include "stitch/eval/surface.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/net/control_net.hpp"
#include "stitch/tess/tessellate.hpp"
#include "stitch/topology/operation.hpp"
#include "stitch/topology/primitives.hpp"

namespace stitch {
namespace {

TEST(RandomEdits, EveryMethodGivesFiniteOutputAndMdcStaysC1) {
  std::mt19937 rng(12345);  // fixed seed: the same 120 meshes every run
  const char* primitives[] = {"tetrahedron", "cube", "octahedron", "icosahedron", "dodecahedron"};
  int cc_checked = 0, checked = 0;
  for (int trial = 0; trial < 120; ++trial) {
    HalfedgeMesh m = make_primitive(primitives[trial % 5], {});
    const int ops = 1 + static_cast<int>(rng() % 6);
    for (int k = 0; k < ops; ++k) {
      m.garbage_collection();
      try {
        apply_operation(m, test::random_operation(m, rng));
      } catch (const Error&) {
      }
    }
    m.garbage_collection();
    ASSERT_TRUE(find_problems(m).empty()) << "trial " << trial;
    for (Method method : {Method::mdc, Method::asc, Method::cc}) {
      std::optional<Surface> surface;
      try {
        surface.emplace(m, method);
      } catch (const Error& e) {
        FAIL() << to_string(method) << ", trial " << trial << ": " << e.what();
      }
      const TessellatedMesh s = tessellate(m, *surface, {3, true});
      for (int i = 0; i < s.num_vertices(); ++i) {
        ASSERT_TRUE(s.positions[i].allFinite()) << "trial " << trial;
        ASSERT_TRUE(s.normals[i].allFinite()) << "trial " << trial;
      }
      double diagonal = 0;
      for (Vertex a : m.vertices())
        for (Vertex b : m.vertices())
          diagonal = std::max(diagonal, (m.position(a) - m.position(b)).norm());
      if (method == Method::cc) {
        // Catmull-Clark is C2 away from extraordinary points, but random geometry may collapse
        // patches, so only positions are compared: neighbouring patches meet, up to the
        // round-off of two limit evaluations (1e-9 of the diagonal, as below).
        for (Corner c : surface->corners())
          for (int side : {0, 1}) {
            const PatchNeighbour nb = neighbour_across(m, c, side);
            for (double t : {0.0, 0.3, 0.5, 1.0}) {
              const auto a = side_point(side, t);
              const auto b = side_point(nb.side, t);
              ASSERT_LT((surface->evaluate(c, a[0], a[1]).position -
                         surface->evaluate(nb.corner, b[0], b[1]).position)
                            .norm(),
                        1e-9 * diagonal)
                  << "trial " << trial;
            }
          }
        ++cc_checked;
      }
      if (method != Method::mdc) continue;
      for (Corner c : surface->corners()) {
        const PatchNeighbour across = neighbour_across(m, c, 0);  // side 0 meets side 3
        for (double t : {1.0 / 4096, 0.1, 0.5, 0.9, 1.0 - 1.0 / 4096}) {
          const SurfacePoint a = surface->evaluate(c, t, 0.0);
          const SurfacePoint b = surface->evaluate(across.corner, 0.0, t);
          ASSERT_LT((a.du - b.dv).norm(), 1e-9 * diagonal) << "trial " << trial;
          ASSERT_LT((a.dv + b.du).norm(), 1e-9 * diagonal) << "trial " << trial;
        }
        const PatchNeighbour inside = neighbour_across(m, c, 1);  // side 1 meets side 2
        for (double t : {1.0 / 4096, 0.1, 0.5, 0.9, 1.0 - 1.0 / 4096}) {
          const SurfacePoint a = surface->evaluate(c, 1.0, t);
          const SurfacePoint b = surface->evaluate(inside.corner, t, 1.0);
          ASSERT_LT((a.dv - b.du).norm(), 1e-9 * diagonal) << "trial " << trial;
          ASSERT_LT((a.du + b.dv).norm(), 1e-9 * diagonal) << "trial " << trial;
        }
      }
      ++checked;
    }
  }
  EXPECT_EQ(cc_checked, 120);
  EXPECT_EQ(checked, 120);
}

}  // namespace
}  // namespace stitch
