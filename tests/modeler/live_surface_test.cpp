// The incremental surface update: after a local edit exactly the patches whose control nets
// changed are recomputed, and the result is identical (bit for bit, since the same code runs on
// the same numbers) to building everything from scratch.
#include "stitch/modeler/live_surface.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "stitch/mesh/io.hpp"
#include "stitch/modeler/navigation.hpp"
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
  const TessellatedMesh expected = tessellate(mesh, fresh, t);
  const TessellatedMesh& got = live.tessellation();
  // Live corner k's block in `expected` is corner c's slot in `got` (blocks indexed by corner).
  const int per = live.vertices_per_patch(), per_quads = live.quads_per_patch();
  const auto corners = mesh.patch_corners();
  ASSERT_EQ(expected.num_vertices(), static_cast<int>(corners.size()) * per);
  ASSERT_EQ(got.num_vertices(), mesh.halfedge_capacity() * per);
  ASSERT_EQ(live.corners(), corners);
  int mismatches = 0;
  for (size_t k = 0; k < corners.size(); ++k) {
    const int a = static_cast<int>(k) * per, b = corners[k].idx * per;
    for (int s = 0; s < per; ++s) {
      const bool same =
          got.positions[b + s] == expected.positions[a + s] &&
          got.normals[b + s] == expected.normals[a + s] && got.uv[b + s] == expected.uv[a + s] &&
          got.patch[b + s] == expected.patch[a + s] && got.level[b + s] == expected.level[a + s];
      mismatches += same ? 0 : 1;
    }
    for (int q = 0; q < per_quads; ++q)
      for (int i = 0; i < 4; ++i)
        mismatches += got.quads[corners[k].idx * per_quads + q][i] - b ==
                              expected.quads[k * per_quads + q][i] - a
                          ? 0
                          : 1;
  }
  EXPECT_EQ(mismatches, 0);
  for (Corner c : corners) EXPECT_TRUE(live.nets()[c.idx] == fresh.bezier().nets[c.idx]);
}

/// Applies `change` (already made to doc) and checks that the recomputed set is exactly the
/// set of live corners whose nets differ between before and a from-scratch rebuild after (a
/// corner without a live patch before counts as changed).
void check_update(LiveSurface& live, const Document& doc, const Change& change) {
  const std::vector<ControlNet> before = live.nets();
  const std::vector<Corner> live_before = live.corners();
  const UpdateStats stats = live.update(doc.mesh(), doc.kgon_options(), change);
  const std::vector<ControlNet> fresh =
      build_control_nets(doc.mesh(), build_kgons(doc.mesh(), doc.kgon_options()));
  std::vector<Corner> changed;
  for (Corner c : doc.mesh().patch_corners()) {
    const bool existed = std::binary_search(live_before.begin(), live_before.end(), c);
    if (!existed || before[c.idx] != fresh[c.idx]) changed.push_back(c);
  }
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
          {"pyramid", read_mesh(test::opensubdiv_shape("catmark_pyramid.obj"))},
          {"open_creased", [] {
             HalfedgeMesh m = make_torus(6, 5);
             m.set_hole(Face(3), true);
             for (int e : {0, 1, 7, 12}) m.set_sharpness(Edge(e), infinitely_sharp);
             m.set_sharpness(Vertex(9), infinitely_sharp);
             return m;
           }()}};
}

