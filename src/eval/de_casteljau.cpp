#include "stitch/eval/de_casteljau.hpp"

#include "eval/split_net.hpp"

namespace stitch {

namespace {

using Net7 = std::array<std::array<Vec3, 7>, 7>;

/// The 7 points of halving a cubic at t = 1/2 (the two halves share the middle one).
std::array<Vec3, 7> halve(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  return {p0,
          (p0 + p1) / 2,
          (p0 + 2 * p1 + p2) / 4,
          (p0 + 3 * p1 + 3 * p2 + p3) / 8,
          (p1 + 2 * p2 + p3) / 4,
          (p2 + p3) / 2,
          p3};
}

}  // namespace

std::array<std::array<Vec3, 7>, 7> split_net(const ControlNet& net, SplitRule rule) {
  // Two-stage form (method.md section 4): bilinear averages B, then the inner 5x5 is T B T^T
  // and the outer ring is the halving of the four boundary curves. The modified rule only
  // changes the corner entries of B at extraordinary corners.
  Vec3 B[3][3];
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      B[a][b] = (net.at(a, b) + net.at(a + 1, b) + net.at(a, b + 1) + net.at(a + 1, b + 1)) / 4;
  if (rule == SplitRule::modified) {
    if (net.extraordinary & corner00) B[0][0] = (net.at(0, 0) + net.at(1, 1)) / 2;
    if (net.extraordinary & corner30) B[2][0] = (net.at(3, 0) + net.at(2, 1)) / 2;
    if (net.extraordinary & corner33) B[2][2] = (net.at(3, 3) + net.at(2, 2)) / 2;
    if (net.extraordinary & corner03) B[0][2] = (net.at(0, 3) + net.at(1, 2)) / 2;
  }
  // T maps 3 points to 5: [1,0,0], [1/2,1/2,0], [1/4,1/2,1/4], [0,1/2,1/2], [0,0,1].
  auto t_apply = [](const Vec3& x0, const Vec3& x1, const Vec3& x2) {
    return std::array<Vec3, 5>{x0, (x0 + x1) / 2, (x0 + 2 * x1 + x2) / 4, (x1 + x2) / 2, x2};
  };
  std::array<Vec3, 5> rows[3];  // T applied along b for each a
  for (int a = 0; a < 3; ++a) rows[a] = t_apply(B[a][0], B[a][1], B[a][2]);
  Net7 n;
  for (int j = 0; j < 5; ++j) {
    const auto col = t_apply(rows[0][j], rows[1][j], rows[2][j]);
    for (int i = 0; i < 5; ++i) n[i + 1][j + 1] = col[i];
  }
  const auto b0 = halve(net.at(0, 0), net.at(1, 0), net.at(2, 0), net.at(3, 0));  // v = 0
  const auto b3 = halve(net.at(0, 3), net.at(1, 3), net.at(2, 3), net.at(3, 3));  // v = 1
  const auto a0 = halve(net.at(0, 0), net.at(0, 1), net.at(0, 2), net.at(0, 3));  // u = 0
  const auto a3 = halve(net.at(3, 0), net.at(3, 1), net.at(3, 2), net.at(3, 3));  // u = 1
  for (int i = 0; i < 7; ++i) {
    n[i][0] = b0[i];
    n[i][6] = b3[i];
    n[0][i] = a0[i];
    n[6][i] = a3[i];
  }
  return n;
}

std::array<ControlNet, 4> split(const ControlNet& net, SplitRule rule) {
  const auto n = split_net(net, rule);
  std::array<ControlNet, 4> children;
  const std::uint8_t corner_bit[2][2] = {{corner00, corner03}, {corner30, corner33}};
  const int corner_index[2][2] = {{0, 3}, {1, 2}};
  for (int qu = 0; qu < 2; ++qu)
    for (int qv = 0; qv < 2; ++qv) {
      ControlNet& c = children[2 * qu + qv];
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) c.at(a, b) = n[3 * qu + a][3 * qv + b];
      // The child keeps only the parent corner it contains.
      c.extraordinary = net.extraordinary & corner_bit[qu][qv];
      c.corner_k = {4, 4, 4, 4};
      c.corner_k[corner_index[qu][qv]] = net.corner_k[corner_index[qu][qv]];
    }
  return children;
}

}  // namespace stitch
