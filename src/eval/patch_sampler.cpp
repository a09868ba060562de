#include "patch_sampler.hpp"

#include <algorithm>
#include <cmath>

#include "descent.hpp"
#include "stitch/eval/de_casteljau.hpp"

namespace stitch {

namespace {
// Paths deeper than this (points within 2^-20 of an extraordinary corner) are split afresh: they
// are rare in a tessellation, and keeping them would let the cache grow with the resolution.
constexpr int kCachedLevels = 20;
// As deep as Surface::evaluate descends (evaluate_patch's default).
constexpr int kMaxLevel = 60;

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
  leaf_u_.resize(samples);
  leaf_v_.resize(samples);
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
    polynomial_block(net, nullptr, 0, table_, i0, table_, j0, 0, nu, 0, nv, out, false);
    return;
  }
  Patch& p = patch(c);
  if (u_.empty()) {
    u_.resize(1);
    v_.resize(1);
  }
  u_[0].assign(table_.t.begin() + i0, table_.t.begin() + i1 + 1);
  v_[0].assign(table_.t.begin() + j0, table_.t.begin() + j1 + 1);
  done_.assign(static_cast<size_t>(nu) * nv, 0);
  done_stride_ = nv;
  origin_ = net.p[0];
  descend_block(p, p.relative, 1, 0, 0, nu, 0, nv, out);
}

bool PatchSampler::pending(int iu, int nu, int jv, int nv) const {
  for (int i = iu; i < iu + nu; ++i)
    for (int j = jv; j < jv + nv; ++j)
      if (!done_[static_cast<size_t>(i) * done_stride_ + j]) return true;
  return false;
}

void PatchSampler::descend_block(Patch& p, const ControlNet& net, std::uint64_t path, int level,
                                 int iu, int nu, int jv, int nv, const GridOut& out) {
  // detail::descend for every sample of the sub-block at once: a sample stops at the first net
  // that is regular or has it at a corner (or at kMaxLevel), and goes on into the child of its
  // quadrant with its parameters doubled, exactly as there.
  if (static_cast<int>(u_.size()) <= level + 1) {  // before the references below are taken
    u_.resize(static_cast<size_t>(level) + 2);
    v_.resize(static_cast<size_t>(level) + 2);
  }
  const std::vector<double>& us = u_[level];
  const std::vector<double>& vs = v_[level];
  if (net.regular() || level >= kMaxLevel) {
    for (int k = 0; k < nu; ++k) leaf_u_.set(static_cast<size_t>(k), us[iu + k]);
    for (int k = 0; k < nv; ++k) leaf_v_.set(static_cast<size_t>(k), vs[jv + k]);
    polynomial_block(net, &origin_, level, leaf_u_, 0, leaf_v_, 0, iu, nu, jv, nv, out, true);
    return;
  }
  const auto at_end = [](double t) { return t == 0 || t == 1; };
  for (int i = iu; i < iu + nu; ++i) {
    if (!at_end(us[i])) continue;
    for (int j = jv; j < jv + nv; ++j) {
      char& done = done_[static_cast<size_t>(i) * done_stride_ + j];
      if (!at_end(vs[j]) || done) continue;
      SurfacePoint sp = evaluate_polynomial(net, us[i], vs[j]);
      const std::ptrdiff_t at = i * out.stride + j;
      out.positions[at] = sp.position + origin_;
      out.normals[at] = sp.normal;
      if (out.levels) out.levels[at] = level;
      done = 1;
    }
  }
  // Samples at this net's corners are done; a block that had no others (the deepest net at an
  // extraordinary corner) needs no split.
  if (!pending(iu, nu, jv, nv)) return;
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
  // A copy: deeper splits may move the cached ones.
  const std::array<ControlNet, 4> children = split_at(p, net, path);
  for (int qu = 0; qu < 2; ++qu)
    for (int qv = 0; qv < 2; ++qv) {
      const int ci = qu == 0 ? iu : su, cn = qu == 0 ? su - iu : iu + nu - su;
      const int cj = qv == 0 ? jv : sv, cm = qv == 0 ? sv - jv : jv + nv - sv;
      if (!pending(ci, cn, cj, cm)) continue;  // e.g. only the corner evaluated here
      const auto q = static_cast<std::uint64_t>(2 * qu + qv);
      descend_block(p, children[2 * qu + qv], level < 30 ? path * 4 + q : 0, level + 1, ci, cn, cj,
                    cm, out);
    }
}

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
// The kernel's loops run on 4 doubles at a time where the CPU has AVX2 (chosen once at load
// time), on 2 elsewhere. No FMA: a fused multiply-add rounds once where evaluate_polynomial rounds
// twice, and the samples must stay Surface::evaluate's to the bit.
__attribute__((target_clones("avx2", "default")))
#endif
void PatchSampler::polynomial_block(const ControlNet& net, const Vec3* origin, int level,
                                    const BasisColumns& bu, int bu_at, const BasisColumns& bv,
                                    int bv_at, int iu, int nu, int jv, int nv, const GridOut& out,
                                    bool use_done) {
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
      const std::ptrdiff_t row_at = (iu + ii) * out.stride + jv + jc;
      const char* done =
          use_done ? done_.data() + static_cast<size_t>(iu + ii) * done_stride_ + jv + jc : nullptr;
      for (int k = 0; k < m; ++k) {
        if (done && done[k]) continue;
        // patch_normal's test; the degenerate points (and NaN) take its whole path.
        const double v = bv.t[bv_at + jc + k];
        out.normals[row_at + k] =
            length2[k] > tiny
                ? Vec3(normal[0][k], normal[1][k], normal[2][k])
                : detail::patch_normal(net, detail::cubic_basis(bu.t[ub]), detail::cubic_basis(v),
                                       bu.t[ub], v, Vec3(du[0][k], du[1][k], du[2][k]),
                                       Vec3(dv[0][k], dv[1][k], dv[2][k]), tiny);
        Vec3 p(position[0][k], position[1][k], position[2][k]);
        if (origin) p += *origin;
        out.positions[row_at + k] = p;
        if (out.levels) out.levels[row_at + k] = level;
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
  sp.normal = detail::patch_normal(net, bu, basis_[j], u, v, sp.du, sp.dv, p.tiny);
  return sp;
}

SurfacePoint PatchSampler::evaluate(Corner c, double u, double v) {
  if (method_ != Method::mdc) return direct(c, u, v);
  const ControlNet& root = nets_[c.idx];
  if (root.regular()) return direct(c, u, v);
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
