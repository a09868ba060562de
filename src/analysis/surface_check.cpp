#include "stitch/analysis/surface_check.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <utility>
#include <vector>

#include "analysis/triangle_check.hpp"
#include "stitch/mesh/polygon.hpp"
#include "support/scratch.hpp"

namespace stitch {

namespace {

void add_triangle(TriangleSoup& soup, int a, int b, int c, int source) {
  // A quad collapsed to a triangle repeats a vertex; that part is no triangle at all.
  if (a == b || b == c || a == c) return;
  soup.triangles.push_back({a, b, c});
  soup.source.push_back(source);
}

/// Which side of the plane (n, d) the point is on, with |distance| <= eps counted as on it.
double plane_side(const Vec3& n, double d, const Vec3& p, double eps) {
  const double s = n.dot(p) + d;
  return std::abs(s) <= eps ? 0.0 : s;
}

/// The interval where a triangle (projections vv, signed distances dd) crosses the other's plane.
/// Returns false when all three distances are zero (coplanar).
bool interval(const double vv[3], const double dd[3], double& lo, double& hi) {
  auto from = [&](int alone, int x, int y) {
    lo = vv[alone] + (vv[x] - vv[alone]) * dd[alone] / (dd[alone] - dd[x]);
    hi = vv[alone] + (vv[y] - vv[alone]) * dd[alone] / (dd[alone] - dd[y]);
    if (lo > hi) std::swap(lo, hi);
    return true;
  };
  if (dd[0] * dd[1] > 0) return from(2, 0, 1);
  if (dd[0] * dd[2] > 0) return from(1, 0, 2);
  if (dd[1] * dd[2] > 0 || dd[0] != 0) return from(0, 1, 2);
  if (dd[1] != 0) return from(1, 0, 2);
  if (dd[2] != 0) return from(2, 0, 1);
  return false;
}

double orient2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

bool strictly_inside2d(const Eigen::Vector2d& p, const Eigen::Vector2d t[3]) {
  const double s0 = orient2d(t[0], t[1], p), s1 = orient2d(t[1], t[2], p),
               s2 = orient2d(t[2], t[0], p);
  return (s0 > 0 && s1 > 0 && s2 > 0) || (s0 < 0 && s1 < 0 && s2 < 0);
}

bool coplanar_overlap(const Vec3& n, const Vec3 a[3], const Vec3 b[3]) {
  int drop = 0;
  n.cwiseAbs().maxCoeff(&drop);
  const int i0 = drop == 0 ? 1 : 0, i1 = drop == 2 ? 1 : 2;
  Eigen::Vector2d pa[3], pb[3];
  for (int k = 0; k < 3; ++k) {
    pa[k] = {a[k][i0], a[k][i1]};
    pb[k] = {b[k][i0], b[k][i1]};
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const auto &p = pa[i], &q = pa[(i + 1) % 3], &r = pb[j], &s = pb[(j + 1) % 3];
      const double o1 = orient2d(p, q, r), o2 = orient2d(p, q, s), o3 = orient2d(r, s, p),
                   o4 = orient2d(r, s, q);
      if (o1 * o2 < 0 && o3 * o4 < 0) return true;
    }
  for (int k = 0; k < 3; ++k)
    if (strictly_inside2d(pa[k], pb) || strictly_inside2d(pb[k], pa)) return true;
  return false;
}

/// Does the open segment p-q pass through the interior of triangle (a, b, c)? (Moller-Trumbore
/// with strict barycentric bounds.)
bool segment_crosses_interior(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b,
                              const Vec3& c) {
  const Vec3 dir = q - p, e1 = b - a, e2 = c - a;
  const Vec3 pv = dir.cross(e2);
  const double det = e1.dot(pv);
  if (std::abs(det) <= 1e-300) return false;
  const Vec3 tv = p - a;
  const double u = tv.dot(pv) / det;
  const Vec3 qv = tv.cross(e1);
  const double v = dir.dot(qv) / det, t = e2.dot(qv) / det;
  return u > 0 && v > 0 && u + v < 1 && t > 0 && t < 1;
}

}  // namespace

TriangleSoup triangulate(const TessellatedMesh& surface) {
  TriangleSoup soup;
  soup.positions = surface.positions;
  for (int q = 0; q < static_cast<int>(surface.quads.size()); ++q) {
    for (const auto& t : quad_triangles(surface.quads[q], surface.positions))
      add_triangle(soup, t[0], t[1], t[2], q);
  }
  return soup;
}

TriangleSoup triangulate(const AdaptiveMesh& surface) {
  TriangleSoup soup;
  soup.positions = surface.positions;
  soup.triangles = surface.triangles;
  soup.source.resize(surface.triangles.size());
  std::iota(soup.source.begin(), soup.source.end(), 0);
  return soup;
}

TriangleSoup triangulate(const PolygonSoup& polygons) {
  TriangleSoup soup;
  std::map<std::array<double, 3>, int> index;
  std::vector<int> weld(polygons.positions.size());
  for (size_t v = 0; v < polygons.positions.size(); ++v) {
    const Vec3& p = polygons.positions[v];
    const auto [it, fresh] = index.emplace(std::array<double, 3>{p.x(), p.y(), p.z()},
                                           static_cast<int>(soup.positions.size()));
    if (fresh) soup.positions.push_back(p);
    weld[v] = it->second;
  }
  for (int f = 0; f < static_cast<int>(polygons.faces.size()); ++f) {
    const auto& loop = polygons.faces[f];
    if (loop.size() == 4) {  // as the tessellation's quads are split (quad_triangles)
      const std::array<int, 4> q = {weld[loop[0]], weld[loop[1]], weld[loop[2]], weld[loop[3]]};
      for (const auto& t : quad_triangles(q, soup.positions))
        add_triangle(soup, t[0], t[1], t[2], f);
      continue;
    }
    for (size_t i = 1; i + 1 < loop.size(); ++i)
      add_triangle(soup, weld[loop[0]], weld[loop[i]], weld[loop[i + 1]], f);
  }
  return soup;
}

bool triangles_intersect(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0,
                         const Vec3& b1, const Vec3& b2, double eps) {
  const Vec3 a[3] = {a0, a1, a2}, b[3] = {b0, b1, b2};
  const Vec3 na = (a1 - a0).cross(a2 - a0), nb = (b1 - b0).cross(b2 - b0);
  const double da = -na.dot(a0), db = -nb.dot(b0);
  // eps is a distance; the plane functions are scaled by |n|.
  double dist_b[3], dist_a[3];
  for (int k = 0; k < 3; ++k) {
    dist_b[k] = plane_side(na, da, b[k], eps * na.norm());
    dist_a[k] = plane_side(nb, db, a[k], eps * nb.norm());
  }
  if (dist_b[0] * dist_b[1] > 0 && dist_b[0] * dist_b[2] > 0) return false;
  if (dist_a[0] * dist_a[1] > 0 && dist_a[0] * dist_a[2] > 0) return false;
  const Vec3 dir = na.cross(nb);
  int axis = 0;
  dir.cwiseAbs().maxCoeff(&axis);
  const double pa[3] = {a0[axis], a1[axis], a2[axis]}, pb[3] = {b0[axis], b1[axis], b2[axis]};
  double lo_a, hi_a, lo_b, hi_b;
  if (!interval(pa, dist_a, lo_a, hi_a) || !interval(pb, dist_b, lo_b, hi_b))
    return coplanar_overlap(na, a, b);
  // Overlap of positive length: triangles that only touch at a point do not cross.
  return std::min(hi_a, hi_b) > std::max(lo_a, lo_b);
}

/// Both checks: the whole surface (focus empty) and the part of it near an edit (focus[t] for
/// the triangles whose problems count; pairs count when either triangle is in focus).
SurfaceCheckReport detail::check_triangles(std::span<const Vec3> P,
                                           std::span<const std::array<int, 3>> T,
                                           std::span<const char> focus,
                                           const SurfaceCheckOptions& options) {
  SurfaceCheckReport report;
  auto focused = [&](int t) { return focus.empty() || focus[t] != 0; };
  const int nt = static_cast<int>(T.size());
  report.triangles = nt;
  if (nt == 0) return report;

  Vec3 lo = P[T[0][0]], hi = lo;
  for (const auto& t : T)
    for (int v : t) {
      lo = lo.cwiseMin(P[v]);
      hi = hi.cwiseMax(P[v]);
    }
  const double diag = (hi - lo).norm();
  detail::ScratchVector<Vec3> normal(nt);
  detail::ScratchVector<char> degenerate(nt, 0);
  for (int i = 0; i < nt; ++i) {
    normal[i] = (P[T[i][1]] - P[T[i][0]]).cross(P[T[i][2]] - P[T[i][0]]);
    if (normal[i].norm() <= options.degenerate_relative_area * diag * diag) {
      degenerate[i] = 1;
      if (!focused(i)) continue;
      ++report.degenerate;
      if (static_cast<int>(report.degenerate_triangles.size()) < options.max_listed)
        report.degenerate_triangles.push_back(i);
    }
  }

  // Folds and orientation, over edges shared by two triangles. Sorted runs rather than a map of
  // lists: one allocation instead of one per edge, which is most of the time on small soups.
  // Sorted by bucketing on the edge's lower vertex, then sorting each bucket (a vertex is the
  // lower end of a few edges): a comparison sort of all uses was most of unfold_tubes' time.
  struct EdgeUse {
    std::uint64_t edge;
    int triangle;
    bool forward;
    bool operator<(const EdgeUse& o) const {
      return edge != o.edge ? edge < o.edge : triangle < o.triangle;
    }
  };
  auto key = [](int a, int b) {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) |
           static_cast<std::uint32_t>(std::max(a, b));
  };
  detail::ScratchVector<int> bucket_start(P.size() + 1, 0);
  for (const auto& t : T)
    for (int k = 0; k < 3; ++k) ++bucket_start[std::min(t[k], t[(k + 1) % 3]) + 1];
  for (size_t v = 0; v < P.size(); ++v) bucket_start[v + 1] += bucket_start[v];
  detail::ScratchVector<EdgeUse> uses(static_cast<size_t>(nt) * 3);
  {
    detail::ScratchVector<int> next(bucket_start.begin(), bucket_start.end() - 1);
    for (int i = 0; i < nt; ++i)
      for (int k = 0; k < 3; ++k) {
        const int a = T[i][k], b = T[i][(k + 1) % 3];
        uses[next[std::min(a, b)]++] = {key(a, b), i, a < b};
      }
  }
  for (size_t v = 0; v < P.size(); ++v)
    std::sort(uses.begin() + bucket_start[v], uses.begin() + bucket_start[v + 1]);
  const double cos_fold = std::cos(options.fold_angle_deg * std::numbers::pi / 180);
  for (size_t run = 0, end = 0; run < uses.size(); run = end) {
    while (end < uses.size() && uses[end].edge == uses[run].edge) ++end;
    for (size_t x = run; x < end; ++x)
      for (size_t y = x + 1; y < end; ++y) {
        const int i = uses[x].triangle, j = uses[y].triangle;
        const bool dir_i = uses[x].forward, dir_j = uses[y].forward;
        if (!focused(i) && !focused(j)) continue;
        if (dir_i == dir_j) {
          ++report.inconsistent_edges;
          continue;
        }
        if (degenerate[i] || degenerate[j]) continue;
        if (normal[i].dot(normal[j]) < cos_fold * normal[i].norm() * normal[j].norm()) {
          ++report.folds;
          if (static_cast<int>(report.folded_pairs.size()) < options.max_listed)
            report.folded_pairs.push_back({std::min(i, j), std::max(i, j)});
        }
      }
  }

