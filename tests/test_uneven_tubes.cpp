// Tubes through prisms whose caps are not regular n-gons on the unit circle two apart (issue 13):
// the twisted-tube placement of src/kgon/openings.cpp (docs/method.md, "K-gons of faces that run
// around two openings", items 5 to 8) was fitted on regular prisms, keyed on the rims' corner
// counts. These variants move the vertices of make_prism(n) (the caps stay planar; fixed seeds)
// and sweep every corner pair of the two caps at resolution 16 as test_twisted_tubes.cpp does:
// clean (check_surface), open (the line through the caps' centroids misses the surface), C1 on
// the clean pairs. The twist steps are those of the regular prism the variant was moved from.
// The counts are achieved counts, not goals: most variants fold on their larger twists, and
// method.md, "Uneven rims", says where; only a small jitter (SmallJitterIsClean) leaves every
// pair clean and open. For time (the file runs in about a minute in Release), the jittered caps
// are swept for n up to 10 and the short prisms for n = 4 and 8; method.md gives the counts of
// n = 12, measured once with the same code.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "stitch/topology/primitives.hpp"
#include "tube_sweep.hpp"

namespace stitch {
namespace {

using test::C1Check;
using test::count;
using test::Counts;
using test::PairResult;
using test::sweep;

/// make_prism(n) (bottom cap vertices 0 to n - 1 at z = -1, top cap n to 2n - 1 at z = 1, vertex
/// i at angle 2 pi i / n on the unit circle) with every vertex moved by `move` (index, position).
HalfedgeMesh moved_prism(int n, const std::function<Vec3(int, const Vec3&)>& move) {
  HalfedgeMesh m = make_prism(n);
  for (Vertex v : m.vertices()) m.position(v) = move(v.idx, m.position(v));
  return m;
}

/// Deterministic numbers in [0, 1) (std::mt19937's output is fixed by the standard, unlike the
/// distributions').
class Unit {
 public:
  explicit Unit(std::uint32_t seed) : gen_(seed) {}
  double operator()() { return static_cast<double>(gen_()) / 4294967296.0; }

