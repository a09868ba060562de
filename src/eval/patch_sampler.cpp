#include "patch_sampler.hpp"

#include "descent.hpp"
#include "stitch/eval/de_casteljau.hpp"

namespace stitch {

namespace {
// Paths deeper than this (points within 2^-20 of an extraordinary corner) are split afresh: they
// are rare in a tessellation, and keeping them would let the cache grow with the resolution.
constexpr int kCachedLevels = 20;
}  // namespace

PatchSampler::PatchSampler(const Surface& surface, int resolution)
    : PatchSampler(surface.method(), surface.bezier().nets, resolution) {
  surface_ = &surface;
}

PatchSampler::PatchSampler(Method method, const std::vector<ControlNet>& nets, int resolution)
    : surface_(nullptr), method_(method), nets_(nets), resolution_(resolution) {
  for (Patch& p : patches_) p.splits.reserve(16);
  for (int k = 0; k <= resolution; ++k)
    basis_.push_back(detail::cubic_basis(static_cast<double>(k) / resolution));
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