  if (options.crossings_only_when_unfolded && report.folds > 0) return report;

  // Candidate pairs from a uniform grid of about one triangle per cell.
  double mean_size = 0;
  for (int i = 0; i < nt; ++i) {
    Vec3 tlo = P[T[i][0]], thi = tlo;
    for (int v : T[i]) {
      tlo = tlo.cwiseMin(P[v]);
      thi = thi.cwiseMax(P[v]);
    }
    mean_size += (thi - tlo).maxCoeff();
  }
  mean_size /= nt;
  // At most 256 cells across the model, so one large triangle among many small ones cannot make
  // the grid explode.
  const double cell = std::max(mean_size, diag / 256) + 1e-300;
  auto cell_of = [&](double x, double origin) {
    return static_cast<long>(std::floor((x - origin) / cell));
  };
  // Cells are 0..256 along each axis (the cell is at least diag / 256), so 21 bits each make a
  // key that names one cell.
  auto cell_key = [](long x, long y, long z) {
    return (static_cast<std::uint64_t>(x) << 42) | (static_cast<std::uint64_t>(y) << 21) |
           static_cast<std::uint64_t>(z);
  };
  // (cell, triangle) for every cell a triangle's box meets, sorted so each cell's triangles
  // form a run; and each triangle's first cell.
  detail::ScratchVector<std::pair<std::uint64_t, int>> in_cell;
  detail::ScratchVector<std::array<long, 3>> first_cell(static_cast<size_t>(nt));
  for (int i = 0; i < nt; ++i) {
    Vec3 tlo = P[T[i][0]], thi = tlo;
    for (int v : T[i]) {
      tlo = tlo.cwiseMin(P[v]);
      thi = thi.cwiseMax(P[v]);
    }
    first_cell[i] = {cell_of(tlo.x(), lo.x()), cell_of(tlo.y(), lo.y()), cell_of(tlo.z(), lo.z())};
    for (long x = first_cell[i][0]; x <= cell_of(thi.x(), lo.x()); ++x)
      for (long y = first_cell[i][1]; y <= cell_of(thi.y(), lo.y()); ++y)
        for (long z = first_cell[i][2]; z <= cell_of(thi.z(), lo.z()); ++z)
          in_cell.emplace_back(cell_key(x, y, z), i);
  }
  tbb::parallel_sort(in_cell.begin(), in_cell.end());
  // Vertices closer than this to the other's plane count as on it; relative to the model size.
  const double eps = 1e-12 * diag;
  // Each cell's pairs are independent of the other cells': runs of cells are checked in
  // parallel, each chunk counting and listing its own crossings, merged in the cells' order so
  // the pairs listed are those a single pass would list.
  detail::ScratchVector<size_t> run_start;
  for (size_t run = 0; run < in_cell.size();) {
    run_start.push_back(run);
    const std::uint64_t cell_here = in_cell[run].first;
    while (run < in_cell.size() && in_cell[run].first == cell_here) ++run;
  }
  run_start.push_back(in_cell.size());
  struct Crossings {
    int count = 0;
    std::vector<std::array<int, 2>> listed;
  };
  constexpr size_t kRunsPerChunk = 512;
  const size_t runs = run_start.size() - 1;
  detail::ScratchVector<Crossings> chunks((runs + kRunsPerChunk - 1) / kRunsPerChunk);
  tbb::parallel_for(size_t{0}, chunks.size(), [&](size_t chunk) {
    Crossings& found = chunks[chunk];
    const size_t last = std::min(runs, (chunk + 1) * kRunsPerChunk);
    for (size_t r = chunk * kRunsPerChunk; r < last; ++r) {
      const size_t run = run_start[r], end = run_start[r + 1];
      for (size_t x = run; x < end; ++x)
        for (size_t y = x + 1; y < end; ++y) {
          const int i = in_cell[x].second, j = in_cell[y].second;  // i < j: sorted
          if (!focused(i) && !focused(j)) continue;
          // A pair is tested in the first of the cells both meet only (the cells both meet form
          // a box, whose lowest corner is the larger of their first cells): once, without a set
          // of the pairs tested.
          if (cell_key(std::max(first_cell[i][0], first_cell[j][0]),
                       std::max(first_cell[i][1], first_cell[j][1]),
                       std::max(first_cell[i][2], first_cell[j][2])) != in_cell[run].first)
            continue;
          if (degenerate[i] || degenerate[j]) continue;
          int shared = 0, si = -1, sj = -1;
          for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
              if (T[i][a] == T[j][b]) {
                ++shared;
                si = a;
                sj = b;
              }
          bool crossing = false;
          if (shared >= 2) continue;  // edge neighbours: the fold test covers them
          if (shared == 1) {
            const Vec3 &i1 = P[T[i][(si + 1) % 3]], &i2 = P[T[i][(si + 2) % 3]];
            const Vec3 &j1 = P[T[j][(sj + 1) % 3]], &j2 = P[T[j][(sj + 2) % 3]];
            crossing = segment_crosses_interior(i1, i2, P[T[j][0]], P[T[j][1]], P[T[j][2]]) ||
                       segment_crosses_interior(j1, j2, P[T[i][0]], P[T[i][1]], P[T[i][2]]);
          } else {
            crossing = triangles_intersect(P[T[i][0]], P[T[i][1]], P[T[i][2]], P[T[j][0]],
                                           P[T[j][1]], P[T[j][2]], eps);
          }
          if (crossing) {
            ++found.count;
            if (static_cast<int>(found.listed.size()) < options.max_listed)
              found.listed.push_back({i, j});
          }
        }
    }
  });
  for (const Crossings& found : chunks) {
    report.self_intersections += found.count;
    for (const auto& pair : found.listed)
      if (static_cast<int>(report.intersecting_pairs.size()) < options.max_listed)
        report.intersecting_pairs.push_back(pair);
  }
  std::sort(report.intersecting_pairs.begin(), report.intersecting_pairs.end());
  std::sort(report.folded_pairs.begin(), report.folded_pairs.end());
  return report;
}

