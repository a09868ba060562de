// Randomized checks of the topology operators (fixed seeds): insert/delete round trips in both
// orders, and a stress run of thousands of random operations with the validator after each.
#include <gtest/gtest.h>

#include <chrono>
#include <random>

#include "stitch/mesh/validate.hpp"
#include "stitch/topology/compare.hpp"
#include "stitch/topology/connect_faces.hpp"
#include "stitch/topology/delete_face.hpp"
#include "stitch/topology/edge_ops.hpp"
#include "stitch/topology/extrude.hpp"
#include "stitch/topology/insert_edge.hpp"
#include "stitch/topology/primitives.hpp"
#include "stitch/topology/remesh.hpp"

namespace stitch {
namespace {

using Rng = std::mt19937;

int uniform(Rng& rng, int lo, int hi) {
  return std::uniform_int_distribution<int>(lo, hi)(rng);
}

HalfedgeMesh random_primitive(Rng& rng) {
  switch (uniform(rng, 0, 6)) {
    case 0:
      return make_tetrahedron();
    case 1:
      return make_cube();
    case 2:
      return make_octahedron();
    case 3:
      return make_dodecahedron();
    case 4:
      return make_icosahedron();
    case 5:
      return make_prism(uniform(rng, 2, 7));
    default:
      return make_torus(uniform(rng, 3, 5), uniform(rng, 3, 5));
  }
}

Halfedge random_halfedge(const HalfedgeMesh& m, Rng& rng) {
  const std::vector<Halfedge> hs = m.halfedges().to_vector();
  return hs[uniform(rng, 0, static_cast<int>(hs.size()) - 1)];
}

Face random_face(const HalfedgeMesh& m, Rng& rng) {
  const std::vector<Face> fs = m.faces().to_vector();
  return fs[uniform(rng, 0, static_cast<int>(fs.size()) - 1)];
}

/// Two corners at different vertices: on one face half of the time, else anywhere.
std::pair<Corner, Corner> random_corners(const HalfedgeMesh& m, Rng& rng) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    const Corner a = random_halfedge(m, rng);
    Corner b;
    if (uniform(rng, 0, 1) == 0) {
      const auto loop = m.loop_from(a);
      b = loop[uniform(rng, 0, static_cast<int>(loop.size()) - 1)];
    } else {
      b = random_halfedge(m, rng);
    }
    if (m.origin(a) != m.origin(b)) return {a, b};
  }
  return {Corner(), Corner()};
}

/// A random mesh: a primitive after a few random edge insertions (handles, splits, 2-gons).
HalfedgeMesh random_mesh(Rng& rng) {
  HalfedgeMesh m = random_primitive(rng);
  for (int i = uniform(rng, 0, 4); i > 0; --i) {
    const auto [a, b] = random_corners(m, rng);
    if (a.valid()) insert_edge(m, a, b);
  }
  m.garbage_collection();
  return m;
}

TEST(TopologyRandom, InsertThenDeleteRestoresTheMesh) {
  Rng rng(20261121);
  int splits = 0, merges = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const HalfedgeMesh original = random_mesh(rng);
    HalfedgeMesh m = original;
    const auto [a, b] = random_corners(m, rng);
    ASSERT_TRUE(a.valid());
    const TopologyStats before = topology_stats(m);
    const InsertEdgeResult r = insert_edge(m, a, b);
    ASSERT_TRUE(find_problems(m).empty()) << find_problems(m).front();
    const TopologyStats mid = topology_stats(m);
    EXPECT_EQ(mid.vertices, before.vertices);
    EXPECT_EQ(mid.edges, before.edges + 1);
    EXPECT_EQ(mid.faces, before.faces + (r.split ? 1 : -1));
    if (r.split) {
      EXPECT_EQ(mid.components, before.components);
      EXPECT_EQ(mid.genus, before.genus);
    } else {
      // Merging joins two components, or adds a handle to one.
      EXPECT_TRUE((mid.components == before.components - 1 && mid.genus == before.genus) ||
                  (mid.components == before.components && mid.genus == before.genus + 1));
    }
    delete_edge(m, r.edge);
    ASSERT_TRUE(find_problems(m).empty()) << find_problems(m).front();
    EXPECT_TRUE(same_up_to_renumbering(m, original)) << "trial " << trial;
    if (r.split) {
      // The split's new face and edge came last and go again: exactly the original arrays.
      m.garbage_collection();
      EXPECT_EQ(m, original) << "trial " << trial;
      ++splits;
    } else {
      ++merges;
    }
  }
  EXPECT_GT(splits, 100);
  EXPECT_GT(merges, 100);
}

TEST(TopologyRandom, DeleteThenInsertRestoresTheMesh) {
  Rng rng(77);
  int done = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const HalfedgeMesh original = random_mesh(rng);
    HalfedgeMesh m = original;
    const Halfedge h = random_halfedge(m, rng), t = HalfedgeMesh::twin(h);
    if (m.valence(m.origin(h)) <= 2 || m.valence(m.origin(t)) <= 2) continue;
    const Halfedge nh = m.next(h), nt = m.next(t);
    const TopologyStats before = topology_stats(m);
    const DeleteEdgeResult d = delete_edge(m, HalfedgeMesh::edge(h));
    ASSERT_TRUE(find_problems(m).empty()) << find_problems(m).front();
    const TopologyStats mid = topology_stats(m);
    EXPECT_EQ(mid.edges, before.edges - 1);
    EXPECT_EQ(mid.faces, before.faces + (d.split ? 1 : -1));
    if (d.split) {
      EXPECT_TRUE((mid.components == before.components + 1 && mid.genus == before.genus) ||
                  (mid.components == before.components && mid.genus == before.genus - 1));
    }
    // The corners the edge left from are the ones to insert it at again.
    insert_edge(m, nt, nh);
    ASSERT_TRUE(find_problems(m).empty());
    EXPECT_TRUE(same_up_to_renumbering(m, original)) << "trial " << trial;
    ++done;
  }
  EXPECT_GT(done, 300);
}

