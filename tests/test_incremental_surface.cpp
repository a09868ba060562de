// stitch::IncrementalSurface: after a local edit exactly the patches whose control nets changed
// are recomputed, and the result is identical (bit for bit, since the same code runs on the same
// numbers) to building everything from scratch. Edits are made here with the core alone: vertex
// moves, K-gon controls, and topology operations recorded by the mesh's journal (undone by
// applying the delta backwards, as the modeler's Document does).
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "incremental_check.hpp"
#include "random_operation.hpp"
#include "stitch/analysis/build_surface.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/mesh_journal.hpp"
#include "stitch/tess/incremental_surface.hpp"
#include "stitch/topology/operation.hpp"
#include "stitch/topology/primitives.hpp"
#include "test_support.hpp"

namespace stitch {
namespace {

using test::check_update;
using test::expect_same_as_rebuild;

SurfaceChange moved(Vertex v) {
  SurfaceChange c;
  c.kind = SurfaceChange::Kind::geometry;
  c.moved = {v};
  return c;
}

/// A mesh edited by operation lines through its journal, each edit kept for undo.
struct JournaledMesh {
  HalfedgeMesh mesh;
  std::vector<MeshDelta> done;

  /// The change of `line`, or nullopt when the line is refused (the mesh is then unchanged).
  std::optional<SurfaceChange> apply(const std::string& line) {
    MeshJournal journal(mesh);
    try {
      apply_operation(mesh, line, Census::counts_only);
    } catch (const Error&) {
      apply_delta(mesh, journal.finish(), false);
      return std::nullopt;
    }
    done.push_back(journal.finish());
    return topology_change(done.back());
  }
  SurfaceChange undo() {
    apply_delta(mesh, done.back(), false);
    SurfaceChange c = topology_change(done.back());
    done.pop_back();
    return c;
  }
};

struct Case {
  std::string name;
  HalfedgeMesh mesh;
};

std::vector<Case> cases() {
  return {{"cube", make_cube()},
          {"cube_hole", read_mesh(test::example_path("cube_hole.obj"), {false, true})},
          {"torus", make_torus(8, 6)},
          {"tetrahedron", make_tetrahedron()},
          {"pyramid", read_mesh(test::opensubdiv_shape("catmark_pyramid.obj"))},
          {"open_creased", [] {
             HalfedgeMesh m = make_torus(6, 5);
             m.set_hole(Face(3), true);
             for (int e : {0, 1, 7, 12}) m.set_sharpness(Edge(e), infinitely_sharp);
             m.set_sharpness(Vertex(9), infinitely_sharp);
             return m;
           }()}};
}

TEST(IncrementalSurface, VertexMovesRecomputeExactlyTheChangedPatches) {
  std::mt19937 rng(7);
  const KgonOptions options;
  for (Method method : {Method::mdc, Method::asc}) {
    for (Case& c : cases()) {
      SCOPED_TRACE(c.name + " " + to_string(method));
      HalfedgeMesh mesh = c.mesh;
      IncrementalSurface live;
      live.rebuild(mesh, options, method, 3);
      const auto vertices = mesh.vertices().to_vector();
      std::uniform_int_distribution<size_t> pick(0, vertices.size() - 1);
      std::uniform_real_distribution<double> step(-0.3, 0.3);
      for (int i = 0; i < 4; ++i) {
        const Vertex v = vertices[pick(rng)];
        mesh.position(v) += Vec3(step(rng), step(rng), step(rng));
        check_update(live, mesh, options, moved(v));
        ASSERT_FALSE(live.recomputed().empty());
      }
    }
  }
}

TEST(IncrementalSurface, KgonEditsRecomputeExactlyTheChangedPatches) {
  for (Case& c : cases()) {
    SCOPED_TRACE(c.name);
    KgonOptions options;
    IncrementalSurface live;
    live.rebuild(c.mesh, options, Method::mdc, 2);
    KgonControl k;
    k.scale = 0.7;
    k.rotate_deg = 12;
    SurfaceChange change;
    change.kind = SurfaceChange::Kind::kgons;
    const Face f = c.mesh.faces().to_vector()[0];
    options.face[f.idx] = k;
    change.faces = {f};
    check_update(live, c.mesh, options, change);
    change.faces.clear();
    const Vertex v = c.mesh.vertices().to_vector()[1];
    options.vertex[v.idx] = k;
    change.vertices = {v};
    check_update(live, c.mesh, options, change);
    change.vertices.clear();
    k.offset = Vec3(0.05, 0.0, -0.02);
    const Edge e = c.mesh.edges().to_vector()[2];
    options.edge[e.idx] = k;
    change.edges = {e};
    check_update(live, c.mesh, options, change);
    change.edges.clear();
    k.regularize = true;
    options.global = k;
    change.all_kgons = true;
    check_update(live, c.mesh, options, change);
  }
}

TEST(IncrementalSurface, VertexMoveIsLocal) {
  HalfedgeMesh mesh = make_torus(30, 20);
  IncrementalSurface live;
  live.rebuild(mesh, {}, Method::mdc, 2);
  mesh.position(Vertex(45)) += Vec3(0, 0, 0.1);
  const SurfaceUpdateStats s = live.update(mesh, {}, moved(Vertex(45)));
  // A valence-4 vertex of a quad mesh: its 4 faces, their 9 vertices and 12 edges, plus the
  // faces around for normals: a few dozen corners out of 2400.
  EXPECT_LT(s.candidate_patches, 200);
  EXPECT_GT(s.recomputed_patches, 0);
  EXPECT_LE(s.recomputed_patches, s.candidate_patches);
}

/// Applies the operation lines in turn, checking each update against a rebuild; returns how many
/// applied. A refused line changes nothing; with `all_apply` it is a failure.
int apply_checked(JournaledMesh& m, IncrementalSurface& live, const std::vector<std::string>& ops,
                  bool all_apply) {
  int applied = 0;
  for (const std::string& op : ops) {
    SCOPED_TRACE(op);
    const auto c = m.apply(op);
    if (!c) {
      if (all_apply) ADD_FAILURE() << "refused";
      continue;
    }
    ++applied;
    check_update(live, m.mesh, {}, *c);
  }
  return applied;
}

TEST(IncrementalSurface, TopologyEditsRecomputeExactlyTheChangedPatches) {
  const std::vector<std::string> ops{
      "insert-edge 1@1 5@2", "subdivide-edge 2 3",  "collapse-edge 3 9", "extrude-face 3 0.4",
      "delete-edge 1 5@1",   "insert-edge 6@3 8@3", "delete-face 4",     "connect-faces 3 5"};
  for (Method method : {Method::mdc, Method::asc}) {
    SCOPED_TRACE(to_string(method));
    JournaledMesh m{make_cube(), {}};
    IncrementalSurface live;
    live.rebuild(m.mesh, {}, method, 2);
    const int applied = apply_checked(m, live, ops, false);
    EXPECT_GE(applied, 5);
    while (!m.done.empty()) check_update(live, m.mesh, {}, m.undo());
    EXPECT_TRUE(m.mesh == make_cube());
    // A remeshing renumbers everything: rebuilt in full.
    apply_operation(m.mesh, "catmull-clark", Census::counts_only);
    EXPECT_TRUE(live.update(m.mesh, {}, whole_change()).full);
    expect_same_as_rebuild(live, m.mesh, {});
  }
}

TEST(IncrementalSurface, HolesCreasesAndCornersUpdateExactly) {
  // Tags and holes change no connectivity, yet they change which patches exist and which sides
  // are sharp curves: each edit is checked against a rebuild, then all are undone.
  const std::vector<std::string> ops{"open-face 2",        "crease 1 2 10", "corner 3 10",
                                     "crease 2 3 10",      "crease 1 2 0",  "insert-edge 1@1 3@1",
                                     "subdivide-edge 3 4", "fill-hole 2",   "open-face 4",
                                     "extrude-face 1 0.3"};
  for (Method method : {Method::mdc, Method::asc}) {
    SCOPED_TRACE(to_string(method));
    JournaledMesh m{make_cube(), {}};
    IncrementalSurface live;
    live.rebuild(m.mesh, {}, method, 2);
    const int applied = apply_checked(m, live, ops, true);
    EXPECT_EQ(applied, static_cast<int>(ops.size()));
    while (!m.done.empty()) check_update(live, m.mesh, {}, m.undo());
    EXPECT_TRUE(m.mesh == make_cube());
  }
}

TEST(IncrementalSurface, RandomTopologyEditsStayExact) {
  // Random operation lines on a torus (fixed seed), each checked against a from-scratch rebuild,
  // then all undone.
  std::mt19937 rng(11);
  JournaledMesh m{make_torus(6, 5), {}};
  IncrementalSurface live;
  live.rebuild(m.mesh, {}, Method::mdc, 2);
  int applied = 0;
  for (int i = 0; i < 40; ++i) {
    const std::string line = test::random_operation(m.mesh, rng);
    SCOPED_TRACE(line);
    const auto c = m.apply(line);
    if (!c) continue;  // refused: nothing changed
    ++applied;
    check_update(live, m.mesh, {}, *c);
  }
  EXPECT_GE(applied, 20);
  while (!m.done.empty()) check_update(live, m.mesh, {}, m.undo());
  EXPECT_TRUE(m.mesh == make_torus(6, 5));
}

TEST(IncrementalSurface, InsertEdgeIsLocal) {
  JournaledMesh m{make_torus(30, 20), {}};
  IncrementalSurface live;
  live.rebuild(m.mesh, {}, Method::mdc, 2);
  const SurfaceUpdateStats s = live.update(m.mesh, {}, *m.apply("insert-edge 1@1 22@1"));
  EXPECT_FALSE(s.full);
  EXPECT_TRUE(s.layout_changed);  // two new corners
  EXPECT_LT(s.recomputed_patches, 100);
  expect_same_as_rebuild(live, m.mesh, {});
}

TEST(IncrementalSurface, MethodAndResolutionChangesRebuildEverything) {
  JournaledMesh m{make_cube(), {}};
  IncrementalSurface live;
  live.rebuild(m.mesh, {}, Method::mdc, 3);
  check_update(live, m.mesh, {}, *m.apply("insert-edge 1@1 5@2"));
  live.set_method(m.mesh, {}, Method::asc);
  expect_same_as_rebuild(live, m.mesh, {});
  live.set_resolution(m.mesh, {}, 5);
  expect_same_as_rebuild(live, m.mesh, {});
  const Vec3 before = m.mesh.position(Vertex(2));
  m.mesh.position(Vertex(2)) = Vec3(1.2, 1.1, -1.0);
  check_update(live, m.mesh, {}, moved(Vertex(2)));
  // The 10-sided face that runs along the bridge twice (cc takes Catmull-Clark steps first).
  live.set_method(m.mesh, {}, Method::cc);
  EXPECT_EQ(live.method(), Method::cc);
  expect_same_as_rebuild(live, m.mesh, {});
  m.mesh.position(Vertex(2)) = before;
  check_update(live, m.mesh, {}, moved(Vertex(2)));
  check_update(live, m.mesh, {}, m.undo());  // the bridge
  m.mesh.position(Vertex(3)) = Vec3(-1.2, 1.1, -1.0);
  check_update(live, m.mesh, {}, moved(Vertex(3)));
}

TEST(IncrementalSurface, RefusesAResolutionBelowOneAndKeepsItsSurface) {
  IncrementalSurface live;
  live.rebuild(make_cube(), {}, Method::mdc, 2);
  EXPECT_THROW(live.set_resolution(make_cube(), {}, 0), UsageError);
  EXPECT_THROW(live.rebuild(make_cube(), {}, Method::asc, 0), UsageError);
  EXPECT_EQ(live.resolution(), 2);
  EXPECT_EQ(live.method(), Method::mdc);
  expect_same_as_rebuild(live, make_cube(), {});
}

// The position-only path: every vertex moves (fixed seed), the connectivity stays. The result
// must equal a rebuild exactly, with the layout untouched.
TEST(IncrementalSurface, UpdatePositionsAfterEveryVertexMovedEqualsARebuild) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> step(-0.2, 0.2);
  for (Method method : {Method::mdc, Method::asc, Method::cc}) {
    for (Case& c : cases()) {
      SCOPED_TRACE(c.name + " " + to_string(method));
      HalfedgeMesh mesh = c.mesh;
      IncrementalSurface live;
      live.rebuild(mesh, {}, method, 3);
      const std::vector<std::array<int, 4>> quads = live.tessellation().quads;
      const std::vector<Eigen::Vector2d> uv = live.tessellation().uv;
      const std::vector<int> patch = live.tessellation().patch;
      for (int round = 0; round < 2; ++round) {
        for (Vertex v : mesh.vertices()) mesh.position(v) += Vec3(step(rng), step(rng), step(rng));
        const SurfaceUpdateStats s = live.update_positions(mesh, {});
        EXPECT_TRUE(live.relaid().empty());
        EXPECT_FALSE(s.layout_changed);
        EXPECT_EQ(s.full, method == Method::cc);
        EXPECT_EQ(s.candidate_patches, live.num_patches());
        EXPECT_GT(s.recomputed_patches, 0);
        expect_same_as_rebuild(live, mesh, {});
        EXPECT_TRUE(live.tessellation().quads == quads);
        EXPECT_TRUE(live.tessellation().uv == uv);
        EXPECT_TRUE(live.tessellation().patch == patch);
      }
    }
  }
}

TEST(IncrementalSurface, UpdatePositionsSkipsPatchesWhoseNetsDidNotChange) {
  // One vertex of a large torus moves: update_positions compares every net but re-evaluates only
  // the few that changed, the same ones update() with the move recomputes.
  HalfedgeMesh mesh = make_torus(30, 20);
  IncrementalSurface by_positions, by_change;
  by_positions.rebuild(mesh, {}, Method::mdc, 2);
  by_change.rebuild(mesh, {}, Method::mdc, 2);
  mesh.position(Vertex(45)) += Vec3(0, 0, 0.1);
  const SurfaceUpdateStats s = by_positions.update_positions(mesh, {});
  by_change.update(mesh, {}, moved(Vertex(45)));
  EXPECT_EQ(s.candidate_patches, by_positions.num_patches());
  EXPECT_LT(s.recomputed_patches, 100);
  EXPECT_EQ(by_positions.recomputed(), by_change.recomputed());
  expect_same_as_rebuild(by_positions, mesh, {});
}

TEST(IncrementalSurface, UpdatePositionsRefusesAMeshWhoseTopologyChanged) {
  JournaledMesh m{make_cube(), {}};
  IncrementalSurface live;
  live.rebuild(m.mesh, {}, Method::mdc, 2);
  const std::vector<Vec3> before = live.tessellation().positions;
  ASSERT_TRUE(m.apply("subdivide-edge 1 2"));
  EXPECT_THROW(live.update_positions(m.mesh, {}), UsageError);
  EXPECT_TRUE(live.tessellation().positions == before);  // nothing changed
}

// Semi-sharp tags: the live surface is built on the mesh refined as build_surface refines it
// (eval/semi_sharp.hpp), and a move, update_positions and a tag edit each give exactly what a
// rebuild on the input refined again gives. Prints what a move costs on a modest mesh (a torus of
// 240 quads, 5 edges at sharpness 2: two levels, 15 360 patches) against a rebuild.
TEST(IncrementalSurface, SemiSharpTagsAreHonouredByRefinementOnEveryUpdate) {
  JournaledMesh m{make_torus(20, 12), {}};
  for (int e : {3, 40, 41, 100, 200}) m.mesh.set_sharpness(Edge(e), 2.0);
  const int corners = static_cast<int>(m.mesh.patch_corners().size());
  // The same surface as build_surface's (the command line's, Python's), bit for bit.
  const auto expect_refined_rebuild = [&m](const IncrementalSurface& live) {
    SurfaceSpec spec;
    spec.method = live.method();
    const BuiltSurface fresh = build_surface(m.mesh, spec);
    ASSERT_EQ(live.refinement().levels, fresh.refinement.levels);
    ASSERT_GT(fresh.refinement.levels, 0);
    test::expect_same_as_surface(live, fresh.mesh(m.mesh), fresh.surface);
  };
  for (Method method : {Method::mdc, Method::asc}) {
    SCOPED_TRACE(to_string(method));
    IncrementalSurface live;
    const SurfaceUpdateStats built = live.rebuild(m.mesh, {}, method, 2);
    EXPECT_EQ(live.refinement().levels, 2);
    EXPECT_EQ(live.num_patches(), corners * 16);
    expect_refined_rebuild(live);
    // A move: the points refined again, only the patches whose nets changed evaluated.
    m.mesh.position(Vertex(5)) += Vec3(0.1, 0.0, 0.05);
    const SurfaceUpdateStats move = live.update(m.mesh, {}, moved(Vertex(5)));
    EXPECT_FALSE(move.layout_changed);
    EXPECT_GT(move.recomputed_patches, 0);
    EXPECT_LT(move.recomputed_patches, live.num_patches() / 10);
    expect_refined_rebuild(live);
    std::printf("%s, %d patches: a move %.1f ms (%d patches evaluated), a rebuild %.1f ms\n",
                to_string(method).c_str(), live.num_patches(), move.milliseconds,
                move.recomputed_patches, built.milliseconds);
    m.mesh.position(Vertex(70)) += Vec3(0.0, -0.1, 0.0);
    live.update_positions(m.mesh, {});
    expect_refined_rebuild(live);
    // A tag edit refines again.
    const Halfedge h = HalfedgeMesh::halfedge(Edge(3), 0);
    const std::string crease = "crease " + std::to_string(m.mesh.origin(h).idx + 1) + " " +
                               std::to_string(m.mesh.target(h).idx + 1) + " 0.5";
    const std::optional<SurfaceChange> tag = m.apply(crease);
    ASSERT_TRUE(tag);
    const SurfaceUpdateStats edit = live.update(m.mesh, {}, *tag);
    EXPECT_TRUE(edit.full);
    expect_refined_rebuild(live);
    live.update(m.mesh, {}, m.undo());
    expect_refined_rebuild(live);
  }
  // Rounding keeps one patch per corner: the tags below sharp_from smooth.
  IncrementalSurface rounded;
  rounded.rebuild(m.mesh, {}, Method::mdc, 2, SemiSharp::round);
  EXPECT_EQ(rounded.refined(), nullptr);
  EXPECT_EQ(rounded.num_patches(), corners);
  expect_same_as_rebuild(rounded, m.mesh, {});
}

// A resolution change lays every block out again: it keeps room as a rebuild does.
TEST(IncrementalSurface, TopologyEditsAfterAResolutionChangeFindRoomToo) {
  JournaledMesh m{make_torus(10, 8), {}};
  IncrementalSurface live;
  live.rebuild(m.mesh, {}, Method::mdc, 4);
  live.set_resolution(m.mesh, {}, 5);
  const Vec3* positions = live.tessellation().positions.data();
  for (int k = 0; k < 10; ++k) {
    const auto change = m.apply("subdivide-edge " + edge_name(m.mesh, Edge(3 * k)));
    ASSERT_TRUE(change) << "edit " << k;
    live.update(m.mesh, {}, *change);
  }
  EXPECT_EQ(live.tessellation().positions.data(), positions);
  expect_same_as_rebuild(live, m.mesh, {});
}

TEST(PatchGrid, LaysOutTheSamplesAndQuadsOfOneBlock) {
  const PatchGrid grid(3);
  EXPECT_EQ(grid.num_samples(), 16);
  EXPECT_EQ(grid.num_quads(), 9);
  EXPECT_EQ(grid.sample(2, 1), 9);
  EXPECT_EQ(grid.row(9), 2);
  EXPECT_EQ(grid.column(9), 1);
  EXPECT_EQ(grid.uv(9), Eigen::Vector2d(2.0 / 3.0, 1.0 / 3.0));
  // Cell (1, 2) = quad 5: samples (1,2) (2,2) (2,3) (1,3), counter-clockwise in (u, v).
  EXPECT_EQ(grid.quad(5, 100), (std::array<std::int64_t, 4>{106, 110, 111, 107}));
  std::vector<std::array<int, 4>> quads(9);
  grid.quads(16, quads.data());
  EXPECT_EQ(quads[5], (std::array<int, 4>{22, 26, 27, 23}));
  EXPECT_THROW(PatchGrid(0), UsageError);
}

// The first topology edit after a rebuild finds room in the surface's arrays: it writes its new
// slots in place instead of moving every sample (which took 400 ms at 10k faces). Tested through
// the arrays' addresses, which move exactly when a vector reallocates.
TEST(IncrementalSurface, FirstTopologyEditsFindRoomInTheArrays) {
  JournaledMesh m{make_torus(10, 8), {}};
  IncrementalSurface live;
  live.rebuild(m.mesh, {}, Method::mdc, 4);
  const Vec3* positions = live.tessellation().positions.data();
  const std::array<int, 4>* quads = live.tessellation().quads.data();
  const int slots = m.mesh.halfedge_capacity();
  // Subdividing edges adds two slots each: 20 edits stay well inside the room for half as many
  // slots again (slot_capacity_for).
  for (int k = 0; k < 20; ++k) {
    const auto change = m.apply("subdivide-edge " + edge_name(m.mesh, Edge(3 * k)));
    ASSERT_TRUE(change) << "edit " << k;
    live.update(m.mesh, {}, *change);
  }
  ASSERT_GT(m.mesh.halfedge_capacity(), slots);
  ASSERT_LE(m.mesh.halfedge_capacity(), slot_capacity_for(slots));
  EXPECT_EQ(live.tessellation().positions.data(), positions);
  EXPECT_EQ(live.tessellation().quads.data(), quads);
  expect_same_as_rebuild(live, m.mesh, {});
}

}  // namespace
}  // namespace stitch
