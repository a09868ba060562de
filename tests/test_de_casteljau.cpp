// The split rules of method.md section 4.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "eval/split_net.hpp"
#include "stitch/eval/bezier.hpp"
#include "stitch/eval/bezier_surface.hpp"
#include "stitch/eval/de_casteljau.hpp"
#include "test_support.hpp"

namespace stitch {
namespace {

ControlNet random_net(unsigned seed, std::uint8_t extraordinary) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  ControlNet net;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) net.at(a, b) = Vec3(a + 0.3 * d(rng), b + 0.3 * d(rng), d(rng));
  net.extraordinary = extraordinary;
  return net;
}

/// N = S P S^T written out directly (rows, then columns, halved as cubics).
std::array<std::array<Vec3, 7>, 7> reference_split(const ControlNet& p) {
  auto halve = [](const std::array<Vec3, 4>& q) {
    return std::array<Vec3, 7>{q[0],
                               (q[0] + q[1]) / 2,
                               (q[0] + 2 * q[1] + q[2]) / 4,
                               (q[0] + 3 * q[1] + 3 * q[2] + q[3]) / 8,
                               (q[1] + 2 * q[2] + q[3]) / 4,
                               (q[2] + q[3]) / 2,
                               q[3]};
  };
  std::array<std::array<Vec3, 7>, 4> half;  // [b][i]
  for (int b = 0; b < 4; ++b) half[b] = halve({p.at(0, b), p.at(1, b), p.at(2, b), p.at(3, b)});
  std::array<std::array<Vec3, 7>, 7> n;
  for (int i = 0; i < 7; ++i) {
    const auto col = halve({half[0][i], half[1][i], half[2][i], half[3][i]});
    for (int j = 0; j < 7; ++j) n[i][j] = col[j];
  }
  return n;
}

// All comparisons below are of sums of a few dozen terms of size ~4: 1e-12 is ~1000 ulps.
constexpr double kTol = 1e-12;

TEST(DeCasteljau, TwoStageClassicEqualsTensorHalving) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const ControlNet net = random_net(seed, 0);
    const auto n = split_net(net, SplitRule::classic);
    const auto r = reference_split(net);
    for (int i = 0; i < 7; ++i)
      for (int j = 0; j < 7; ++j) EXPECT_LT((n[i][j] - r[i][j]).norm(), kTol) << i << "," << j;
  }
}

TEST(DeCasteljau, ClassicSplitReproducesThePolynomial) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> d(0.0, 1.0);
  for (unsigned seed = 1; seed <= 10; ++seed) {
    const ControlNet net = random_net(seed, corner00 | corner33);
    const auto children = split(net, SplitRule::classic);
    for (int k = 0; k < 50; ++k) {
      const double u = d(rng), v = d(rng);
      const int qu = u >= 0.5, qv = v >= 0.5;
      const SurfacePoint parent = evaluate_polynomial(net, u, v);
      const SurfacePoint child = evaluate_polynomial(children[2 * qu + qv], 2 * u - qu, 2 * v - qv);
      EXPECT_LT((parent.position - child.position).norm(), kTol);
      EXPECT_LT((parent.du - 2 * child.du).norm(), 1e-10);  // derivatives scale by 2
      EXPECT_LT((parent.dv - 2 * child.dv).norm(), 1e-10);
    }
  }
}

TEST(DeCasteljau, ModifiedSplitKeepsBoundaryCurves) {
  for (int flags : std::initializer_list<int>{corner00, corner30, corner33, corner03,
                                              corner00 | corner33 | corner30}) {
    const ControlNet net = random_net(3 + flags, static_cast<std::uint8_t>(flags));
    const auto classic = split_net(net, SplitRule::classic);
    const auto modified = split_net(net, SplitRule::modified);
    for (int i = 0; i < 7; ++i) {
      EXPECT_EQ(classic[i][0], modified[i][0]);
      EXPECT_EQ(classic[i][6], modified[i][6]);
      EXPECT_EQ(classic[0][i], modified[0][i]);
      EXPECT_EQ(classic[6][i], modified[6][i]);
    }
    // The inner rows next to a regular corner are unchanged too, so a modified patch stays
    // consistent with a regular neighbour.
    if (!(flags & corner33)) {
      EXPECT_LT((classic[5][5] - modified[5][5]).norm(), kTol);
    }
    if (flags & corner00) {
      EXPECT_GT((classic[1][1] - modified[1][1]).norm(), 1e-6);
    }
  }
}

TEST(DeCasteljau, ChildrenKeepOnlyTheirOwnCornerFlag) {
  const ControlNet net = random_net(5, corner00 | corner33);
  const auto c = split(net, SplitRule::modified);
  EXPECT_EQ(c[0].extraordinary, corner00);
  EXPECT_EQ(c[1].extraordinary, 0);  // (0, 1): contains corner 03
  EXPECT_EQ(c[2].extraordinary, 0);  // (1, 0): contains corner 30
  EXPECT_EQ(c[3].extraordinary, corner33);
}

/// Second u-derivative of the polynomial at (u, v), from the net directly.
Vec3 duu(const ControlNet& n, double u, double v) {
  const double bu[4] = {6 * (1 - u), 6 * u - 12 * (1 - u), 6 * (1 - u) - 12 * u, 6 * u};
  const double s = 1 - v;
  const double bv[4] = {s * s * s, 3 * v * s * s, 3 * v * v * s, v * v * v};
  Vec3 r = Vec3::Zero();
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) r += bu[a] * bv[b] * n.at(a, b);
  return r;
}