/// One random operation, with its exact expected effect on the counts checked; returns false
/// when the operator refused (then the mesh must be unchanged: checked by the caller).
void random_operation(HalfedgeMesh& m, Rng& rng, int& refusals) {
  const HalfedgeMesh before_mesh = m;
  const TopologyStats b = topology_stats(m);
  const bool big = b.faces > 150;
  const int kind = uniform(rng, 0, 99);
  try {
    if (kind < 30) {
      const auto [x, y] = random_corners(m, rng);
      if (!x.valid()) return;
      // Now and then a deliberately bad pair: the same corner, or two corners at one vertex.
      const Corner y2 = uniform(rng, 0, 9) == 0 ? x : y;
      const bool split = m.face(x) == m.face(y2);
      insert_edge(m, x, y2);
      const TopologyStats a = topology_stats(m);
      EXPECT_EQ(a.edges, b.edges + 1);
      EXPECT_EQ(a.faces, b.faces + (split ? 1 : -1));
    } else if (kind < 60) {
      const Edge e = HalfedgeMesh::edge(random_halfedge(m, rng));
      delete_edge(m, e);
      const TopologyStats a = topology_stats(m);
      EXPECT_EQ(a.edges, b.edges - 1);
      EXPECT_EQ(a.vertices, b.vertices);
    } else if (kind < 70) {
      if (big) return;
      subdivide_edge(m, HalfedgeMesh::edge(random_halfedge(m, rng)));
      const TopologyStats a = topology_stats(m);
      EXPECT_EQ(a.vertices, b.vertices + 1);
      EXPECT_EQ(a.edges, b.edges + 1);
      EXPECT_EQ(a.faces, b.faces);
    } else if (kind < 82) {
      const Halfedge h = random_halfedge(m, rng);
      collapse_edge(m, HalfedgeMesh::edge(h), m.origin(h));
      const TopologyStats a = topology_stats(m);
      EXPECT_EQ(a.vertices, b.vertices - 1);
      EXPECT_EQ(a.edges, b.edges - 1);
      EXPECT_EQ(a.faces, b.faces);
      EXPECT_EQ(a.genus, b.genus);
    } else if (kind < 88) {
      if (big) return;
      const Face f = random_face(m, rng);
      const int k = m.degree(f);
      extrude_face(m, f, 0.25);
      const TopologyStats a = topology_stats(m);
      EXPECT_EQ(a.vertices, b.vertices + k);
      EXPECT_EQ(a.edges, b.edges + 2 * k);
      EXPECT_EQ(a.faces, b.faces + k);
    } else if (kind < 94) {
      if (big) return;
      const Face f = random_face(m, rng), g = random_face(m, rng);
      const int k = m.degree(f);
      connect_faces(m, f, g, uniform(rng, 0, 5));
      const TopologyStats a = topology_stats(m);
      EXPECT_EQ(a.edges, b.edges + k);
      EXPECT_EQ(a.faces, b.faces + k - 2);
      EXPECT_TRUE((a.components == b.components - 1 && a.genus == b.genus) ||
                  (a.components == b.components && a.genus == b.genus + 1));
    } else if (kind < 97) {
      delete_face(m, random_face(m, rng));
    } else {
      if (b.faces > 40) return;
      const int which = uniform(rng, 0, 3);
      HalfedgeMesh r = which == 0   ? dual(m)
                       : which == 1 ? vertex_insertion(m)
                       : which == 2 ? doo_sabin(m)
                                    : catmull_clark_step(m);
      const TopologyStats a = topology_stats(r);
      EXPECT_EQ(a.genus, b.genus);
      EXPECT_EQ(a.components, b.components);
      m = std::move(r);
    }
  } catch (const Error& e) {
    ++refusals;
    EXPECT_FALSE(std::string(e.what()).empty());
    EXPECT_EQ(m, before_mesh) << "refused but changed: " << e.what();
    return;
  }
  const auto problems = find_problems(m);
  ASSERT_TRUE(problems.empty()) << "kind " << kind << ": " << problems.front();
}

TEST(TopologyRandom, StressThousandsOfOperations) {
  Rng rng(4242);
  const auto start = std::chrono::steady_clock::now();
  int refusals = 0, ops = 0;
  for (int run = 0; run < 20; ++run) {
    HalfedgeMesh m = random_primitive(rng);
    for (int i = 0; i < 200; ++i) {
      random_operation(m, rng, refusals);
      ++ops;
      if (HasFatalFailure()) return;
      if (uniform(rng, 0, 49) == 0) m.garbage_collection();
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(ops, 4000);
  EXPECT_GT(refusals, 50);  // the refusal paths were exercised too
  EXPECT_LT(refusals, ops / 2);
  RecordProperty("seconds", std::to_string(seconds));
}

}  // namespace
}  // namespace stitch