 private:
  std::mt19937 gen_;
};

/// Each cap vertex's distance from the axis scaled by a factor in [1 - amplitude, 1 + amplitude].
HalfedgeMesh radial_jitter(int n, std::uint32_t seed, double amplitude = 0.2) {
  Unit u(seed);
  return moved_prism(n, [&](int, const Vec3& p) {
    const double s = 1 + amplitude * (2 * u() - 1);
    return Vec3(s * p.x(), s * p.y(), p.z());
  });
}

/// Each cap vertex moved along the unit circle by up to `amplitude` of the angular step either
/// way.
HalfedgeMesh angular_jitter(int n, std::uint32_t seed, double amplitude = 0.3) {
  Unit u(seed);
  return moved_prism(n, [&](int i, const Vec3& p) {
    const double step = 2 * std::numbers::pi / n;
    const double a = step * (i % n) + amplitude * step * (2 * u() - 1);
    return Vec3(std::cos(a), std::sin(a), p.z());
  });
}

/// Unit radius, the caps `height` apart.
HalfedgeMesh with_height(int n, double height) {
  return moved_prism(n, [&](int, const Vec3& p) { return Vec3(p.x(), p.y(), p.z() * height / 2); });
}

/// The top cap at radius 0.5, the bottom one at 1.
HalfedgeMesh frustum(int n) {
  return moved_prism(n, [&](int i, const Vec3& p) {
    const double s = i < n ? 1.0 : 0.5;
    return Vec3(s * p.x(), s * p.y(), p.z());
  });
}

/// Both caps stretched to an ellipse, x twice as long.
HalfedgeMesh elongated(int n) {
  return moved_prism(n, [&](int, const Vec3& p) { return Vec3(2 * p.x(), p.y(), p.z()); });
}

/// What a sweep gave, for the messages: the failing pairs and how they fail.
std::string failures(const std::vector<PairResult>& results) {
  std::string out;
  for (const PairResult& r : results)
    if (!r.clean || !r.open)
      out += "  " + r.op + " (" + std::to_string(r.steps) + " steps): " + std::to_string(r.folds) +
             " folded, " + std::to_string(r.self_intersections) + " crossing" +
             (r.open ? "" : ", axis blocked") + "\n";
  return out;
}

/// Each n's counts by twist (count()), and the largest twist up to which every pair is clean and
/// open (-1: not even every straight tube).
struct Expected {
  std::map<int, Counts> counts;
  int clean_up_to = -1;
};

/// Sweeps the variant make(n) of every n in `expected` and checks its counts.
void expect_counts(const std::string& family, const std::map<int, Expected>& expected,
                   const std::function<HalfedgeMesh(int)>& make,
                   test::TubeKgons kgons = test::TubeKgons::fitted) {
  for (const auto& [n, e] : expected) {
    SCOPED_TRACE(family + ", prism " + std::to_string(n));
    const HalfedgeMesh regular = make_prism(n);
    const auto results =
        sweep(make(n), 1, 2, C1Check::clean_pairs, &regular, test::SweepTessellation::resolution_16,
              test::SweepScope::every_pair, kgons);
    EXPECT_EQ(count(results), e.counts) << failures(results);
    test::expect_clean_and_open(results, e.clean_up_to);
  }
}

/// Every corner pair of each variant clean and open with the controls unfold_tubes chooses.
void expect_every_pair_unfolded(const std::vector<std::pair<std::string, HalfedgeMesh>>& variants) {
  for (const auto& [name, solid] : variants) {
    SCOPED_TRACE(name);
    const int n = solid.degree(Face(0));
    const HalfedgeMesh regular = make_prism(n);
    const auto results =
        sweep(solid, 1, 2, C1Check::clean_pairs, &regular, test::SweepTessellation::resolution_16,
              test::SweepScope::every_pair, test::TubeKgons::unfolded);
    EXPECT_EQ(static_cast<int>(results.size()), n * n);
    test::expect_clean_and_open(results, n);
  }
}

TEST(UnevenTubes, CapsWithRadialJitter) {
  // Each cap vertex's distance from the axis times 0.8 to 1.2 (seed 1300 + n). Prism 12 (not
  // swept here): 106 of 144 clean, all open.
  expect_counts(
      "radial jitter",
      {{4, {{{-1, {16, 16, 16}}, {0, {4, 4, 4}}, {1, {8, 8, 8}}, {2, {4, 4, 4}}}, 2}},
       {6,
        {{{-1, {36, 30, 36}}, {0, {6, 6, 6}}, {1, {12, 12, 12}}, {2, {12, 12, 12}}, {3, {6, 0, 6}}},
         2}},
       {8,
        {{{-1, {64, 57, 64}},
          {0, {8, 8, 8}},
          {1, {16, 16, 16}},
          {2, {16, 16, 16}},
          {3, {16, 14, 16}},
          {4, {8, 3, 8}}},
         2}},
       {10,
        {{{-1, {100, 84, 100}},
          {0, {10, 10, 10}},
          {1, {20, 20, 20}},
          {2, {20, 20, 20}},
          {3, {20, 19, 20}},
          {4, {20, 11, 20}},
          {5, {10, 4, 10}}},
         2}}},
      [](int n) { return radial_jitter(n, 1300u + static_cast<std::uint32_t>(n)); });
}

TEST(UnevenTubes, CapsWithAngularJitter) {
  // Each cap vertex moved around the unit circle by up to 0.3 of the angular step either way
  // (seed 2300 + n): no tube is straight any more. Prism 12 (not swept here): 125 of 144 clean,
  // 142 open.
  expect_counts(
      "angular jitter",
      {{4, {{{-1, {16, 14, 16}}, {0, {4, 4, 4}}, {1, {8, 8, 8}}, {2, {4, 2, 4}}}, 1}},
       {6,
        {{{-1, {36, 33, 33}}, {0, {6, 6, 6}}, {1, {12, 12, 12}}, {2, {12, 12, 12}}, {3, {6, 3, 3}}},
         2}},
       {8,
        {{{-1, {64, 64, 64}},
          {0, {8, 8, 8}},
          {1, {16, 16, 16}},
          {2, {16, 16, 16}},
          {3, {16, 16, 16}},
          {4, {8, 8, 8}}},
         4}},
       {10,
        {{{-1, {100, 99, 100}},
          {0, {10, 10, 10}},
          {1, {20, 20, 20}},
          {2, {20, 20, 20}},
          {3, {20, 20, 20}},
          {4, {20, 20, 20}},
          {5, {10, 9, 10}}},
         4}}},
      [](int n) { return angular_jitter(n, 2300u + static_cast<std::uint32_t>(n)); });
}

TEST(UnevenTubes, SmallJitterIsClean) {
  // A quarter of the jitter above, with the same seeds: every pair is clean and open but one of
  // prism 10's with radial jitter, `insert-edge 2@1 17@2` (five steps), whose one folded pair of
  // triangles came with the split of quads along their shorter diagonal (method.md, "Quads split
  // along the shorter diagonal"). Measured once for prisms 6, 8 and 10 with these seeds, with the
  // split along the first diagonal: up to 0.05 of the radius and 0.075 of the step every pair
  // was clean; at 0.1 and 0.15, 35 and 31 of prism 6's 36 pairs were, 64 and 61 of prism 8's 64,
  // 92 and 100 of prism 10's 100 (prisms 6 and 10 here, for time).
  for (int n : {6, 10}) {
    SCOPED_TRACE("prism " + std::to_string(n));
    const HalfedgeMesh regular = make_prism(n);
    for (const bool angular : {false, true}) {
      const auto seed = (angular ? 2300u : 1300u) + static_cast<std::uint32_t>(n);
      const HalfedgeMesh mesh =
          angular ? angular_jitter(n, seed, 0.075) : radial_jitter(n, seed, 0.05);
      const auto results = sweep(mesh, 1, 2, C1Check::clean_pairs, &regular);
      const int folding = n == 10 && !angular ? 1 : 0;
      EXPECT_EQ(count(results).at(-1), (Counts{n * n, n * n - folding, n * n}))
          << failures(results);
      test::expect_clean_and_open(results, n / 2 - folding);
    }
  }
}

TEST(UnevenTubes, ShortAndLongPrisms) {
  // Unit radius, height 0.5 and 6 (the regular prisms' is 2). Before the straight tube's K-gon
  // was cut across to the tube's radius, every straight tube at height 6 folded and crossed
  // itself (prism 4 100 folded pairs each, prism 8 240, prism 12 456 to 468). Before the far
  // point's direction was taken across the far corner, 1 of prism 4's straight tubes at height 0.5
  // folded (8 pairs). Prism 12 at height 0.5, not swept here for time: 60 of 144 pairs clean
  // (every twist of three steps and more folds), 84 open.
  expect_counts("height 0.5",
                {{4, {{{-1, {16, 12, 12}}, {0, {4, 4, 4}}, {1, {8, 8, 8}}, {2, {4, 0, 0}}}, 1}},
                 {8,
                  {{{-1, {64, 56, 64}},
                    {0, {8, 8, 8}},
                    {1, {16, 16, 16}},
                    {2, {16, 16, 16}},
                    {3, {16, 16, 16}},
                    {4, {8, 0, 8}}},
                   3}}},
                [](int n) { return with_height(n, 0.5); });
  expect_counts("height 6",
                {{4, {{{-1, {16, 0, 16}}, {0, {4, 0, 4}}, {1, {8, 0, 8}}, {2, {4, 0, 4}}}, -1}},
                 {8,
                  {{{-1, {64, 56, 64}},
                    {0, {8, 8, 8}},
                    {1, {16, 16, 16}},
                    {2, {16, 16, 16}},
                    {3, {16, 16, 16}},
                    {4, {8, 0, 8}}},
                   3}},
                 {12,
                  {{{-1, {144, 84, 144}},
                    {0, {12, 12, 12}},
                    {1, {24, 24, 24}},
                    {2, {24, 24, 24}},
                    {3, {24, 24, 24}},
                    {4, {24, 0, 24}},
                    {5, {24, 0, 24}},
                    {6, {12, 0, 12}}},
                   3}}},
                [](int n) { return with_height(n, 6); });
}

TEST(UnevenTubes, Frustum) {
  // The top cap at radius 0.5, the bottom one at 1. Before the straight tube's K-gon was cut to
  // the tube's radius, 4 of prism 10's straight tubes folded (5 pairs each).
  expect_counts(
      "frustum",
      {{6,
        {{{-1, {36, 30, 36}}, {0, {6, 6, 6}}, {1, {12, 12, 12}}, {2, {12, 12, 12}}, {3, {6, 0, 6}}},
         2}},
       {10,
        {{{-1, {100, 10, 100}},
          {0, {10, 10, 10}},
          {1, {20, 0, 20}},
          {2, {20, 0, 20}},
          {3, {20, 0, 20}},
          {4, {20, 0, 20}},
          {5, {10, 0, 10}}},
         0}}},
      frustum);
}

TEST(UnevenTubes, EllipticCaps) {
  // Both caps twice as long along x as across. Before the far point's direction was taken
  // across the far corner, 4 of prism 10's straight tubes folded (2 pairs each).
  expect_counts(
      "ellipse",
      {{6,
        {{{-1, {36, 18, 22}}, {0, {6, 6, 6}}, {1, {12, 8, 12}}, {2, {12, 4, 4}}, {3, {6, 0, 0}}},
         0}},
       {10,
        {{{-1, {100, 26, 78}},
          {0, {10, 10, 10}},
          {1, {20, 8, 20}},
          {2, {20, 4, 20}},
          {3, {20, 0, 20}},
          {4, {20, 4, 4}},
          {5, {10, 0, 4}}},
         0}}},
      elongated);
}

TEST(UnevenTubes, UnfoldedTubesAreCleanAndOpen) {
  // With the K-gon controls unfold_tubes chooses where the fitted ones fold (what stitch smooth
  // and the modeler build), every pair of these variants is clean and open: the frustum of prism
  // 10 (10 of 100 clean fitted), the radial jitter of prism 10 (79), the angular jitter of prism
  // 8 (56) and prism 8 at height 6 (40). method.md, "Tubes that still fold", has every variant's
  // counts; these four are the ones the search makes whole, within a time a test can take.
  expect_every_pair_unfolded({{"frustum 10", frustum(10)},
                              {"radial jitter 10", radial_jitter(10, 1310u)},
                              {"angular jitter 8", angular_jitter(8, 2308u)},
                              {"prism 8, height 6", with_height(8, 6)}});
}

TEST(UnevenTubes, TheDescentLeavesEveryPairCleanAndOpen) {
  // Where no setting of unfold_tubes' grid is clean, its descent (method.md, "Tubes that still
  // fold") looks on: with it, every pair of every variant of this file, n from 4 to 12, is clean
  // and open at resolution 16 (measured once with a probe; method.md has the table). Swept here,
  // for time, the variants of prism 4 and 6 where the descent does the most: prism 4 six high (12
  // of its 16 pairs no grid setting cleans), prism 6 half as high (6 of 36: its half twists,
  // which cross themselves with the fitted K-gons) and the elliptic prism 6 (14 of 36).
  expect_every_pair_unfolded({{"prism 4, height 6", with_height(4, 6)},
                              {"prism 6, height 0.5", with_height(6, 0.5)},
                              {"ellipse 6", elongated(6)}});
}

TEST(UnevenTubes, KgonControlsRepairFoldingTubes) {
  // Where the placement folds a tube, the per-element K-gon controls (docs/modeler.md: scale and
  // rotate the merged face's K-gon, scale the bridge's edge K-gon) leave it clean and open:
  // the fitted items 5 to 8 miss these tubes, not the method (method.md, "Uneven rims"). Each
  // control was picked from the middle of the clean ones of a sweep over face scale 0.4 to 1.6,
  // rotation -30 to 30 degrees and bridge scale 0.5 to 1.5 (prism 16's edge of that region:
  // 1.1 to 1.3 at -35 to -20 degrees). Resolution 16; the default placement folds every one or
  // blocks its axis.
  struct Repair {
    std::string name;
    HalfedgeMesh solid;
    std::string op;
    KgonControl face, bridge;
  };
  // Three more that folded (prism 8 six high and half as high, three steps; prism 14's half
  // twist) are clean and open with the fitted K-gons since quads are split along their shorter
  // diagonal; prism 16's half twist is clean but its axis blocked.
  const std::vector<Repair> repairs{
      {"frustum 10, one step", frustum(10), "insert-edge 1@1 12@2", {0.6, 0}, {}},
      {"frustum 10, three steps", frustum(10), "insert-edge 1@1 14@2", {0.7, -20}, {}},
      {"prism 16, half twist", make_prism(16), "insert-edge 1@1 25@2", {1.2, -30}, {}}};
  for (const Repair& r : repairs) {
    SCOPED_TRACE(r.name);
    const Vec3 ca = test::face_centre(r.solid, Face(0)), cb = test::face_centre(r.solid, Face(1));
    const PairResult placed = test::check_tube(r.solid, r.op, ca, cb);
    EXPECT_FALSE(placed.clean && placed.open) << "the placement alone is clean now: " << r.op;
    // The insert-edge merges both caps into face 1 and adds the mesh's next edge.
    KgonOptions controls;
    controls.face[0] = r.face;
    controls.edge[r.solid.edge_capacity()] = r.bridge;
    const PairResult repaired = test::check_tube(r.solid, r.op, ca, cb, C1Check::every_pair,
                                                 test::SweepTessellation::resolution_16, controls);
    EXPECT_TRUE(repaired.clean) << r.op << "\n" << repaired.problems;
    EXPECT_TRUE(repaired.open) << r.op;
  }
}

}  // namespace
}  // namespace stitch
