#include "eval/patch_sampler.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "eval/descent.hpp"
#include "stitch/eval/de_casteljau.hpp"

namespace stitch {

namespace {
// Paths deeper than this (points within 2^-20 of an extraordinary corner) are split afresh: they
// are rare in a tessellation, and keeping them would let the cache grow with the resolution.
constexpr int kCachedLevels = 20;
// As deep as Surface::evaluate descends (evaluate_patch's default).
constexpr int kMaxLevel = 60;

// The extraordinary corner a split's child (qu, qv) keeps of its parent's: its own corner.
constexpr std::uint8_t kChildCorner[2][2] = {{corner00, corner03}, {corner30, corner33}};

using detail::LaneNet;
using detail::Lanes;

// The target_clones of the lane code: see polynomial_block.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define STITCH_LANE_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define STITCH_LANE_CLONES
#endif

void to_lanes(const Vec3& p, Lanes& out) {
  out = Lanes{p.x(), p.y(), p.z(), 0.0};
}

ControlNet to_net(const LaneNet& net) {
  ControlNet n;
  for (int k = 0; k < 16; ++k) n.p[k] = Vec3(net.p[k][0], net.p[k][1], net.p[k][2]);
  n.extraordinary = net.extraordinary;
  return n;
}

// Eigen's squaredNorm of a Vec3, as polynomial_block sums it.
double squared_norm(const Lanes& p) {
  return p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
}

// detail::patch_normal for a LaneNet (out of line: the degenerate points are rare).
[[gnu::noinline, gnu::cold]] Vec3 lane_patch_normal(const LaneNet& net, double u, double v,
                                                    const Lanes& du, const Lanes& dv, double tiny) {
  return detail::patch_normal(to_net(net), u, v, Vec3(du[0], du[1], du[2]),
                              Vec3(dv[0], dv[1], dv[2]), tiny);
}

// detail::degenerate_threshold.
double lane_threshold(const LaneNet& net) {
  const Lanes d0 = net.p[15] - net.p[0], d1 = net.p[12] - net.p[3];
  const double size2 = std::max(squared_norm(d0), squared_norm(d1));
  return 1e-24 * size2 * size2;
}

// split_net's T: 3 points to 5, each handed to store(k, point).
template <class Store>
[[gnu::always_inline]] inline void t_apply(const Lanes& x0, const Lanes& x1, const Lanes& x2,
                                           Store&& store) {
  store(0, x0);
  store(1, (x0 + x1) / 2.0);
  store(2, (x0 + 2.0 * x1 + x2) / 4.0);
  store(3, (x1 + x2) / 2.0);
  store(4, x2);
}

// split_net's halve: the 7 points of a cubic halved at t = 1/2, each handed to store(k, point).
template <class Store>
[[gnu::always_inline]] inline void halve(const Lanes& p0, const Lanes& p1, const Lanes& p2,
                                         const Lanes& p3, Store&& store) {
  store(0, p0);
  store(1, (p0 + p1) / 2.0);
  store(2, (p0 + 2.0 * p1 + p2) / 4.0);
  store(3, (p0 + 3.0 * p1 + 3.0 * p2 + p3) / 8.0);
  store(4, (p1 + 2.0 * p2 + p3) / 4.0);
  store(5, (p2 + p3) / 2.0);
  store(6, p3);
}

// split(net, SplitRule::modified) in lanes: split_net's operations on each coordinate in its
// order (the same bits). Each point N[i][j] of the 7x7 net is stored straight into the children
// that hold it (one, two or four), without the 7x7 net in between.
STITCH_LANE_CLONES
void split_lanes(const LaneNet& __restrict net, LaneNet* __restrict children) {
  const Lanes* P = net.p;
  const auto at = [P](int a, int b) -> const Lanes& { return P[4 * a + b]; };
  const auto put = [children](int i, int j, const Lanes& x) {
    for (int qu = 0; qu < 2; ++qu) {
      const int a = i - 3 * qu;
      if (a < 0 || a > 3) continue;
      for (int qv = 0; qv < 2; ++qv) {
        const int b = j - 3 * qv;
        if (b >= 0 && b <= 3) children[2 * qu + qv].p[4 * a + b] = x;
      }
    }
  };
  Lanes B[3][3];
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      B[a][b] = (at(a, b) + at(a + 1, b) + at(a, b + 1) + at(a + 1, b + 1)) / 4.0;
  if (net.extraordinary & corner00) B[0][0] = (at(0, 0) + at(1, 1)) / 2.0;
  if (net.extraordinary & corner30) B[2][0] = (at(3, 0) + at(2, 1)) / 2.0;
  if (net.extraordinary & corner33) B[2][2] = (at(3, 3) + at(2, 2)) / 2.0;
  if (net.extraordinary & corner03) B[0][2] = (at(0, 3) + at(1, 2)) / 2.0;
  Lanes rows[3][5];
  for (int a = 0; a < 3; ++a)
    t_apply(B[a][0], B[a][1], B[a][2], [&](int k, const Lanes& x) { rows[a][k] = x; });
#pragma GCC unroll 5
  for (int j = 0; j < 5; ++j)
    t_apply(rows[0][j], rows[1][j], rows[2][j],
            [&](int i, const Lanes& x) { put(i + 1, j + 1, x); });
  // The sides (each corner is stored twice, the same point).
  halve(at(0, 0), at(1, 0), at(2, 0), at(3, 0), [&](int i, const Lanes& x) { put(i, 0, x); });
  halve(at(0, 3), at(1, 3), at(2, 3), at(3, 3), [&](int i, const Lanes& x) { put(i, 6, x); });
  halve(at(0, 0), at(0, 1), at(0, 2), at(0, 3), [&](int j, const Lanes& x) { put(0, j, x); });
  halve(at(3, 0), at(3, 1), at(3, 2), at(3, 3), [&](int j, const Lanes& x) { put(6, j, x); });
  for (int qu = 0; qu < 2; ++qu)
    for (int qv = 0; qv < 2; ++qv)
      children[2 * qu + qv].extraordinary = net.extraordinary & kChildCorner[qu][qv];
}

}  // namespace

void PatchSampler::BasisColumns::resize(size_t n) {
  t.resize(n);
  for (int a = 0; a < 4; ++a) {
    b[a].resize(n);
    d[a].resize(n);
  }
}

void PatchSampler::BasisColumns::set(size_t k, double value) {
  const detail::CubicBasis basis = detail::cubic_basis(value);
  t[k] = value;
  for (int a = 0; a < 4; ++a) {
    b[a][k] = basis.b[a];
    d[a][k] = basis.d[a];
  }
}

PatchSampler::PatchSampler(const Surface& surface, int resolution)
    : PatchSampler(surface.method(), surface.bezier().nets, resolution) {
  surface_ = &surface;
}

PatchSampler::PatchSampler(Method method, const std::vector<ControlNet>& nets, int resolution)
    : surface_(nullptr), method_(method), nets_(nets), resolution_(resolution) {
  for (Patch& p : patches_) p.splits.reserve(16);
  for (int k = 0; k <= resolution; ++k)
    basis_.push_back(detail::cubic_basis(static_cast<double>(k) / resolution));
  const auto samples = static_cast<size_t>(std::max(resolution + 1, 0));
  table_.resize(samples);
  for (int k = 0; k <= resolution; ++k)
    table_.set(static_cast<size_t>(k), static_cast<double>(k) / resolution);
}

void PatchSampler::evaluate_block(Corner c, int i0, int i1, int j0, int j1, const GridOut& out) {
  const int nu = i1 - i0 + 1, nv = j1 - j0 + 1;
  const ControlNet& net = nets_[c.idx];
  if (method_ == Method::cc) {
    for (int i = i0; i <= i1; ++i)
      for (int j = j0; j <= j1; ++j) {
        const SurfacePoint sp = evaluate_grid(c, i, j);
        const std::ptrdiff_t at = (i - i0) * out.stride + (j - j0);
        out.positions[at] = sp.position;
        out.normals[at] = sp.normal;
        if (out.levels) out.levels[at] = sp.level;
      }
    return;
  }
  if (method_ == Method::asc || net.regular()) {
    polynomial_block(net, i0, j0, nu, nv, out);
    return;
  }
  const Plan& steps = plan(net.extraordinary, i0, i1, j0, j1);
  while (static_cast<int>(children_.size()) < steps.levels)
    children_.push_back(std::make_unique<LaneNet[]>(4));
  origin_ = net.p[0];
  run_plan(steps, net, out);
}

inline void PatchSampler::corner_sample(const LaneNet& net, const PlanOp& op,
                                        const GridOut& out) const {
  // evaluate_polynomial at a patch corner (evaluate_at_patch_corner): the corner point, and
  // derivatives from it and its neighbours along the sides, with the bases' values there
  // (1; -3 and 3), sums from +0 in its order.
  const bool u_end = op.u_end != 0, v_end = op.v_end != 0;
  const int eu = u_end ? 3 : 0, du = u_end ? 2 : 0;
  const int ev = v_end ? 3 : 0, dv = v_end ? 2 : 0;
  const Lanes zero = {0, 0, 0, 0};
  const auto point = [&](int a, int b) -> const Lanes& { return net.p[4 * a + b]; };
  const Lanes row_e = zero + 1.0 * point(eu, ev), row_d = zero + 1.0 * point(du, ev),
              row_d1 = zero + 1.0 * point(du + 1, ev);
  const Lanes row_dv = zero + -3.0 * point(eu, dv) + 3.0 * point(eu, dv + 1);
  const Lanes position = zero + 1.0 * row_e;
  const Lanes sdu = zero + -3.0 * row_d + 3.0 * row_d1;
  const Lanes sdv = zero + 1.0 * row_dv;
  const std::ptrdiff_t at = op.iu * out.stride + op.jv;
  out.positions[at] =
      Vec3(position[0] + origin_[0], position[1] + origin_[1], position[2] + origin_[2]);
  const double cx = sdu[1] * sdv[2] - sdu[2] * sdv[1];
  const double cy = sdu[2] * sdv[0] - sdu[0] * sdv[2];
  const double cz = sdu[0] * sdv[1] - sdu[1] * sdv[0];
  const double n2 = cx * cx + cy * cy + cz * cz;
  const double tiny = lane_threshold(net);
  if (n2 > tiny) {
    const double length = std::sqrt(n2);
    out.normals[at] = Vec3(cx / length, cy / length, cz / length);
  } else {
    out.normals[at] = lane_patch_normal(net, u_end ? 1.0 : 0.0, v_end ? 1.0 : 0.0, sdu, sdv, tiny);
  }
  if (out.levels) out.levels[at] = op.level;
}

STITCH_LANE_CLONES
void PatchSampler::run_plan(const Plan& steps, const ControlNet& net, const GridOut& out) {
  // The net relative to its first point, as Patch::relative.
  LaneNet relative;
  Lanes origin;
  to_lanes(net.p[0], origin);
  for (int k = 0; k < 16; ++k) {
    to_lanes(net.p[k], relative.p[k]);
    relative.p[k] -= origin;
  }
  relative.extraordinary = net.extraordinary;
  for (const PlanOp& op : steps.ops) {
    const LaneNet& at = op.level == 0 ? relative : children_[op.level - 1][op.child];
    switch (op.kind) {
      case PlanOp::split:
        split_lanes(at, children_[op.level].get());
        break;
      case PlanOp::corner:
        corner_sample(at, op, out);
        break;
      case PlanOp::block:
        lane_block(at, op.level, op.iu, op.nu, op.jv, op.nv, steps.bases.data() + op.bases,
                   steps.bases.data() + op.bases + op.nu, steps.params.data() + op.bases,
                   steps.params.data() + op.bases + op.nu, steps.skip.data() + op.skip, out);
        break;
    }
  }
}

const PatchSampler::Plan& PatchSampler::plan(std::uint8_t mask, int i0, int i1, int j0, int j1) {
  std::vector<Plan>& plans = plans_[mask & 15];
  for (const Plan& p : plans)
    if (p.i0 == i0 && p.i1 == i1 && p.j0 == j0 && p.j1 == j1) return p;
  if (plans.size() >= 64) plans.clear();  // a caller of many different blocks
  Plan& p = plans.emplace_back();
  p.i0 = i0;
  p.i1 = i1;
  p.j0 = j0;
  p.j1 = j1;
  const int nu = i1 - i0 + 1, nv = j1 - j0 + 1;
  if (u_.empty()) {
    u_.resize(1);
    v_.resize(1);
  }
  u_[0].assign(table_.t.begin() + i0, table_.t.begin() + i1 + 1);
  v_[0].assign(table_.t.begin() + j0, table_.t.begin() + j1 + 1);
  done_.assign(static_cast<size_t>(nu) * nv, 0);
  done_stride_ = nv;
  plan_descent(p, mask, 0, 0, 0, nu, 0, nv);
  // The bases of the blocks' parameters: the resolution's table entry when the parameter is a
  // grid value of it (the same bits as computing it), else computed (reserved: no reallocation).
  p.computed.reserve(p.params.size());
  p.bases.resize(p.params.size());
  for (size_t k = 0; k < p.params.size(); ++k) {
    const double t = p.params[k];  // in [0, 1], and resolution_ >= 1 (the table is read)
    const double scaled = t * resolution_;
    const auto index = static_cast<size_t>(scaled);
    if (static_cast<double>(index) == scaled && table_.t[index] == t) {
      p.bases[k] = &basis_[index];
    } else {
      p.computed.push_back(detail::cubic_basis(t));
      p.bases[k] = &p.computed.back();
    }
  }
  return p;
}

bool PatchSampler::pending(int iu, int nu, int jv, int nv) const {
  for (int i = iu; i < iu + nu; ++i)
    for (int j = jv; j < jv + nv; ++j)
      if (!done_[static_cast<size_t>(i) * done_stride_ + j]) return true;
  return false;
}

void PatchSampler::plan_descent(Plan& plan, std::uint8_t mask, int level, int child, int iu, int nu,
                                int jv, int nv) {
  // detail::descend for every sample of the sub-block at once: a sample stops at the first net
  // that is regular or has it at a corner (or at kMaxLevel), and goes on into the child of its
  // quadrant with its parameters doubled, exactly as there.
  PlanOp op;
  op.level = static_cast<std::uint8_t>(level);
  op.child = static_cast<std::uint8_t>(child);
  if (mask == 0 || level >= kMaxLevel) {
    op.kind = PlanOp::block;
    op.iu = iu;
    op.nu = nu;
    op.jv = jv;
    op.nv = nv;
    op.bases = static_cast<int>(plan.params.size());
    for (int i = iu; i < iu + nu; ++i) plan.params.push_back(u_[level][i]);
    for (int j = jv; j < jv + nv; ++j) plan.params.push_back(v_[level][j]);
    op.skip = static_cast<int>(plan.skip.size());
    for (int i = iu; i < iu + nu; ++i)
      for (int j = jv; j < jv + nv; ++j)
        plan.skip.push_back(done_[static_cast<size_t>(i) * done_stride_ + j]);
    plan.ops.push_back(op);
    return;
  }
  if (static_cast<int>(u_.size()) <= level + 1) {  // before the references below are taken
    u_.resize(static_cast<size_t>(level) + 2);
    v_.resize(static_cast<size_t>(level) + 2);
  }
  const std::vector<double>& us = u_[level];
  const std::vector<double>& vs = v_[level];
  const auto at_end = [](double t) { return t == 0 || t == 1; };
  bool corner_here = false;
  // Parameters rise along the block: only its first and last ones can be 0 or 1.
  const int corner_i[2] = {iu, iu + nu - 1}, corner_j[2] = {jv, jv + nv - 1};
  for (int ci = 0; ci < (nu > 1 ? 2 : 1); ++ci) {
    const int i = corner_i[ci];
    if (!at_end(us[i])) continue;
    for (int cj = 0; cj < (nv > 1 ? 2 : 1); ++cj) {
      const int j = corner_j[cj];
      char& done = done_[static_cast<size_t>(i) * done_stride_ + j];
      if (!at_end(vs[j]) || done) continue;
      corner_here = true;
      PlanOp corner = op;
      corner.kind = PlanOp::corner;
      corner.iu = i;
      corner.jv = j;
      corner.u_end = us[i] == 1 ? 1 : 0;
      corner.v_end = vs[j] == 1 ? 1 : 0;
      plan.ops.push_back(corner);
      done = 1;
    }
  }
  // Samples at this net's corners are done; a block that had no others (the deepest net at an
  // extraordinary corner) needs no split.
  if (corner_here && !pending(iu, nu, jv, nv)) return;
  std::vector<double>& child_us = u_[level + 1];
  std::vector<double>& child_vs = v_[level + 1];
  child_us.resize(us.size());
  child_vs.resize(vs.size());
  // Parameters rise along the block, so each half is a contiguous run.
  int su = iu, sv = jv;
  for (int i = iu; i < iu + nu; ++i) {
    const int q = us[i] >= 0.5 ? 1 : 0;
    child_us[i] = 2 * us[i] - q;
    su += 1 - q;
  }
  for (int j = jv; j < jv + nv; ++j) {
    const int q = vs[j] >= 0.5 ? 1 : 0;
    child_vs[j] = 2 * vs[j] - q;
    sv += 1 - q;
  }
  op.kind = PlanOp::split;
  plan.ops.push_back(op);
  plan.levels = std::max(plan.levels, level + 1);
  for (int qu = 0; qu < 2; ++qu)
    for (int qv = 0; qv < 2; ++qv) {
      const int ci = qu == 0 ? iu : su, cn = qu == 0 ? su - iu : iu + nu - su;
      const int cj = qv == 0 ? jv : sv, cm = qv == 0 ? sv - jv : jv + nv - sv;
      if (cn == 0 || cm == 0 || !pending(ci, cn, cj, cm)) continue;  // e.g. only the corner
      plan_descent(plan, static_cast<std::uint8_t>(mask & kChildCorner[qu][qv]), level + 1,
                   2 * qu + qv, ci, cn, cj, cm);
    }
}

// Inlined into run_plan, its only caller, whose AVX2 clone it shares (no call per child).
[[gnu::always_inline]] inline void PatchSampler::lane_block(const LaneNet& net, int level, int iu,
                                                            int nu, int jv, int nv,
                                                            const detail::CubicBasis* const* bu,
                                                            const detail::CubicBasis* const* bv,
                                                            const double* tu, const double* tv,
                                                            const char* skip, const GridOut& out) {
  // polynomial_block's sums on whole points: the row sums of each column, then each sample.
  constexpr int kChunk = 16;
  const double tiny = lane_threshold(net);
  const Lanes zero = {0, 0, 0, 0};
  Lanes origin;
  to_lanes(origin_, origin);
  Vec3* const positions = out.positions;
  Vec3* const normals = out.normals;
  int* const levels = out.levels;
  for (int jc = 0; jc < nv; jc += kChunk) {
    const int m = std::min(kChunk, nv - jc);
    Lanes rows[kChunk][4], rows_dv[kChunk][4];  // [k][a]: sums over b, of b(v) and b'(v)
    for (int k = 0; k < m; ++k) {
      const detail::CubicBasis& basis = *bv[jc + k];
      // evaluate_polynomial starts these sums at +0, which only turns a -0 sum into +0; the
      // sums over a below start at +0 too, and a sum from +0 has the same bits whatever the
      // signs of its zero terms, so the samples are the same without that first addition.
      for (int a = 0; a < 4; ++a) {
        Lanes r = basis.b[0] * net.p[4 * a], r_dv = basis.d[0] * net.p[4 * a];
        for (int b = 1; b < 4; ++b) {
          r += basis.b[b] * net.p[4 * a + b];
          r_dv += basis.d[b] * net.p[4 * a + b];
        }
        rows[k][a] = r;
        rows_dv[k][a] = r_dv;
      }
    }
    for (int ii = 0; ii < nu; ++ii) {
      const detail::CubicBasis& basis = *bu[ii];
      const double b[4] = {basis.b[0], basis.b[1], basis.b[2], basis.b[3]};
      const double d[4] = {basis.d[0], basis.d[1], basis.d[2], basis.d[3]};
      const std::ptrdiff_t row_at = (iu + ii) * out.stride + jv + jc;
      const char* done = skip + static_cast<size_t>(ii) * nv + jc;
      for (int k = 0; k < m; ++k) {
        if (done[k]) continue;
        Lanes p = zero, u = zero, v = zero;
        for (int a = 0; a < 4; ++a) {
          p += b[a] * rows[k][a];
          u += d[a] * rows[k][a];
          v += b[a] * rows_dv[k][a];
        }
        // du x dv normalized as Eigen's cross() and normalized() compute it.
        const double cx = u[1] * v[2] - u[2] * v[1];
        const double cy = u[2] * v[0] - u[0] * v[2];
        const double cz = u[0] * v[1] - u[1] * v[0];
        const double n2 = cx * cx + cy * cy + cz * cz;
        Vec3& normal = normals[row_at + k];
        if (n2 > tiny) {
          const double length = std::sqrt(n2);
          normal[0] = cx / length;
          normal[1] = cy / length;
          normal[2] = cz / length;
        } else {  // patch_normal's test; the degenerate points (and NaN) take its whole path
          normal = lane_patch_normal(net, tu[ii], tv[jc + k], u, v, tiny);
        }
        const Lanes position = p + origin;
        Vec3& to = positions[row_at + k];
        to[0] = position[0];
        to[1] = position[1];
        to[2] = position[2];
        if (levels) levels[row_at + k] = level;
      }
    }
  }
}

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
// The kernel's loops run on 4 doubles at a time where the CPU has AVX2 (chosen once at load
// time), on 2 elsewhere. No FMA: a fused multiply-add rounds once where evaluate_polynomial rounds
// twice, and the samples must stay Surface::evaluate's to the bit.
__attribute__((target_clones("avx2", "default")))
#endif
void PatchSampler::polynomial_block(const ControlNet& net, int i0, int j0, int nu, int nv,
                                    const GridOut& out) {
  const BasisColumns &bu = table_, &bv = table_;
  const int bu_at = i0, bv_at = j0;
  // evaluate_polynomial's sums in its order, spread over up to kChunk samples of a grid row: each
  // loop over k below works on local arrays, which the compiler vectorises.
  constexpr int kChunk = 16;
  double points[4][4][3];  // [a][b][xyz]
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      for (int x = 0; x < 3; ++x) points[a][b][x] = net.at(a, b)[x];
  const double tiny = detail::degenerate_threshold(net);
  for (int jc = 0; jc < nv; jc += kChunk) {
    const int m = std::min(kChunk, nv - jc);
    double vb[4][kChunk], vd[4][kChunk];
    for (int b = 0; b < 4; ++b)
      for (int k = 0; k < m; ++k) {
        vb[b][k] = bv.b[b][bv_at + jc + k];
        vd[b][k] = bv.d[b][bv_at + jc + k];
      }
    double rows[4][3][kChunk], rows_dv[4][3][kChunk];  // sums over b, of b(v) and b'(v)
    for (int a = 0; a < 4; ++a)
      for (int x = 0; x < 3; ++x)
        for (int k = 0; k < m; ++k) {
          double r = 0, r_dv = 0;
          for (int b = 0; b < 4; ++b) {
            r += vb[b][k] * points[a][b][x];
            r_dv += vd[b][k] * points[a][b][x];
          }
          rows[a][x][k] = r;
          rows_dv[a][x][k] = r_dv;
        }
    for (int ii = 0; ii < nu; ++ii) {
      const int ub = bu_at + ii;
      const double b[4] = {bu.b[0][ub], bu.b[1][ub], bu.b[2][ub], bu.b[3][ub]};
      const double d[4] = {bu.d[0][ub], bu.d[1][ub], bu.d[2][ub], bu.d[3][ub]};
      double position[3][kChunk], du[3][kChunk], dv[3][kChunk], normal[3][kChunk], length2[kChunk];
      for (int k = 0; k < m; ++k) {
        double uu[3], vv[3];
        for (int x = 0; x < 3; ++x) {
          double p = 0, u = 0, v = 0;
          for (int a = 0; a < 4; ++a) {
            p += b[a] * rows[a][x][k];
            u += d[a] * rows[a][x][k];
            v += b[a] * rows_dv[a][x][k];
          }
          uu[x] = u;
          vv[x] = v;
          position[x][k] = p;
          du[x][k] = u;
          dv[x][k] = v;
        }
        // du x dv normalized as Eigen's cross() and normalized() compute it.
        const double cx = uu[1] * vv[2] - uu[2] * vv[1];
        const double cy = uu[2] * vv[0] - uu[0] * vv[2];
        const double cz = uu[0] * vv[1] - uu[1] * vv[0];
        const double n2 = cx * cx + cy * cy + cz * cz;
        const double length = std::sqrt(n2);
        normal[0][k] = cx / length;
        normal[1][k] = cy / length;
        normal[2][k] = cz / length;
        length2[k] = n2;
      }
      const std::ptrdiff_t row_at = ii * out.stride + jc;
      for (int k = 0; k < m; ++k) {
        // patch_normal's test; the degenerate points (and NaN) take its whole path.
        const double v = bv.t[bv_at + jc + k];
        out.normals[row_at + k] =
            length2[k] > tiny
                ? Vec3(normal[0][k], normal[1][k], normal[2][k])
                : detail::patch_normal(net, bu.t[ub], v, Vec3(du[0][k], du[1][k], du[2][k]),
                                       Vec3(dv[0][k], dv[1][k], dv[2][k]), tiny);
        out.positions[row_at + k] = Vec3(position[0][k], position[1][k], position[2][k]);
        if (out.levels) out.levels[row_at + k] = 0;
      }
    }
  }
}

SurfacePoint PatchSampler::evaluate_grid(Corner c, int i, int j) {
  const double u = static_cast<double>(i) / resolution_, v = static_cast<double>(j) / resolution_;
  const Method method = method_;
  const ControlNet& net = nets_[c.idx];
  if (method == Method::cc || (method == Method::mdc && !net.regular())) return evaluate(c, u, v);
  Patch& p = patch(c);
  if (p.rows.empty()) {
    p.rows.resize(basis_.size());
    p.rows_dv.resize(basis_.size());
    p.row_ready.assign(basis_.size(), 0);
    p.tiny = detail::degenerate_threshold(net);
  }
  // Rows are summed when first asked for: a neighbour sampled along one side needs one or few.
  if (!p.row_ready[j]) {
    for (int a = 0; a < 4; ++a) {
      Vec3 row = Vec3::Zero(), row_dv = Vec3::Zero();
      for (int b = 0; b < 4; ++b) {
        row += basis_[j].b[b] * net.at(a, b);
        row_dv += basis_[j].d[b] * net.at(a, b);
      }
      p.rows[j][a] = row;
      p.rows_dv[j][a] = row_dv;
    }
    p.row_ready[j] = 1;
  }
  const detail::CubicBasis& bu = basis_[i];
  SurfacePoint sp;
  for (int a = 0; a < 4; ++a) {
    sp.position += bu.b[a] * p.rows[j][a];
    sp.du += bu.d[a] * p.rows[j][a];
    sp.dv += bu.b[a] * p.rows_dv[j][a];
  }
  sp.normal = detail::patch_normal(net, u, v, sp.du, sp.dv, p.tiny);
  return sp;
}

SurfacePoint PatchSampler::evaluate(Corner c, double u, double v) {
  if (method_ != Method::mdc) return direct(c, u, v);
  const ControlNet& root = nets_[c.idx];
  if (root.regular()) return direct(c, u, v);
  if ((u == 0 || u == 1) && (v == 0 || v == 1)) {
    // descend stops at once at a corner of the root (the mesh vertices, face centres and edge
    // midpoints a tessellation evaluates on every patch around them): the net relative to its
    // first point, as Patch::relative, is all it reads, so the patch cache is left alone.
    ControlNet relative = root;
    for (Vec3& point : relative.p) point -= root.p[0];
    return detail::descend(
        relative, root.p[0], u, v, 0,
        [](const ControlNet&, std::uint64_t) -> const std::array<ControlNet, 4>& {
          throw std::logic_error("a patch corner needs no split");
        });
  }
  Patch& p = patch(c);
  return detail::descend(
      p.relative, root.p[0], u, v,
      60, [&](const ControlNet& net, std::uint64_t path) -> const auto& {
        return split_at(p, net, path);
      });
}

SurfacePoint PatchSampler::direct(Corner c, double u, double v) const {
  if (surface_) return surface_->evaluate(c, u, v);
  return evaluate_patch(nets_[c.idx], u, v,
                        method_ == Method::asc ? BezierRule::asc : BezierRule::mdc);
}

PatchSampler::Patch& PatchSampler::patch(Corner c) {
  for (Patch& p : patches_)
    if (p.corner == c.idx) return p;
  Patch& p = patches_[next_];
  next_ = (next_ + 1) % static_cast<int>(patches_.size());
  p.corner = c.idx;
  const ControlNet& root = nets_[c.idx];
  p.relative = root;
  for (Vec3& point : p.relative.p) point -= root.p[0];
  p.splits.clear();
  p.rows.clear();
  p.rows_dv.clear();
  p.row_ready.clear();
  return p;
}

const std::array<ControlNet, 4>& PatchSampler::split_at(Patch& patch, const ControlNet& net,
                                                        std::uint64_t path) {
  const bool cached = path != 0 && path < (std::uint64_t{1} << (2 * kCachedLevels));
  if (!cached) {
    latest_deep_ ^= 1;
    deep_[latest_deep_] = split(net, SplitRule::modified);
    return deep_[latest_deep_];
  }
  for (const Split& s : patch.splits)
    if (s.path == path) return s.children;
  // Split before storing: `net` may live in the splits, which push_back can move.
  Split made{path, split(net, SplitRule::modified)};
  patch.splits.push_back(std::move(made));
  return patch.splits.back().children;
}

}  // namespace stitch
