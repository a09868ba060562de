#include "stitch/tess/patches.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <deque>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <tuple>

#include "eval/descent.hpp"
#include "stitch/error.hpp"
#include "stitch/eval/bezier_surface.hpp"
#include "stitch/eval/de_casteljau.hpp"
#include "stitch/topology/operation.hpp"

namespace stitch {

namespace {

/// A cell of the hierarchy under an extraordinary root, its net moved by -origin like
/// evaluate_patch does, so that the splits here are the very splits exact evaluation makes.
struct Cell {
  ControlNet net;
  int root = 0;  ///< index into Surface::corners()
  int level = 0, cell_u = 0, cell_v = 0;
  /// How far the surface's normals turn in the cell one level up (turning(), in degrees).
  double parent_turning = INFINITY;
  /// False for an innermost cell, whose polynomial only approximates the surface.
  bool exact = true;
};

/// Where an innermost cell's deviation is measured, along each side: every eighth, and towards
/// an extraordinary corner at 2^-k too, where the cell's normals turn fastest (the deviation
/// there peaks a few hundredths of the cell from the corner). Measured against a 129 x 129 grid
/// of every innermost cell of examples/ and catmark_smoothtris0, these samples miss the largest
/// normal deviation by 2% at most; a cell is accepted within kSampledShare of the tolerances.
constexpr double kSampledShare = 0.9;
std::vector<double> sample_parameters(bool towards_0, bool towards_1) {
  std::vector<double> at;
  for (int i = 0; i <= 8; ++i) at.push_back(i / 8.0);
  for (int k = 4; k <= 6; ++k) {
    if (towards_0) at.push_back(std::ldexp(1.0, -k));
    if (towards_1) at.push_back(1 - std::ldexp(1.0, -k));
  }
  return at;
}

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
  patch.occurrence = corner_occurrence(mesh, corner);
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
      Cell child{children[2 * qu + qv],
                 cell.root,
                 cell.level + 1,
                 2 * cell.cell_u + qu,
                 2 * cell.cell_v + qv,
                 INFINITY,
                 true};
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

/// The patch corners in PatchCorner order with their (u, v).
constexpr std::array<std::pair<std::uint8_t, std::array<double, 2>>, 4> kPatchCorners{
    {{corner00, {0, 0}}, {corner30, {1, 0}}, {corner33, {1, 1}}, {corner03, {0, 1}}}};

/// One innermost cell against exact evaluation.
struct CellDeviation {
  double position = 0;    ///< largest distance
  double normal_deg = 0;  ///< largest angle between the cell's normal and the surface's
  /// Largest angle between the surface's normals in the cell and at its centre: how far the
  /// normals turn around the extraordinary point the cell holds.
  double turning_deg = 0;
  /// Whether the normals turn as around a point without a tangent plane (the normal tolerance
  /// is not applied).
  bool turning = false;
  bool within = false;  ///< within both tolerances
};

/// What a cell is measured against.
struct CellTolerances {
  double position = 0, normal_deg = 0;  ///< a cell's bounds
  double angle_deg = 0;                 ///< the asked angle tolerance
  /// Measure every sample even once a cell is known to be outside the tolerances (for the
  /// message that names the deviation).
  bool complete = false;
};

/// The innermost cells' polynomials against exact evaluation. Normals are not compared at the
/// root corners in `no_normal` (root index -> PatchCorner bits).
std::vector<CellDeviation> measure(const Surface& surface, const std::vector<Cell>& cells,
                                   const std::vector<std::uint8_t>& no_normal,
                                   const CellTolerances& tolerances) {
  std::vector<CellDeviation> per_cell(cells.size());
  tbb::parallel_for(size_t{0}, cells.size(), [&](size_t k) {
    const Cell& cell = cells[k];
    const Corner corner = surface.corners()[cell.root];
    const Vec3& origin = surface.bezier().nets[corner.idx].p[0];
    const double scale = std::ldexp(1.0, -cell.level);
    // The cell is the net the descent of Surface::evaluate reaches at its level for the points
    // it puts in the cell (ties go to the upper child; 1 stays in the last), and none of them
    // is a corner of a coarser net but the root's, where the descent stops at the root. So
    // continuing the descent from the cell gives Surface::evaluate's bits without the splits
    // above it; the other points (the cell's sides that the descent gives to a neighbour) and
    // the root's corners are evaluated from the root.
    const auto in_cell = [&](double x, int index) {
      return (x == 1 ? (1 << cell.level) - 1 : static_cast<int>(std::ldexp(x, cell.level))) ==
             index;
    };
    // The splits below the cell, made once for all its samples: most of them descend through
    // the same nets towards its extraordinary corners (evaluate_relative's splits, so its bits).
    // A deque keeps the children where descend reads them while more are added.
    std::deque<std::pair<std::uint64_t, std::array<ControlNet, 4>>> splits;
    std::array<std::array<ControlNet, 4>, 2> deep;  // below the paths' 30 levels: not kept
    int latest = 0;
    const auto split_at = [&](const ControlNet& net,
                              std::uint64_t path) -> const std::array<ControlNet, 4>& {
      if (path == 0) {
        latest ^= 1;
        return deep[latest] = split(net, SplitRule::modified);
      }
      for (const auto& [at, children] : splits)
        if (at == path) return children;
      return splits.emplace_back(path, split(net, SplitRule::modified)).second;
    };
    // The surface at the root's (u, v), its derivatives in (u, v).
    const auto exact_at = [&](double u, double v) {
      const bool root_corner = (u == 0 || u == 1) && (v == 0 || v == 1);
      if (root_corner || !in_cell(u, cell.cell_u) || !in_cell(v, cell.cell_v))
        return surface.evaluate(corner, u, v);
      SurfacePoint p = detail::descend(cell.net, origin, std::ldexp(u, cell.level) - cell.cell_u,
                                       std::ldexp(v, cell.level) - cell.cell_v,
                                       kMaxEvaluationLevel - cell.level, split_at);
      p.du /= scale;
      p.dv /= scale;
      return p;
    };
    // The samples, nearest to an extraordinary corner first: a cell outside the tolerances is
    // usually outside there.
    const std::uint8_t ev = cell.net.extraordinary;
    struct Sample {
      double s, t, from_ev;
    };
    std::vector<Sample> samples;
    for (const double s : sample_parameters(ev & (corner00 | corner03), ev & (corner30 | corner33)))
      for (const double t :
           sample_parameters(ev & (corner00 | corner30), ev & (corner03 | corner33))) {
        double from_ev = INFINITY;
        for (const auto& [bit, at] : kPatchCorners)
          if (ev & bit) from_ev = std::min(from_ev, std::hypot(s - at[0], t - at[1]));
        samples.push_back({s, t, from_ev});
      }
    std::sort(samples.begin(), samples.end(),
              [](const Sample& a, const Sample& b) { return a.from_ev < b.from_ev; });

    // How far the normals turn decides whether the normal tolerance applies.
    const Vec3 centre = exact_at((cell.cell_u + 0.5) * scale, (cell.cell_v + 0.5) * scale).normal;
    const auto without_normal = [&](double u, double v) {
      for (const auto& [bit, at] : kPatchCorners)
        if ((no_normal[cell.root] & bit) && u == at[0] && v == at[1]) return true;
      return false;
    };
    // On the cell's quarters: enough to tell a cone from a tangent plane, at a sixth of the
    // cost of every sample (most cells measured are outside the tolerances and need no more).
    CellDeviation d;
    for (int i = 0; i <= 4; ++i)
      for (int j = 0; j <= 4; ++j) {
        const double u = (cell.cell_u + i / 4.0) * scale, v = (cell.cell_v + j / 4.0) * scale;
        if (!without_normal(u, v))
          d.turning_deg = std::max(d.turning_deg, angle_deg(exact_at(u, v).normal, centre));
      }
    // Around a point with a tangent plane the normals turn less far in a cell half as large
    // (half as far where the surface is smooth; at a valence-6 vertex about 0.77 as far in the
    // first levels); where they turn beyond the tolerance and nearly as far as one level up (a
    // fold, a cone), there is no normal to converge to, and the cell is left out of the normal
    // tolerance.
    d.turning = d.turning_deg > tolerances.angle_deg && d.turning_deg > 0.9 * cell.parent_turning;

    d.within = true;
    for (const Sample& sample : samples) {
      const double u = (cell.cell_u + sample.s) * scale, v = (cell.cell_v + sample.t) * scale;
      const SurfacePoint cell_point = evaluate_polynomial(cell.net, sample.s, sample.t);
      // The tolerance bounds the distance from the cell to the surface. The cell's
      // parametrisation is shifted along the surface from the exact one (by about half the
      // cell per level), so the surface's point at the same (u, v) is not the nearest.
      const Vec3 point = cell_point.position + origin;
      const SurfacePoint nearest = nearest_point(exact_at, point, u, v);
      d.position = std::max(d.position, (point - nearest.position).norm());
      if (!without_normal(u, v))
        d.normal_deg = std::max(d.normal_deg, angle_deg(cell_point.normal, nearest.normal));
      d.within =
          d.position <= tolerances.position && (d.turning || d.normal_deg <= tolerances.normal_deg);
      if (!d.within && !tolerances.complete) break;
    }
    per_cell[k] = d;
  });
  return per_cell;
}

/// The mesh element at a corner of the patch of corner c.
PointWithoutNormal element_at(const HalfedgeMesh& mesh, Corner c, std::uint8_t at) {
  using Kind = PointWithoutNormal::Kind;
  switch (at) {
    case corner00:
      return {Kind::vertex, mesh.origin(c).idx};
    case corner33:
      return {Kind::face_centre, mesh.face(c).idx};
    case corner30:
      return {Kind::edge_middle, HalfedgeMesh::edge(c).idx};
    default:
      return {Kind::edge_middle, HalfedgeMesh::edge(mesh.prev(c)).idx};
  }
}

/// The extraordinary corners of the roots where the surface has no tangent plane. Halving keeps
/// a cell's corner and its tangent directions there, so the innermost cell's normal at the point
/// is the root's at every depth: where it differs from the surface's by more than the tolerance,
/// no depth brings it closer, and the point is left out of the normal tolerance.
std::vector<std::uint8_t> corners_without_normal(const HalfedgeMesh& mesh, const Surface& surface,
                                                 double tolerance_deg,
                                                 std::vector<PointWithoutNormal>& points) {
  const auto& corners = surface.corners();
  std::vector<std::uint8_t> bits(corners.size(), 0);
  for (size_t r = 0; r < corners.size(); ++r) {
    const ControlNet& net = surface.bezier().nets[corners[r].idx];
    for (const auto& [bit, at] : kPatchCorners) {
      if (!(net.extraordinary & bit)) continue;
      const double angle = angle_deg(evaluate_polynomial(net, at[0], at[1]).normal,
                                     surface.evaluate(corners[r], at[0], at[1]).normal);
      if (!(angle <= tolerance_deg)) {
        bits[r] |= bit;
        PointWithoutNormal point = element_at(mesh, corners[r], bit);
        point.angle_deg = angle;
        points.push_back(point);
      }
    }
  }
  return bits;
}

/// One entry per point, with the largest angle measured around it.
void merge_points(std::vector<PointWithoutNormal>& points) {
  std::sort(points.begin(), points.end(), [](const auto& a, const auto& b) {
    return std::tie(a.kind, a.index, b.angle_deg) < std::tie(b.kind, b.index, a.angle_deg);
  });
  points.erase(std::unique(points.begin(), points.end(),
                           [](const auto& a, const auto& b) {
                             return a.kind == b.kind && a.index == b.index;
                           }),
               points.end());
}

/// The first root net with a coordinate that is not finite, or -1.
int first_non_finite_root(const Surface& surface) {
  const auto& corners = surface.corners();
  for (size_t r = 0; r < corners.size(); ++r)
    for (const Vec3& p : surface.bezier().nets[corners[r].idx].p)
      if (!p.allFinite()) return static_cast<int>(r);
  return -1;
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

std::string describe(const HalfedgeMesh& mesh, const PointWithoutNormal& point) {
  switch (point.kind) {
    case PointWithoutNormal::Kind::vertex:
      return fmt::format("vertex {}", point.index + 1);
    case PointWithoutNormal::Kind::face_centre:
      return fmt::format("the centre of face {}", point.index + 1);
    case PointWithoutNormal::Kind::edge_middle:
      break;
  }
  return fmt::format("the middle of edge {}", edge_name(mesh, Edge(point.index)));
}

int PatchSet::num_exact() const {
  return static_cast<int>(
      std::count_if(patches.begin(), patches.end(), [](const BezierPatch& p) { return p.exact; }));
}

PatchSet bezier_patches(const HalfedgeMesh& mesh, const Surface& surface,
                        const PatchSetOptions& options,
                        const std::function<void(double)>& progress) {
  if (surface.method() == Method::cc)
    throw UsageError(fmt::format(
        "the Catmull-Clark surface (--method {}) is not a set of Bezier patches; use {} or {}",
        to_string(Method::cc), to_string(Method::mdc), to_string(Method::asc)));
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

  // Each extraordinary point's depth: the smallest at which its innermost cell is within both
  // tolerances. The cells of each root, regular ones exact, the innermost ones not.
  std::vector<Cell> frontier;
  std::vector<std::vector<Cell>> cells_of_root(corners.size());
  if (hierarchical)
    for (int r = 0; r < static_cast<int>(corners.size()); ++r)
      if (!nets[corners[r].idx].regular()) {
        Cell root{nets[corners[r].idx], r, 0, 0, 0};
        const Vec3 origin = root.net.p[0];
        for (Vec3& p : root.net.p) p -= origin;
        frontier.push_back(root);
      }
  if (const int r = first_non_finite_root(surface); r >= 0)
    throw InputError(fmt::format(
        "the control net of corner {} has coordinates that are not finite numbers; check the "
        "input's coordinates and the K-gon controls there",
        corner_name(mesh, corners[r])));
  if (!frontier.empty()) {
    const std::vector<std::uint8_t> no_normal = corners_without_normal(
        mesh, surface, options.angle_tolerance_deg, set.points_without_normal);
    // Both tolerances within the samples' share.
    CellTolerances tolerances{kSampledShare * options.tolerance * set.model_size,
                              kSampledShare * set.cell_angle_tolerance_deg(),
                              options.angle_tolerance_deg};
    // Progress by points settled: each extraordinary corner of a root is one chain of cells.
    size_t chains = 0, settled = 0;
    for (const Cell& root : frontier) chains += std::popcount(unsigned(root.net.extraordinary));
    for (int depth = 0; !frontier.empty(); ++depth) {
      tolerances.complete = depth == options.max_depth;
      const std::vector<CellDeviation> per_cell = measure(surface, frontier, no_normal, tolerances);
      std::vector<Cell> next;
      for (size_t k = 0; k < frontier.size(); ++k) {
        const CellDeviation& d = per_cell[k];
        Cell& cell = frontier[k];
        if (d.within) {
          set.depth = std::max(set.depth, depth);
          set.max_position_deviation = std::max(set.max_position_deviation, d.position);
          if (d.turning) {
            PointWithoutNormal point = element_at(mesh, corners[cell.root], cell.net.extraordinary);
            point.angle_deg = d.turning_deg;
            set.points_without_normal.push_back(point);
          } else {
            set.max_normal_deviation_deg = std::max(set.max_normal_deviation_deg, d.normal_deg);
          }
          cell.exact = false;
          settled += depth == 0 ? std::popcount(unsigned(cell.net.extraordinary)) : 1;
          cells_of_root[cell.root].push_back(cell);
          continue;
        }
        if (depth == options.max_depth) {
          const bool position_ok = d.position <= tolerances.position;
          throw UsageError(fmt::format(
              "the {} is not reached in {} splits near the corner of patch {} (deviation {:.3g} "
              "relative, {:.3g} degrees): ask for a larger {}",
              position_ok ? fmt::format("angle tolerance {} degrees", options.angle_tolerance_deg)
                          : fmt::format("tolerance {} (relative)", options.tolerance),
              depth, corner_name(mesh, corners[cell.root]), d.position / set.model_size,
              d.normal_deg, position_ok ? "--angle-tolerance" : "--tolerance"));
        }
        std::vector<Cell> regular;
        for (Cell& child : split_cell(cell, &regular)) {
          child.parent_turning = d.turning_deg;
          next.push_back(std::move(child));
        }
        for (Cell& c : regular) cells_of_root[c.root].push_back(std::move(c));
      }
      frontier = std::move(next);
      if (progress) progress(double(settled) / double(chains));
    }
    merge_points(set.points_without_normal);
  }

  for (int r = 0; r < static_cast<int>(corners.size()); ++r) {
    const Corner corner = corners[r];
    const ControlNet& root = nets[corner.idx];
    if (!hierarchical || root.regular()) {
      set.patches.push_back(make_patch(mesh, corner, root, Vec3::Zero(), 0, 0, 0, true));
      continue;
    }
    for (const Cell& c : cells_of_root[r])
      set.patches.push_back(
          make_patch(mesh, corner, c.net, root.p[0], c.level, c.cell_u, c.cell_v, c.exact));
  }
  return set;
}

double enclosed_volume(const PatchSet& patches) {
  // p . (du x dv) has degree 8 in each parameter: 5-point Gauss-Legendre is exact for it.
  constexpr std::array<double, 5> x{0.0469100770306680, 0.2307653449471585, 0.5, 0.7692346550528415,
                                    0.9530899229693320};
  constexpr std::array<double, 5> w{0.1184634425280945, 0.2393143352496832, 0.2844444444444444,
                                    0.2393143352496832, 0.1184634425280945};
  return tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, patches.patches.size()), 0.0,
      [&](const tbb::blocked_range<size_t>& range, double sum) {
        for (size_t k = range.begin(); k != range.end(); ++k)
          for (int i = 0; i < 5; ++i)
            for (int j = 0; j < 5; ++j) {
              const SurfacePoint p = evaluate_polynomial(patches.patches[k].net, x[i], x[j]);
              sum += w[i] * w[j] * p.position.dot(p.du.cross(p.dv)) / 3;
            }
        return sum;
      },
      std::plus<>());
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

SurfacePoint nearest_on_surface(const Surface& surface, Corner c, const Vec3& point, double u,
                                double v) {
  return nearest_point([&](double x, double y) { return surface.evaluate(c, x, y); }, point, u, v);
}

}  // namespace stitch