SurfaceCheckReport check_surface(const TriangleSoup& soup, const SurfaceCheckOptions& options) {
  return detail::check_triangles(soup.positions, soup.triangles, {}, options);
}

SurfaceCheckReport check_surface(const TriangleSoup& soup, const std::vector<char>& focus,
                                 const SurfaceCheckOptions& options) {
  if (focus.size() != soup.triangles.size())
    throw std::invalid_argument(fmt::format("check_surface: {} focus flags for {} triangles",
                                            focus.size(), soup.triangles.size()));
  return detail::check_triangles(soup.positions, soup.triangles, focus, options);
}

std::string SurfaceCheckReport::describe(const TriangleSoup& soup) const {
  auto src = [&](int t) {
    return t < static_cast<int>(soup.source.size()) ? soup.source[t] + 1 : t + 1;
  };
  std::string s = fmt::format(
      "{} triangles: {} self-intersecting pairs, {} folded pairs, {} degenerate, {} "
      "inconsistently oriented edges\n",
      triangles, self_intersections, folds, degenerate, inconsistent_edges);
  for (const auto& p : intersecting_pairs)
    s += fmt::format("  intersecting: triangles {} and {} (of polygons {} and {})\n", p[0] + 1,
                     p[1] + 1, src(p[0]), src(p[1]));
  for (const auto& p : folded_pairs)
    s += fmt::format("  folded: triangles {} and {} (of polygons {} and {})\n", p[0] + 1, p[1] + 1,
                     src(p[0]), src(p[1]));
  for (int t : degenerate_triangles)
    s += fmt::format("  degenerate: triangle {} (of polygon {})\n", t + 1, src(t));
  return s;
}

std::vector<SegmentHit> segment_hits(const TriangleSoup& soup, const Vec3& p, const Vec3& q) {
  std::vector<SegmentHit> hits;
  const Vec3 dir = q - p;
  for (int i = 0; i < static_cast<int>(soup.triangles.size()); ++i) {
    const Vec3& a = soup.positions[soup.triangles[i][0]];
    const Vec3 e1 = soup.positions[soup.triangles[i][1]] - a;
    const Vec3 e2 = soup.positions[soup.triangles[i][2]] - a;
    const Vec3 pv = dir.cross(e2);
    const double det = e1.dot(pv);
    if (std::abs(det) <= 1e-300) continue;
    const Vec3 tv = p - a;
    const double u = tv.dot(pv) / det;
    const Vec3 qv = tv.cross(e1);
    const double v = dir.dot(qv) / det, t = e2.dot(qv) / det;
    // Closed bounds: a segment through a shared edge or vertex hits, it does not slip through.
    if (u >= 0 && v >= 0 && u + v <= 1 && t >= 0 && t <= 1) hits.push_back({i, t});
  }
  std::sort(hits.begin(), hits.end(),
            [](const SegmentHit& a, const SegmentHit& b) { return a.t < b.t; });
  return hits;
}

}  // namespace stitch