TEST(ModelerLiveSurface, VertexMovesRecomputeExactlyTheChangedPatches) {
  std::mt19937 rng(7);
  for (Method method : {Method::mdc, Method::asc}) {
    for (Case& c : cases()) {
      SCOPED_TRACE(c.name + " " + to_string(method));
      Document doc(c.mesh);
      LiveSurface live;
      live.rebuild(doc.mesh(), doc.kgon_options(), method, 3);
      const auto vertices = doc.mesh().vertices().to_vector();
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
    check_update(live, doc,
                 doc.set_kgon_control({KgonKind::face, doc.mesh().faces().to_vector()[0].idx}, k));
    check_update(
        live, doc,
        doc.set_kgon_control({KgonKind::vertex, doc.mesh().vertices().to_vector()[1].idx}, k));
    k.offset = Vec3(0.05, 0.0, -0.02);
    check_update(live, doc,
                 doc.set_kgon_control({KgonKind::edge, doc.mesh().edges().to_vector()[2].idx}, k));
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

/// Applies the operation lines in turn, checking each update against a rebuild; returns how many
/// applied. A refused line changes nothing; with `all_apply` it is a failure.
int apply_checked(Document& doc, LiveSurface& live, const std::vector<std::string>& ops,
                  bool all_apply) {
  int applied = 0;
  for (const std::string& op : ops) {
    SCOPED_TRACE(op);
    Change c;
    try {
      c = doc.apply_operation(op);
    } catch (const Error& e) {
      if (all_apply) ADD_FAILURE() << "refused: " << e.what();
      continue;
    }
    ++applied;
    check_update(live, doc, c);
  }
  return applied;
}

TEST(ModelerLiveSurface, TopologyEditsRecomputeExactlyTheChangedPatches) {
  const std::vector<std::string> ops{
      "insert-edge 1@1 5@2", "subdivide-edge 2 3",  "collapse-edge 3 9", "extrude-face 3 0.4",
      "delete-edge 1 5@1",   "insert-edge 6@3 8@3", "delete-face 4",     "connect-faces 3 5"};
  for (Method method : {Method::mdc, Method::asc}) {
    SCOPED_TRACE(to_string(method));
    Document doc(make_cube());
    LiveSurface live;
    live.rebuild(doc.mesh(), doc.kgon_options(), method, 2);
    const int applied = apply_checked(doc, live, ops, false);
    EXPECT_GE(applied, 5);
    for (int i = 0; i < applied; ++i) check_update(live, doc, doc.undo());
    EXPECT_TRUE(doc.mesh() == make_cube());
    // A remeshing renumbers everything: rebuilt in full, both ways.
    for (int step = 0; step < 2; ++step) {
      const Change c = step == 0 ? doc.apply_operation("catmull-clark") : doc.undo();
      EXPECT_TRUE(c.whole);
      EXPECT_TRUE(live.update(doc.mesh(), doc.kgon_options(), c).full);
      expect_same_as_rebuild(live, doc.mesh(), doc.kgon_options());
    }
    EXPECT_TRUE(doc.mesh() == make_cube());
  }
}

TEST(ModelerLiveSurface, HolesCreasesAndCornersUpdateExactly) {
  // Tags and holes change no connectivity, yet they change which patches exist and which sides
  // are sharp curves: each edit is checked against a rebuild, then all are undone.
  const std::vector<std::string> ops{"open-face 2",        "crease 1 2 10", "corner 3 10",
                                     "crease 2 3 10",      "crease 1 2 0",  "insert-edge 1@1 3@1",
                                     "subdivide-edge 3 4", "fill-hole 2",   "open-face 4",
                                     "extrude-face 1 0.3"};
  for (Method method : {Method::mdc, Method::asc}) {
    SCOPED_TRACE(to_string(method));
    Document doc(make_cube());
    LiveSurface live;
    live.rebuild(doc.mesh(), doc.kgon_options(), method, 2);
    const int applied = apply_checked(doc, live, ops, true);
    EXPECT_EQ(applied, static_cast<int>(ops.size()));
    for (int i = 0; i < applied; ++i) check_update(live, doc, doc.undo());
    EXPECT_TRUE(doc.mesh() == make_cube());
  }
}

TEST(ModelerLiveSurface, RandomTopologyEditsStayExact) {
  // Random operator lines on a torus (fixed seed), each checked against a from-scratch rebuild,
  // then all undone.
  std::mt19937 rng(11);
  Document doc(make_torus(6, 5));
  LiveSurface live;
  live.rebuild(doc.mesh(), doc.kgon_options(), Method::mdc, 2);
  auto pick_from = [&](const auto& list) {
    return list[std::uniform_int_distribution<size_t>(0, list.size() - 1)(rng)];
  };
  auto without_kind = [](const std::string& d) { return d.substr(d.find(' ') + 1); };
  int applied = 0;
  for (int i = 0; i < 40; ++i) {
    const HalfedgeMesh& m = doc.mesh();
    std::string line;
    switch (i % 5) {
      case 0: {  // split a face between two of its corners
        const Face f = pick_from(m.faces().to_vector());
        const auto loop = m.face_loop(f);
        const Pick a{PickKind::corner, pick_from(loop).idx},
            b{PickKind::corner, pick_from(loop).idx};
        line = "insert-edge " + without_kind(describe(m, a)) + " " + without_kind(describe(m, b));
        break;
      }
      case 1:
        line =
            "subdivide-edge " +
            without_kind(describe(m, {PickKind::edge, pick_from(m.halfedges().to_vector()).idx}));
        break;
      case 2:
        line = "delete-edge " + without_kind(describe(
                                    m, {PickKind::edge, pick_from(m.halfedges().to_vector()).idx}));
        break;
      case 3:
        line =
            "collapse-edge " +
            without_kind(describe(m, {PickKind::edge, pick_from(m.halfedges().to_vector()).idx}));
        break;
      default:
        line = "extrude-face " + std::to_string(pick_from(m.faces().to_vector()).idx + 1) + " 0.2";
        break;
    }
    SCOPED_TRACE(line);
    Change c;
    try {
      c = doc.apply_operation(line);
    } catch (const Error&) {
      continue;  // refused: nothing changed
    }
    ++applied;
    check_update(live, doc, c);
  }
  EXPECT_GE(applied, 20);
  while (doc.can_undo()) check_update(live, doc, doc.undo());
  EXPECT_TRUE(doc.mesh() == make_torus(6, 5));
}

TEST(ModelerLiveSurface, InsertEdgeIsLocal) {
  Document doc(make_torus(30, 20));
  LiveSurface live;
  live.rebuild(doc.mesh(), doc.kgon_options(), Method::mdc, 2);
  const UpdateStats s =
      live.update(doc.mesh(), doc.kgon_options(), doc.apply_operation("insert-edge 1@1 22@1"));
  EXPECT_FALSE(s.full);
  EXPECT_TRUE(s.layout_changed);  // two new corners
  EXPECT_LT(s.recomputed_patches, 100);
  expect_same_as_rebuild(live, doc.mesh(), doc.kgon_options());
}

TEST(ModelerLiveSurface, MethodAndResolutionChangesRebuildEverything) {
  Document doc(make_cube());
  LiveSurface live;
  live.rebuild(doc.mesh(), doc.kgon_options(), Method::mdc, 3);
  check_update(live, doc, doc.apply_operation("insert-edge 1@1 5@2"));
  live.set_method(doc.mesh(), doc.kgon_options(), Method::asc);
  expect_same_as_rebuild(live, doc.mesh(), doc.kgon_options());
  live.set_resolution(doc.mesh(), doc.kgon_options(), 5);
  expect_same_as_rebuild(live, doc.mesh(), doc.kgon_options());
  check_update(live, doc, doc.move_vertices({Vertex(2)}, {Vec3(1.2, 1.1, -1.0)}));
  // The 10-sided face that runs along the bridge twice (cc takes Catmull-Clark steps first).
  live.set_method(doc.mesh(), doc.kgon_options(), Method::cc);
  EXPECT_EQ(live.method(), Method::cc);
  expect_same_as_rebuild(live, doc.mesh(), doc.kgon_options());
  check_update(live, doc, doc.undo());  // the move
  check_update(live, doc, doc.undo());  // the bridge
  check_update(live, doc, doc.move_vertices({Vertex(3)}, {Vec3(-1.2, 1.1, -1.0)}));
}

}  // namespace
}  // namespace stitch::modeler
