// The incremental surface update: after a local edit exactly the patches whose control nets
// changed are recomputed, and the result is identical (bit for bit, since the same code runs on
// the same numbers) to building everything from scratch.
#include "stitch/modeler/live_surface.hpp"

#include <gtest/gtest.h>

#include <random>
#include <set>

#include "stitch/mesh/io.hpp"
#include "stitch/tess/tessellate.hpp"
#include "stitch/topology/primitives.hpp"
#include "test_support.hpp"

namespace stitch::modeler {
namespace {

void expect_same_as_rebuild(const LiveSurface& live, const HalfedgeMesh& mesh,
                            const KgonOptions& options) {
  const Surface fresh(mesh, live.method(), options);
  TessellationOptions t;
  t.resolution = live.resolution();
  t.welded = false;
  const SurfaceMesh expected = tessellate(mesh, fresh, t);
  const SurfaceMesh& got = live.tessellation();
  ASSERT_EQ(got.num_vertices(), expected.num_vertices());
  EXPECT_TRUE(got.positions == expected.positions);
  EXPECT_TRUE(got.normals == expected.normals);
  EXPECT_TRUE(got.uv == expected.uv);
  EXPECT_TRUE(got.patch == expected.patch);
  EXPECT_TRUE(got.level == expected.level);
  EXPECT_TRUE(got.quads == expected.quads);
  EXPECT_TRUE(live.nets() == fresh.bezier().nets);
}

/// Applies `change` (already made to doc) and checks that the recomputed set is exactly the set
/// of corners whose nets differ between before and a from-scratch rebuild after.
void check_update(LiveSurface& live, const Document& doc, const Change& change) {
  const std::vector<ControlNet> before = live.nets();
  const UpdateStats stats = live.update(doc.mesh(), doc.kgon_options(), change);
  const std::vector<ControlNet> fresh =
      build_control_nets(doc.mesh(), build_kgons(doc.mesh(), doc.kgon_options()));
  std::vector<Corner> changed;
  for (Corner c : doc.mesh().halfedges())
    if (before[c.idx] != fresh[c.idx]) changed.push_back(c);
  if (live.method() != Method::cc) {
    EXPECT_EQ(live.recomputed(), changed);
    EXPECT_EQ(stats.recomputed_patches, static_cast<int>(changed.size()));
    EXPECT_FALSE(stats.full);
  }
  expect_same_as_rebuild(live, doc.mesh(), doc.kgon_options());
}

struct Case {
  std::string name;
  HalfedgeMesh mesh;
};

std::vector<Case> cases() {
  return {{"cube", make_cube()},
          {"cube_hole", read_mesh(test::example_path("cube_hole.obj"), {false, true})},
          {"torus", make_torus(8, 6)},
          {"tetrahedron", make_tetrahedron()},
          {"pyramid", read_mesh(test::shared_path("catmark_pyramid.obj"))}};
}

TEST(ModelerLiveSurface, VertexMovesRecomputeExactlyTheChangedPatches) {
  std::mt19937 rng(7);
  for (Method method : {Method::mdc, Method::asc}) {
    for (Case& c : cases()) {
      SCOPED_TRACE(c.name + " " + to_string(method));
      Document doc(c.mesh);
      LiveSurface live;
      live.rebuild(doc.mesh(), doc.kgon_options(), method, 3);
      const auto vertices = doc.mesh().vertices();
      std::uniform_int_distribution<size_t> pick(0, vertices.size() - 1);
      std::uniform_real_distribution<double> step(-0.3, 0.3);
      for (int i = 0; i < 4; ++i) {
        const Vertex v = vertices[pick(rng)];
        const Vec3 p = doc.mesh().position(v) + Vec3(step(rng), step(rng), step(rng));
        check_update(live, doc, doc.move_vertices({v}, {p}));
        ASSERT_FALSE(live.recomputed().empty());
      }
      check_update(live, doc, doc.undo());  // undo is a move back
    }
  }
}

TEST(ModelerLiveSurface, KgonEditsRecomputeExactlyTheChangedPatches) {
  for (Case& c : cases()) {
    SCOPED_TRACE(c.name);
    Document doc(c.mesh);
    LiveSurface live;
    live.rebuild(doc.mesh(), doc.kgon_options(), Method::mdc, 2);
    KgonControl k;
    k.scale = 0.7;
    k.rotate_deg = 12;
    check_update(live, doc, doc.set_kgon_control({KgonKind::face, doc.mesh().faces()[0].idx}, k));
    check_update(live, doc,
                 doc.set_kgon_control({KgonKind::vertex, doc.mesh().vertices()[1].idx}, k));
    k.offset = Vec3(0.05, 0.0, -0.02);
    check_update(live, doc, doc.set_kgon_control({KgonKind::edge, doc.mesh().edges()[2].idx}, k));
    k.regularize = true;
    check_update(live, doc, doc.set_kgon_control({}, k));  // the global control
    check_update(live, doc, doc.undo());
  }
}

TEST(ModelerLiveSurface, VertexMoveIsLocal) {
  Document doc(make_torus(30, 20));
  LiveSurface live;
  live.rebuild(doc.mesh(), doc.kgon_options(), Method::mdc, 2);
  const UpdateStats s = live.update(
      doc.mesh(), doc.kgon_options(),
      doc.move_vertices({Vertex(45)}, {doc.mesh().position(Vertex(45)) + Vec3(0, 0, 0.1)}));
  // A valence-4 vertex of a quad mesh: its 4 faces, their 9 vertices and 12 edges, plus the
  // faces around for normals: a few dozen corners out of 2400.
  EXPECT_LT(s.candidate_patches, 200);
  EXPECT_GT(s.recomputed_patches, 0);
  EXPECT_LE(s.recomputed_patches, s.candidate_patches);
}

TEST(ModelerLiveSurface, TopologyMethodAndResolutionChangesRebuildEverything) {
  Document doc(make_cube());
  LiveSurface live;
  live.rebuild(doc.mesh(), doc.kgon_options(), Method::mdc, 3);
  const UpdateStats s =
      live.update(doc.mesh(), doc.kgon_options(), doc.apply_operation("insert-edge 1@1 5@2"));
  EXPECT_TRUE(s.full);
  expect_same_as_rebuild(live, doc.mesh(), doc.kgon_options());
  live.set_method(doc.mesh(), doc.kgon_options(), Method::asc);
  expect_same_as_rebuild(live, doc.mesh(), doc.kgon_options());
  live.set_resolution(doc.mesh(), doc.kgon_options(), 5);
  expect_same_as_rebuild(live, doc.mesh(), doc.kgon_options());
  check_update(live, doc, doc.move_vertices({Vertex(2)}, {Vec3(1.2, 1.1, -1.0)}));
  // OpenSubdiv cannot represent the 10-sided face that runs along the bridge twice: refused,
  // nothing changed.
  EXPECT_THROW(live.set_method(doc.mesh(), doc.kgon_options(), Method::cc), MeshError);
  EXPECT_EQ(live.method(), Method::asc);
  expect_same_as_rebuild(live, doc.mesh(), doc.kgon_options());
  live.update(doc.mesh(), doc.kgon_options(), doc.undo());  // the move
  live.update(doc.mesh(), doc.kgon_options(), doc.undo());  // the bridge
  live.set_method(doc.mesh(), doc.kgon_options(), Method::cc);
  expect_same_as_rebuild(live, doc.mesh(), doc.kgon_options());
  check_update(live, doc, doc.move_vertices({Vertex(3)}, {Vec3(-1.2, 1.1, -1.0)}));
}

}  // namespace
}  // namespace stitch::modeler
