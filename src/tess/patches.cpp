#include "stitch/tess/patches.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "stitch/error.hpp"

namespace stitch {

namespace {

/// A cell of the hierarchy under an extraordinary root, its net moved by -origin like
/// evaluate_patch does, so that the splits here are the very splits exact evaluation makes.
struct Cell {
  ControlNet net;
  int root = 0;  ///< index into Surface::corners()
  int level = 0, cell_u = 0, cell_v = 0;
};

/// Samples per side of an innermost cell when its deviation is measured: the corners, the
/// sides and the interior, dense enough that the maximum between samples is not missed by more
/// than the tolerances' own precision (deviation varies smoothly over one cell).
constexpr int kSamples = 9;

BezierPatch make_patch(const HalfedgeMesh& mesh, Corner corner, const ControlNet& relative,
                       const Vec3& origin, int level, int cell_u, int cell_v, bool exact) {
  BezierPatch patch;
  patch.net = relative;
  for (Vec3& p : patch.net.p) p += origin;
  patch.net.extraordinary = 0;
  patch.net.corner_k = {4, 4, 4, 4};
  patch.corner = corner;
  patch.face = mesh.face(corner).idx;
  patch.vertex = mesh.origin(corner).idx;
  patch.level = level;
  patch.cell_u = cell_u;
  patch.cell_v = cell_v;
  patch.exact = exact;
  return patch;
}

/// The children of an extraordinary cell one level down: regular ones go to `done`, the ones
/// still at an extraordinary point are returned.
std::vector<Cell> split_cell(const Cell& cell, std::vector<Cell>* done) {
  std::vector<Cell> inner;
  const auto children = split(cell.net, SplitRule::modified);
  for (int qu = 0; qu < 2; ++qu)
    for (int qv = 0; qv < 2; ++qv) {
      Cell child{children[2 * qu + qv], cell.root, cell.level + 1, 2 * cell.cell_u + qu,
                 2 * cell.cell_v + qv};
      if (!child.net.regular())
        inner.push_back(child);
      else if (done)
        done->push_back(child);
    }
  return inner;
}

double angle_deg(const Vec3& a, const Vec3& b) {
  // atan2 of |a x b| and a . b stays accurate for the tiny angles measured here.
  return std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / std::numbers::pi;
}

struct Deviation {
  double position = 0, normal_deg = 0;
};

/// The largest deviation of the innermost cells' polynomials from exact evaluation.
Deviation measure(const Surface& surface, const std::vector<Cell>& cells) {
  std::vector<Deviation> per_cell(cells.size());
  tbb::parallel_for(size_t{0}, cells.size(), [&](size_t k) {
    const Cell& cell = cells[k];
    const Corner corner = surface.corners()[cell.root];
    const Vec3& origin = surface.bezier().nets[corner.idx].p[0];
    const double scale = std::ldexp(1.0, -cell.level);
    Deviation d;
    for (int i = 0; i < kSamples; ++i)
      for (int j = 0; j < kSamples; ++j) {
        const double s = double(i) / (kSamples - 1), t = double(j) / (kSamples - 1);
        const SurfacePoint cell_point = evaluate_polynomial(cell.net, s, t);
        const SurfacePoint exact =
            surface.evaluate(corner, (cell.cell_u + s) * scale, (cell.cell_v + t) * scale);
        d.position = std::max(d.position, (cell_point.position + origin - exact.position).norm());
        d.normal_deg = std::max(d.normal_deg, angle_deg(cell_point.normal, exact.normal));
      }
    per_cell[k] = d;
  });
  Deviation worst;
  for (const Deviation& d : per_cell) {
    worst.position = std::max(worst.position, d.position);
    worst.normal_deg = std::max(worst.normal_deg, d.normal_deg);
  }
  return worst;
}

double bounding_box_diagonal(const Surface& surface) {
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (Corner c : surface.corners())
    for (const Vec3& p : surface.bezier().nets[c.idx].p) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  return surface.corners().empty() ? 0.0 : (hi - lo).norm();
}

}  // namespace

int PatchSet::num_exact() const {
  return static_cast<int>(
      std::count_if(patches.begin(), patches.end(), [](const BezierPatch& p) { return p.exact; }));
}

PatchSet bezier_patches(const HalfedgeMesh& mesh, const Surface& surface,
                        const PatchSetOptions& options) {
  if (surface.method() == Method::cc)
    throw UsageError(
        "the Catmull-Clark surface (--method cc) is not a set of Bezier patches; use mdc or asc");
  if (!(options.tolerance > 0) || !std::isfinite(options.tolerance))
    throw UsageError(fmt::format("the tolerance must be a number > 0 (got {})", options.tolerance));
  if (!(options.angle_tolerance_deg > 0) || !std::isfinite(options.angle_tolerance_deg))
    throw UsageError(fmt::format("the angle tolerance must be a number > 0 (got {})",
                                 options.angle_tolerance_deg));
  PatchSet set;
  set.method = surface.method();
  set.tolerance = options.tolerance;
  set.angle_tolerance_deg = options.angle_tolerance_deg;
  set.model_size = bounding_box_diagonal(surface);
  const auto& corners = surface.corners();
  const auto& nets = surface.bezier().nets;
  const bool hierarchical = surface.method() == Method::mdc;

  // The depth: the smallest at which every innermost cell is within both tolerances.
  std::vector<Cell> frontier;
  if (hierarchical)
    for (int r = 0; r < static_cast<int>(corners.size()); ++r)
      if (!nets[corners[r].idx].regular()) {
        Cell root{nets[corners[r].idx], r, 0, 0, 0};
        const Vec3 origin = root.net.p[0];
        for (Vec3& p : root.net.p) p -= origin;
        frontier.push_back(root);
      }
  if (!frontier.empty()) {
    const double position_tolerance = options.tolerance * set.model_size;
    for (int depth = 0;; ++depth) {
      const Deviation d = measure(surface, frontier);
      if (d.position <= position_tolerance && d.normal_deg <= options.angle_tolerance_deg) {
        set.depth = depth;
        set.max_position_deviation = d.position;
        set.max_normal_deviation_deg = d.normal_deg;
        break;
      }
      if (depth == options.max_depth)
        throw UsageError(fmt::format(
            "the tolerance {} (relative) and {} degrees are not reached in {} splits (deviation "
            "{:.3g} relative, {:.3g} degrees): ask for a larger tolerance",
            options.tolerance, options.angle_tolerance_deg, depth, d.position / set.model_size,
            d.normal_deg));
      std::vector<Cell> next;
      for (const Cell& cell : frontier)
        for (Cell& child : split_cell(cell, nullptr)) next.push_back(std::move(child));
      frontier = std::move(next);
    }
  }

  // The patches, root by root: regular cells exact, the innermost ones at `depth` inexact.
  for (int r = 0; r < static_cast<int>(corners.size()); ++r) {
    const Corner corner = corners[r];
    const ControlNet& root = nets[corner.idx];
    if (!hierarchical || root.regular()) {
      set.patches.push_back(make_patch(mesh, corner, root, Vec3::Zero(), 0, 0, 0, true));
      continue;
    }
    const Vec3 origin = root.p[0];
    Cell top{root, r, 0, 0, 0};
    for (Vec3& p : top.net.p) p -= origin;
    std::vector<Cell> open{top};
    while (!open.empty()) {
      const Cell cell = open.back();
      open.pop_back();
      if (cell.level == set.depth) {
        set.patches.push_back(make_patch(mesh, corner, cell.net, origin, cell.level, cell.cell_u,
                                         cell.cell_v, false));
        continue;
      }
      std::vector<Cell> regular;
      for (Cell& inner : split_cell(cell, &regular)) open.push_back(std::move(inner));
      for (const Cell& c : regular)
        set.patches.push_back(
            make_patch(mesh, corner, c.net, origin, c.level, c.cell_u, c.cell_v, true));
    }
  }
  return set;
}

SurfacePoint evaluate_cell(const BezierPatch& patch, double u, double v) {
  SurfacePoint sp = evaluate_polynomial(patch.net, u, v);
  const double scale = std::ldexp(1.0, patch.level);
  sp.du *= scale;
  sp.dv *= scale;
  sp.level = patch.level;
  return sp;
}

std::array<double, 2> cell_to_root(const BezierPatch& patch, double s, double t) {
  const double scale = std::ldexp(1.0, -patch.level);
  return {(patch.cell_u + s) * scale, (patch.cell_v + t) * scale};
}

}  // namespace stitch