TEST(DeCasteljau, ModifiedChildrenJoinWithC2) {
  // Across u = 1/2: children (0, qv) and (1, qv) must agree in position and first and second
  // u-derivatives along the whole shared curve.
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const ControlNet net = random_net(seed, corner00 | corner30 | corner33 | corner03);
    const auto c = split(net, SplitRule::modified);
    for (int qv = 0; qv < 2; ++qv)
      for (double t : {0.1, 0.37, 0.5, 0.81}) {
        const ControlNet& left = c[qv];
        const ControlNet& right = c[2 + qv];
        const SurfacePoint a = evaluate_polynomial(left, 1.0, t);
        const SurfacePoint b = evaluate_polynomial(right, 0.0, t);
        EXPECT_LT((a.position - b.position).norm(), kTol);
        EXPECT_LT((a.du - b.du).norm(), 1e-10);
        EXPECT_LT((duu(left, 1.0, t) - duu(right, 0.0, t)).norm(), 1e-9);
      }
  }
}

TEST(DeCasteljau, ModifiedSplitScalesTheKgonRingByHalf) {
  // Around the 3-valent corner of a cube: the inner points P11 of the three patches at that
  // vertex are its K-gon; after the modified split the children's P11 are the same K-gon
  // scaled by 1/2 about the centroid P00, and still in the K-gon plane.
  const HalfedgeMesh cube = test::cube_mesh();
  const BezierSurface s = build_bezier_surface(cube);
  const Vertex v(0);
  for (Corner c : cube.vertex_fan(v)) {
    const ControlNet& net = s.nets[c.idx];
    ASSERT_TRUE(net.extraordinary & corner00);
    const ControlNet child = split(net, SplitRule::modified)[0];
    const Vec3 expected = net.at(0, 0) + 0.5 * (net.at(1, 1) - net.at(0, 0));
    EXPECT_LT((child.at(1, 1) - expected).norm(), kTol);
    const Vec3 n = s.kgons.vertex[v.idx].normal;
    EXPECT_LT(std::abs((child.at(1, 1) - child.at(0, 0)).dot(n)), kTol);
    EXPECT_LT(std::abs((child.at(1, 0) - child.at(0, 0)).dot(n)), kTol);
  }
}

TEST(HierarchicalEvaluation, AgreesWithExplicitSplitsAndScalesDerivatives) {
  const ControlNet net = random_net(11, corner00);
  // (0.3, 0.1) lies in child (0, 0), at (0.6, 0.2) there, and then in that child's child
  // (1, 0), which no longer touches the extraordinary corner.
  const ControlNet c1 = split(net, SplitRule::modified)[0];
  const ControlNet c2 = split(c1, SplitRule::modified)[2];
  ASSERT_TRUE(c2.regular());
  const SurfacePoint direct = evaluate_polynomial(c2, 4 * 0.3 - 1, 4 * 0.1);
  const SurfacePoint sp = evaluate_patch(net, 0.3, 0.1, BezierRule::mdc);
  EXPECT_EQ(sp.level, 2);
  EXPECT_LT((sp.position - direct.position).norm(), kTol);
  EXPECT_LT((sp.du - 4 * direct.du).norm(), 1e-10);
  // Far from the extraordinary corner, in a regular child: the same as the modified split.
  EXPECT_EQ(evaluate_patch(net, 0.9, 0.9, BezierRule::mdc).level, 1);
  // asc never splits.
  EXPECT_EQ(evaluate_patch(net, 0.2, 0.1, BezierRule::asc).level, 0);
}

TEST(HierarchicalEvaluation, ContinuedFromACellGivesTheSameBits) {
  // bezier_patches measures its innermost cells with evaluate_relative from the cell: the same
  // splits of the same nets as evaluate_patch's descent from the root, so equal to the bit
  // (ASSERT_EQ, no tolerance), for cells towards an extraordinary corner at (0, 0) and at (1, 1).
  for (const auto& [bit, child] : {std::pair{corner00, 0}, {corner33, 3}}) {
    const ControlNet root = random_net(5, bit);
    const Vec3 origin = root.p[0];
    ControlNet cell = root;
    for (Vec3& p : cell.p) p -= origin;
    constexpr int kLevel = 6;
    for (int level = 0; level < kLevel; ++level) cell = split(cell, SplitRule::modified)[child];
    const double offset = child == 0 ? 0 : (1 << kLevel) - 1, scale = std::ldexp(1.0, -kLevel);
    for (int i = 0; i <= 8; ++i)
      for (int j = 0; j <= 8; ++j) {
        const double s = i / 8.0, t = j / 8.0;
        const double u = (offset + s) * scale, v = (offset + t) * scale;
        if ((u == 0 || u == 1) && (v == 0 || v == 1)) continue;  // the root's own corner
        // The root's descent gives the sides s = 1 and t = 1 of a cell at (0, 0) to its
        // neighbours (ties go to the upper child).
        if (child == 0 && (i == 8 || j == 8)) continue;
        const SurfacePoint from_root = evaluate_patch(root, u, v, BezierRule::mdc);
        const SurfacePoint from_cell =
            evaluate_relative(cell, origin, s, t, kMaxEvaluationLevel - kLevel);
        ASSERT_EQ(from_cell.position, from_root.position) << u << " " << v;
        ASSERT_EQ(from_cell.normal, from_root.normal) << u << " " << v;
        ASSERT_EQ(from_cell.level + kLevel, from_root.level);
      }
  }
}

}  // namespace
}  // namespace stitch
