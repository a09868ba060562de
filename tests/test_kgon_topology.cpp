// The K-gons' topology apart from their point data: a set prepared once and placed again after
// the vertices moved is exactly (==, bit for bit) what build_kgons makes of the moved mesh.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "stitch/kgon/kgon_topology.hpp"
#include "stitch/tess/incremental_surface.hpp"
#include "stitch/topology/operation.hpp"
#include "stitch/topology/primitives.hpp"
#include "test_support.hpp"

namespace stitch {
namespace {

/// Every field of the two sets is equal, exactly; counts the K-gons that differ.
void expect_same_kgons(const KgonSet& got, const KgonSet& expected) {
  auto differing = [](const std::vector<Kgon>& a, const std::vector<Kgon>& b) {
    if (a.size() != b.size()) return -1;
    int n = 0;
    for (size_t i = 0; i < a.size(); ++i)
      n += a[i].points == b[i].points && a[i].corners == b[i].corners &&
                   a[i].centroid == b[i].centroid && a[i].normal == b[i].normal
               ? 0
               : 1;
    return n;
  };
  EXPECT_EQ(differing(got.face, expected.face), 0) << "face K-gons";
  EXPECT_EQ(differing(got.vertex, expected.vertex), 0) << "vertex K-gons";
  EXPECT_EQ(differing(got.edge, expected.edge), 0) << "edge K-gons";
  EXPECT_TRUE(got.corner_point == expected.corner_point);
  EXPECT_TRUE(got.in_face == expected.in_face);
  EXPECT_TRUE(got.in_vertex == expected.in_vertex);
  EXPECT_TRUE(got.in_next_edge == expected.in_next_edge);
  EXPECT_TRUE(got.in_prev_edge == expected.in_prev_edge);
  EXPECT_TRUE(got.vertex_k == expected.vertex_k);
  EXPECT_TRUE(got.sharp_curve == expected.sharp_curve);
  EXPECT_TRUE(got.cone == expected.cone);
  EXPECT_TRUE(got.sharp_edge == expected.sharp_edge);
}

HalfedgeMesh edited(HalfedgeMesh m, const std::string& op) {
  apply_operation(m, op);
  return m;
}

struct Case {
  std::string name;
  HalfedgeMesh mesh;
  KgonOptions options;
};

std::vector<Case> cases() {
  KgonOptions controls;
  controls.global.scale = 0.8;
  controls.global.rotate_deg = 10;
  controls.face[0].regularize = true;
  controls.vertex[2].offset = Vec3(0.01, 0.02, 0.03);
  controls.edge[1].scale = 1.2;
  KgonOptions section2;
  section2.construction = KgonConstruction::doo_sabin;
  KgonOptions smooth_boundary;
  smooth_boundary.boundary = BoundaryInterpolation::edge_only;
  const BuildOptions holes{false, true};
  std::vector<Case> out{
      {"cube", make_cube(), {}},
      {"torus with controls", make_torus(8, 6), controls},
      {"tetrahedron", make_tetrahedron(), {}},
      {"cube_hole (open)", read_mesh(test::example_path("cube_hole.obj"), holes), {}},
      {"cube_hole, edge-only boundary", read_mesh(test::example_path("cube_hole.obj"), holes),
       smooth_boundary},
      {"open_box", read_mesh(test::example_path("open_box.obj"), holes), {}},
      {"cube_creased", read_mesh(test::example_path("cube_creased.obj"), holes), {}},
      {"catmark_torus_creases0",
       read_mesh(test::opensubdiv_shape("catmark_torus_creases0.obj"), holes),
       {}},
      {"catmark_pyramid", read_mesh(test::opensubdiv_shape("catmark_pyramid.obj")), {}},
      {"catmark_car", read_mesh(test::opensubdiv_shape("catmark_car.obj"), holes), {}},
      {"tube", edited(make_cube(), "insert-edge 1@1 5@2"), {}},
      {"twisted tube", edited(make_cube(), "insert-edge 1@1 6@2"), {}},
      {"twisted tube, section 2", edited(make_cube(), "insert-edge 1@1 6@2"), section2},
      {"corner and crease tags", edited(edited(make_cube(), "crease 1 2 10"), "corner 7 10"),
       controls},
  };
  return out;
}

// The tube meshes are only worth their place if the openings construction sees their openings.
TEST(KgonTopology, FindsTheOpeningsOfAMergedFace) {
  const KgonTopology t = prepare_kgons(edited(make_cube(), "insert-edge 1@1 6@2"), {});
  int with_openings = 0;
  for (const auto& o : t.openings) with_openings += o.has_value();
  EXPECT_EQ(with_openings, 1);
  KgonOptions section2;
  section2.construction = KgonConstruction::doo_sabin;
  for (const auto& o : prepare_kgons(edited(make_cube(), "insert-edge 1@1 6@2"), section2).openings)
    EXPECT_FALSE(o.has_value());
}

// One preparation, then rounds of random moves of every vertex (fixed seed): each placement over
// the previous one's set equals a from-scratch build_kgons of the moved mesh.
TEST(KgonTopology, PlacedAgainAfterEveryVertexMovedEqualsBuildKgons) {
  std::mt19937 rng(15);
  std::uniform_real_distribution<double> step(-0.15, 0.15);
  for (Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const KgonTopology topology = prepare_kgons(c.mesh, c.options);
    KgonSet set = topology.skeleton;
    place_kgons(c.mesh, c.options, topology, set);
    expect_same_kgons(set, build_kgons(c.mesh, c.options));
    for (int round = 0; round < 3; ++round) {
      for (Vertex v : c.mesh.vertices())
        c.mesh.position(v) += Vec3(step(rng), step(rng), step(rng));
      EXPECT_TRUE(topology.fits(c.mesh, c.options));
      place_kgons(c.mesh, c.options, topology, set);
      expect_same_kgons(set, build_kgons(c.mesh, c.options));
    }
  }
}

TEST(KgonTopology, FitsOnlyTheCapacitiesAndOptionsItWasPreparedFor) {
  const HalfedgeMesh cube = make_cube();
  const KgonTopology t = prepare_kgons(cube, {});
  EXPECT_TRUE(t.fits(cube, {}));
  KgonOptions controls;
  controls.global.scale = 0.5;  // controls are applied with the points
  EXPECT_TRUE(t.fits(cube, controls));
  KgonOptions other;
  other.construction = KgonConstruction::doo_sabin;
  EXPECT_FALSE(t.fits(cube, other));
  other = {};
  other.boundary = BoundaryInterpolation::edge_only;
  EXPECT_FALSE(t.fits(cube, other));
  other = {};
  other.sharp_from = 2;
  EXPECT_FALSE(t.fits(cube, other));
  EXPECT_FALSE(t.fits(edited(cube, "subdivide-edge 1 2"), {}));
}

// update_positions keeps the prepared topology between calls: its K-gons stay those of a build.
TEST(KgonTopology, UpdatePositionsKeepsItsKgonsEqualToABuild) {
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> step(-0.15, 0.15);
  for (Case& c : cases()) {
    SCOPED_TRACE(c.name);
    IncrementalSurface live;
    // Rounded: the K-gons are the input's (catmark_torus_creases0's semi-sharp tags would
    // otherwise put them on the refined mesh).
    live.rebuild(c.mesh, c.options, Method::mdc, 2, SemiSharp::round);
    for (int round = 0; round < 3; ++round) {
      for (Vertex v : c.mesh.vertices())
        c.mesh.position(v) += Vec3(step(rng), step(rng), step(rng));
      live.update_positions(c.mesh, c.options);
      expect_same_kgons(live.kgons(), build_kgons(c.mesh, c.options));
    }
    // New controls reach every K-gon without a new preparation.
    KgonOptions changed = c.options;
    changed.global.scale = 0.6;
    live.update_positions(c.mesh, changed);
    expect_same_kgons(live.kgons(), build_kgons(c.mesh, changed));
    // Options the topology depends on are noticed: it is prepared again.
    changed.construction = KgonConstruction::doo_sabin;
    changed.boundary = BoundaryInterpolation::edge_only;
    live.update_positions(c.mesh, changed);
    expect_same_kgons(live.kgons(), build_kgons(c.mesh, changed));
  }
}

}  // namespace
}  // namespace stitch
