#include "stitch/analysis/surface_check.hpp"

#include <fmt/format.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <tuple>
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
  // Equal positions are one vertex, numbered in order of first appearance: sorted by position
  // (then index), each run's first is the vertex the others become.
  const std::vector<Vec3>& P = polygons.positions;
  std::vector<int> order(P.size()), weld(P.size());
  std::iota(order.begin(), order.end(), 0);
  const auto key = [&](int v) { return std::tuple(P[v].x(), P[v].y(), P[v].z(), v); };
  tbb::parallel_sort(order.begin(), order.end(), [&](int a, int b) { return key(a) < key(b); });
  for (size_t k = 0; k < order.size(); ++k)
    weld[order[k]] = k > 0 && P[order[k]] == P[order[k - 1]] ? weld[order[k - 1]] : order[k];
  for (size_t v = 0; v < P.size(); ++v) {
    if (weld[v] == static_cast<int>(v)) {
      weld[v] = static_cast<int>(soup.positions.size());
      soup.positions.push_back(P[v]);
    } else {
      weld[v] = weld[weld[v]];  // an earlier vertex, already renumbered
    }
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

namespace detail {

namespace {

/// The thresholds of a check, from its options and the model's size.
struct CheckParams {
  double cos_fold = 0;    ///< normals fold below this cosine
  double tiny_area = 0;   ///< twice the area of a degenerate triangle, at most
  double eps = 0;         ///< distance to a plane that counts as on it
  bool focus_all = true;  ///< no focus flags: every triangle counts
};

CheckParams check_params(const CheckGrid& grid, const SurfaceCheckOptions& options) {
  CheckParams p;
  // sin of the complement rather than cos: exactly 0 at 90 degrees, so that faces meeting at a
  // right angle (a box's creases and corners, flat to round-off) are not a fold; std::cos gives
  // 6e-17 there, which made every such pair one.
  p.cos_fold = std::sin((90 - options.fold_angle_deg) * std::numbers::pi / 180);
  const double diag = grid.diagonal();
  p.tiny_area = options.degenerate_relative_area * diag * diag;
  p.eps = 1e-12 * diag;
  return p;
}

/// Items grouped by a 64-bit key without sorting them: an open-addressing table of keys, each
/// with the chain of its items (latest first). A tile's edges and cells are grouped so; sorting
/// them was a fifth of the check.
class KeyChains {
 public:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};  ///< no key is all ones
  /// Room for `items` items, none held.
  void reset(size_t items) {
    size_t size = 16;
    shift_ = 60;
    while (size < 2 * items) {
      size *= 2;
      --shift_;
    }
    mask_ = size - 1;
    keys_.assign(size, kEmpty);
    head_.resize(size);
    next_.resize(items);
  }
  void add(std::uint64_t key, int item) {
    // Fibonacci hashing: the product's top bits depend on all of the key's.
    size_t at = key * 0x9E3779B97F4A7C15u >> shift_;
    while (keys_[at] != kEmpty && keys_[at] != key) at = (at + 1) & mask_;
    next_[static_cast<size_t>(item)] = keys_[at] == key ? head_[at] : -1;
    keys_[at] = key;
    head_[at] = item;
  }
  /// visit(key, first item) for every key; next(item) follows its chain to -1.
  template <class Visit>
  void for_each(Visit&& visit) const {
    for (size_t at = 0; at < keys_.size(); ++at)
      if (keys_[at] != kEmpty) visit(keys_[at], head_[at]);
  }
  [[nodiscard]] int next(int item) const { return next_[static_cast<size_t>(item)]; }

 private:
  size_t mask_ = 0;
  int shift_ = 60;
  ScratchVector<std::uint64_t> keys_;
  ScratchVector<int> head_, next_;
};

/// Working arrays of one thread, kept from tile to tile.
struct TileScratch {
  TileTriangles triangles;
  ScratchVector<Vec3> normal;
  ScratchVector<Vec3> lo, hi;                  ///< each triangle's box
  ScratchVector<CheckGrid::Cell> first, last;  ///< its cells, in the whole grid
  ScratchVector<CheckGrid::Cell> corner_cell;  ///< three per triangle
  ScratchVector<char> degenerate;
  struct EdgeUse {
    int triangle;
    std::uint8_t side;  ///< the edge's index in its triangle
    bool forward;       ///< from the lower vertex number to the higher
  };
  ScratchVector<EdgeUse> edges;
  KeyChains by_edge;
  ScratchVector<int> cell_head;     ///< by cell of the tile: its latest entry, -1: none
  ScratchVector<int> in_cell;       ///< by entry: its triangle
  ScratchVector<int> next_in_cell;  ///< by entry: the cell's entry before, -1: none
  ScratchVector<int> used_cells;    ///< the cells with entries, in order of their first
  ScratchVector<int> large;         ///< triangles over too many of the tile's cells
  struct InRun {
    Vec3 lo, hi;  ///< the triangle's box
    int triangle;
    std::uint8_t axes;  ///< bit a: the triangle's first cell is this cell's along axis a
  };
  ScratchVector<InRun> run;  ///< the triangles of one cell
};

/// A tile's cells along each axis take this many bits in a key of TileScratch::in_cell.
constexpr int kTileBits = 7;
/// Triangles over more of a tile's cells than this are tested against all of its triangles.
constexpr std::int64_t kMostCells = 64;

CheckGrid::Cell min_cell(const CheckGrid::Cell& a, const CheckGrid::Cell& b) {
  return {std::min(a[0], b[0]), std::min(a[1], b[1]), std::min(a[2], b[2])};
}

CheckGrid::Cell max_cell(const CheckGrid::Cell& a, const CheckGrid::Cell& b) {
  return {std::max(a[0], b[0]), std::max(a[1], b[1]), std::max(a[2], b[2])};
}

/// Keeps the `most` smallest entries, sorted.
template <class T>
void keep_smallest(std::vector<T>& list, int most) {
  std::sort(list.begin(), list.end());
  if (static_cast<int>(list.size()) > most) list.resize(static_cast<size_t>(most));
}

/// Adds what `part` found to `into` (whose triangle count stays).
void merge(SurfaceCheckReport& into, const SurfaceCheckReport& part, int most) {
  into.self_intersections += part.self_intersections;
  into.folds += part.folds;
  into.degenerate += part.degenerate;
  into.inconsistent_edges += part.inconsistent_edges;
  const auto append = [most](auto& list, const auto& more) {
    list.insert(list.end(), more.begin(), more.end());
    keep_smallest(list, most);
  };
  append(into.intersecting_pairs, part.intersecting_pairs);
  append(into.folded_pairs, part.folded_pairs);
  append(into.degenerate_triangles, part.degenerate_triangles);
}

/// Two triangles on one edge: running along it the same way is an inconsistent edge; otherwise,
/// when `fold` is asked (neither is degenerate, the edge is no crease and touches no cone
/// point), normals further apart than the fold angle are a fold. `pair`: their numbers.
void check_edge_pair(bool same_direction, bool fold, const Vec3& ni, const Vec3& nj,
                     double cos_fold, const std::array<int, 2>& pair, SurfaceCheckReport& out) {
  if (same_direction) {
    ++out.inconsistent_edges;
    return;
  }
  if (fold && ni.dot(nj) < cos_fold * ni.norm() * nj.norm()) {
    ++out.folds;
    out.folded_pairs.push_back(pair);
  }
}

void check_tile(const CheckGrid& grid, std::uint32_t key, unsigned passes, const CheckParams& p,
                const SurfaceCheckOptions& options, TileScratch& s, SurfaceCheckReport& out) {
  const TileTriangles& t = s.triangles;
  const int n = t.size();
  const CheckGrid::Cell origin = grid.tile_origin(key);
  const int side = grid.tile_cells();
  const auto inside = [&](const CheckGrid::Cell& c) {
    for (int a = 0; a < 3; ++a)
      if (c[a] < origin[a] || c[a] >= origin[a] + side) return false;
    return true;
  };
  const auto focused = [&](int i) { return p.focus_all || (t.flags[i] & kInFocus) != 0; };
  const auto corner = [&](int i, int k) -> const Vec3& { return t.corners[3 * i + k]; };
  s.normal.resize(static_cast<size_t>(n));
  s.lo.resize(static_cast<size_t>(n));
  s.hi.resize(static_cast<size_t>(n));
  s.corner_cell.resize(3 * static_cast<size_t>(n));
  s.first.resize(static_cast<size_t>(n));
  s.last.resize(static_cast<size_t>(n));
  s.degenerate.assign(static_cast<size_t>(n), 0);
  for (int i = 0; i < n; ++i) {
    const Vec3 &a = corner(i, 0), &b = corner(i, 1), &c = corner(i, 2);
    s.normal[i] = (b - a).cross(c - a);
    s.lo[i] = a.cwiseMin(b).cwiseMin(c);
    s.hi[i] = a.cwiseMax(b).cwiseMax(c);
    // The cell of a box's corner is the least or largest of its points' cells (cell() is
    // monotone), so three look-ups serve the triangle's box and its edges' boxes.
    for (int k = 0; k < 3; ++k) s.corner_cell[3 * i + k] = grid.cell(corner(i, k));
    s.first[i] = min_cell(min_cell(s.corner_cell[3 * i], s.corner_cell[3 * i + 1]),
                          s.corner_cell[3 * i + 2]);
    s.last[i] = max_cell(max_cell(s.corner_cell[3 * i], s.corner_cell[3 * i + 1]),
                         s.corner_cell[3 * i + 2]);
    if (s.normal[i].norm() > p.tiny_area) continue;
    s.degenerate[i] = 1;
    // Counted by the tile of its first cell, which every tile it meets agrees on.
    if ((passes & kEdges) && focused(i) && inside(s.first[i])) {
      ++out.degenerate;
      out.degenerate_triangles.push_back(t.ids[i]);
    }
  }
  const auto pair = [&](int i, int j) {
    return std::array<int, 2>{std::min(t.ids[i], t.ids[j]), std::max(t.ids[i], t.ids[j])};
  };

  if (passes & kEdges) {
    // Folds and orientation over the edges whose box's lowest corner is in this tile: every
    // triangle on such an edge meets that cell, so it is here.
    s.edges.clear();
    s.by_edge.reset(3 * static_cast<size_t>(n));
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) {
        const int a = t.vertices[i][k], b = t.vertices[i][(k + 1) % 3];
        if (a == b ||
            !inside(min_cell(s.corner_cell[3 * i + k], s.corner_cell[3 * i + (k + 1) % 3])))
          continue;
        const std::uint64_t edge = static_cast<std::uint64_t>(std::min(a, b)) << 32 |
                                   static_cast<std::uint32_t>(std::max(a, b));
        s.by_edge.add(edge, static_cast<int>(s.edges.size()));
        s.edges.push_back({i, static_cast<std::uint8_t>(k), a < b});
      }
    // Whether a triangle meets the crease or cone point at its side k: no fold there.
    const auto sharp = [&](int i, int k) {
      const std::uint8_t f = t.flags[i];
      return (f & (kCreaseEdge << k)) != 0 || (f & (kConeVertex << k)) != 0 ||
             (f & (kConeVertex << ((k + 1) % 3))) != 0;
    };
    s.by_edge.for_each([&](std::uint64_t, int first) {
      for (int x = first; x >= 0; x = s.by_edge.next(x))
        for (int y = s.by_edge.next(x); y >= 0; y = s.by_edge.next(y)) {
          const TileScratch::EdgeUse &u = s.edges[x], &v = s.edges[y];
          const int i = u.triangle, j = v.triangle;
          if (!focused(i) && !focused(j)) continue;
          check_edge_pair(
              u.forward == v.forward,
              !s.degenerate[i] && !s.degenerate[j] && !sharp(i, u.side) && !sharp(j, v.side),
              s.normal[i], s.normal[j], p.cos_fold, pair(i, j), out);
        }
    });
  }

  if (passes & kCrossings) {
    // Pairs of triangles that share at most a vertex, near each other: in the cell that holds
    // the lowest corner of the intersection of their boxes, the larger of their first cells.
    // Boxes apart by more than eps: most pairs that share a cell, for a fraction of the test.
    const auto apart = [&](const Vec3& lo_i, const Vec3& hi_i, const Vec3& lo_j, const Vec3& hi_j) {
      return ((lo_i.array() - p.eps) > hi_j.array()).any() ||
             ((lo_j.array() - p.eps) > hi_i.array()).any();
    };
    const auto test = [&](int i, int j) {
      if (!focused(i) && !focused(j)) return;
      if (s.degenerate[i] || s.degenerate[j]) return;
      int shared = 0, si = -1, sj = -1;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
          if (t.vertices[i][a] == t.vertices[j][b]) {
            ++shared;
            si = a;
            sj = b;
          }
      if (shared >= 2) return;  // edge neighbours: the fold test covers them
      bool crossing = false;
      if (shared == 1) {
        // The edge across from the shared vertex crosses the other triangle only through its
        // plane: both ends clearly on one side of it (most pairs) rule that out at once.
        const auto apart = [&](int from, int to, int at) {
          const Vec3& n = s.normal[to];
          const Vec3& o = corner(to, 0);
          const double d1 = n.dot(corner(from, (at + 1) % 3) - o),
                       d2 = n.dot(corner(from, (at + 2) % 3) - o);
          const double tolerance = 1e-9 * (std::abs(d1) + std::abs(d2));
          return (d1 > tolerance && d2 > tolerance) || (d1 < -tolerance && d2 < -tolerance);
        };
        if (apart(i, j, si) && apart(j, i, sj)) return;
        crossing = segment_crosses_interior(corner(i, (si + 1) % 3), corner(i, (si + 2) % 3),
                                            corner(j, 0), corner(j, 1), corner(j, 2)) ||
                   segment_crosses_interior(corner(j, (sj + 1) % 3), corner(j, (sj + 2) % 3),
                                            corner(i, 0), corner(i, 1), corner(i, 2));
      } else {
        crossing = triangles_intersect(corner(i, 0), corner(i, 1), corner(i, 2), corner(j, 0),
                                       corner(j, 1), corner(j, 2), p.eps);
      }
      if (!crossing) return;
      ++out.self_intersections;
      out.intersecting_pairs.push_back(pair(i, j));
    };
    const auto lowest = [&](int i, int j) {
      return CheckGrid::Cell{std::max(s.first[i][0], s.first[j][0]),
                             std::max(s.first[i][1], s.first[j][1]),
                             std::max(s.first[i][2], s.first[j][2])};
    };
    // Each cell's triangles as a chain from the cell's head in a flat array over the tile's
    // cells, which the thread keeps and resets where it was used.
    const size_t tile_cells = static_cast<size_t>(side) * side * side;
    if (s.cell_head.size() < tile_cells) s.cell_head.assign(tile_cells, -1);
    s.in_cell.clear();
    s.next_in_cell.clear();
    s.used_cells.clear();
    s.large.clear();
    for (int i = 0; i < n; ++i) {
      CheckGrid::Cell lo, hi;
      std::int64_t cells = 1;
      for (int a = 0; a < 3; ++a) {
        lo[a] = std::max(s.first[i][a], origin[a]) - origin[a];
        hi[a] = std::min(s.last[i][a], origin[a] + side - 1) - origin[a];
        cells *= std::max(0, hi[a] - lo[a] + 1);
      }
      if (cells > kMostCells) {
        s.large.push_back(i);
        continue;
      }
      for (int x = lo[0]; x <= hi[0]; ++x)
        for (int y = lo[1]; y <= hi[1]; ++y)
          for (int z = lo[2]; z <= hi[2]; ++z) {
            const int c = (x * side + y) * side + z;
            if (s.cell_head[c] < 0) s.used_cells.push_back(c);
            s.next_in_cell.push_back(s.cell_head[c]);
            s.cell_head[c] = static_cast<int>(s.in_cell.size());
            s.in_cell.push_back(i);
          }
    }
    for (const int c : s.used_cells) {
      const CheckGrid::Cell here{origin[0] + c / (side * side), origin[1] + c / side % side,
                                 origin[2] + c % side};
      // The larger of two first cells is this one when, along each axis, either first cell is
      // here: one bit per axis and triangle, so that the pairs that are some other cell's cost
      // an OR each; and the boxes, so that most of the others cost a comparison in cache.
      s.run.clear();
      for (int e = s.cell_head[c]; e >= 0; e = s.next_in_cell[static_cast<size_t>(e)]) {
        const int i = s.in_cell[static_cast<size_t>(e)];
        const CheckGrid::Cell& f = s.first[i];
        s.run.push_back({s.lo[i], s.hi[i], i,
                         static_cast<std::uint8_t>((f[0] == here[0]) | (f[1] == here[1]) << 1 |
                                                   (f[2] == here[2]) << 2)});
      }
      s.cell_head[c] = -1;
      for (size_t x = 0; x < s.run.size(); ++x)
        for (size_t y = x + 1; y < s.run.size(); ++y) {
          const TileScratch::InRun &u = s.run[x], &v = s.run[y];
          if ((u.axes | v.axes) != 7 || apart(u.lo, u.hi, v.lo, v.hi)) continue;
          test(std::min(u.triangle, v.triangle), std::max(u.triangle, v.triangle));
        }
    }
    // Large triangles against every other one whose box meets theirs (each pair of two large
    // ones once).
    for (const int i : s.large)
      for (int j = 0; j < n; ++j) {
        if (j == i) continue;
        const bool other_large = std::binary_search(s.large.begin(), s.large.end(), j);
        if (other_large && j < i) continue;
        bool meet = true;
        for (int a = 0; a < 3 && meet; ++a)
          meet = std::max(s.first[i][a], s.first[j][a]) <= std::min(s.last[i][a], s.last[j][a]);
        if (meet && inside(lowest(i, j)) && !apart(s.lo[i], s.hi[i], s.lo[j], s.hi[j])) test(i, j);
      }
  }
  keep_smallest(out.intersecting_pairs, options.max_listed);
  keep_smallest(out.folded_pairs, options.max_listed);
  keep_smallest(out.degenerate_triangles, options.max_listed);
}

}  // namespace

CheckGrid::CheckGrid(const Vec3& lo, const Vec3& hi, double cell, int tile)
    : origin_(lo), diagonal_((hi - lo).norm()), tile_(std::clamp(tile, 1, 1 << kTileBits)) {
  // At most 1024 tiles along an axis (10 bits of a tile's key).
  const double extent = (hi - lo).maxCoeff();
  cell_ = std::max({cell, extent / (1024.0 * tile_ - 1), 1e-300});
  inverse_ = 1 / cell_;
  for (int a = 0; a < 3; ++a)
    last_[a] = static_cast<int>(std::min(1024.0 * tile_ - 1, std::floor((hi[a] - lo[a]) / cell_)));
}

std::int64_t CheckGrid::count_tiles(const Vec3& lo, const Vec3& hi) const {
  const Cell a = cell(lo), b = cell(hi);
  std::int64_t count = 1;
  for (int k = 0; k < 3; ++k) count *= b[k] / tile_ - a[k] / tile_ + 1;
  return count;
}

void sort_entries(TileRuns& runs) {
  tbb::parallel_sort(runs.entries.begin(), runs.entries.end());
  for (size_t e = 0; e < runs.entries.size(); ++e)
    if (e == 0 || runs.entries[e] >> 32 != runs.entries[e - 1] >> 32) {
      runs.keys.push_back(static_cast<std::uint32_t>(runs.entries[e] >> 32));
      runs.starts.push_back(e);
    }
  runs.starts.push_back(runs.entries.size());
}

SurfaceCheckReport check_tiles(std::span<const std::uint32_t> keys, const CheckGrid& grid,
                               const std::function<void(size_t, TileTriangles&)>& gather,
                               int triangles, const SurfaceCheckOptions& options, bool focused_only,
                               unsigned passes) {
  SurfaceCheckReport report;
  report.triangles = triangles;
  CheckParams params = check_params(grid, options);
  params.focus_all = !focused_only;
  std::vector<SurfaceCheckReport> found(keys.size());
  tbb::enumerable_thread_specific<TileScratch> scratch;
  const bool two_runs = passes == (kEdges | kCrossings) && options.crossings_only_when_unfolded;
  // Tiles checked (each run's), told by whichever thread finds no other telling, none waiting;
  // read under the lock, so the fractions told never go back.
  const double tiles = static_cast<double>(keys.size()) * (two_runs ? 2 : 1);
  std::atomic<size_t> checked{0};
  std::mutex telling;
  const auto run = [&](unsigned passes) {
    tbb::parallel_for(size_t{0}, keys.size(), [&](size_t k) {
      TileScratch& s = scratch.local();
      s.triangles.clear();
      gather(k, s.triangles);
      check_tile(grid, keys[k], passes, params, options, s, found[k]);
      ++checked;
      if (!options.progress) return;
      if (const std::unique_lock lock(telling, std::try_to_lock); lock.owns_lock())
        options.progress(static_cast<double>(checked.load()) / tiles);
    });
  };
  if (two_runs) {
    run(kEdges);
    int folds = 0;
    for (const SurfaceCheckReport& r : found) folds += r.folds;
    if (folds == 0) run(kCrossings);
  } else {
    run(passes);
  }
  if (options.progress) options.progress(1.0);
  for (const SurfaceCheckReport& r : found) merge(report, r, options.max_listed);
  return report;
}

namespace {

/// Soups of up to this many triangles have their edges checked over the whole soup at once:
/// faster than tile by tile for the small soups the local check and unfold_tubes' search check
/// again and again (the soup's vertex numbers are dense, so its edges are bucketed by their
/// lower vertex without a hash), for 50 bytes per triangle.
constexpr int kWholeSoupEdges = 1 << 21;

/// Degenerate triangles, folds and orientation over the edges of the whole soup (what check_tile
/// does a tile at a time).
SurfaceCheckReport soup_edges(std::span<const Vec3> P, std::span<const std::array<int, 3>> T,
                              std::span<const char> focus, const CheckParams& params,
                              const SurfaceCheckOptions& options) {
  SurfaceCheckReport out;
  const auto focused = [&](int t) { return focus.empty() || focus[t] != 0; };
  const auto nt = static_cast<int>(T.size());
  ScratchVector<Vec3> normal(static_cast<size_t>(nt));
  ScratchVector<char> degenerate(static_cast<size_t>(nt), 0);
  for (int i = 0; i < nt; ++i) {
    normal[i] = (P[T[i][1]] - P[T[i][0]]).cross(P[T[i][2]] - P[T[i][0]]);
    if (normal[i].norm() > params.tiny_area) continue;
    degenerate[i] = 1;
    if (!focused(i)) continue;
    ++out.degenerate;
    out.degenerate_triangles.push_back(i);
  }
  // Sorted runs rather than a map of lists: bucketed on the edge's lower vertex, then each
  // bucket sorted (a vertex is the lower end of a few edges).
  struct EdgeUse {
    std::uint64_t edge;
    int triangle;
    bool forward;
    bool operator<(const EdgeUse& o) const {
      return edge != o.edge ? edge < o.edge : triangle < o.triangle;
    }
  };
  const auto key = [](int a, int b) {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) |
           static_cast<std::uint32_t>(std::max(a, b));
  };
  ScratchVector<int> bucket_start(P.size() + 1, 0);
  for (const auto& t : T)
    for (int k = 0; k < 3; ++k) ++bucket_start[std::min(t[k], t[(k + 1) % 3]) + 1];
  for (size_t v = 0; v < P.size(); ++v) bucket_start[v + 1] += bucket_start[v];
  ScratchVector<EdgeUse> uses(static_cast<size_t>(nt) * 3);
  {
    ScratchVector<int> next(bucket_start.begin(), bucket_start.end() - 1);
    for (int i = 0; i < nt; ++i)
      for (int k = 0; k < 3; ++k) {
        const int a = T[i][k], b = T[i][(k + 1) % 3];
        uses[next[std::min(a, b)]++] = {key(a, b), i, a < b};
      }
  }
  for (size_t v = 0; v < P.size(); ++v)
    std::sort(uses.begin() + bucket_start[v], uses.begin() + bucket_start[v + 1]);
  for (size_t run = 0, end = 0; run < uses.size(); run = end) {
    while (end < uses.size() && uses[end].edge == uses[run].edge) ++end;
    for (size_t x = run; x < end; ++x)
      for (size_t y = x + 1; y < end; ++y) {
        const int i = uses[x].triangle, j = uses[y].triangle;
        if (!focused(i) && !focused(j)) continue;
        check_edge_pair(uses[x].forward == uses[y].forward, !degenerate[i] && !degenerate[j],
                        normal[i], normal[j], params.cos_fold, {std::min(i, j), std::max(i, j)},
                        out);
      }
  }
  keep_smallest(out.folded_pairs, options.max_listed);
  keep_smallest(out.degenerate_triangles, options.max_listed);
  return out;
}

}  // namespace

SurfaceCheckReport check_triangles(std::span<const Vec3> P, std::span<const std::array<int, 3>> T,
                                   std::span<const char> focus,
                                   const SurfaceCheckOptions& options) {
  const auto nt = static_cast<int>(T.size());
  if (nt == 0) return {};
  const auto box = [&](const std::array<int, 3>& t) {
    return std::pair{P[t[0]].cwiseMin(P[t[1]]).cwiseMin(P[t[2]]),
                     P[t[0]].cwiseMax(P[t[1]]).cwiseMax(P[t[2]])};
  };
  Vec3 lo = P[T[0][0]], hi = lo;
  double mean_size = 0;
  for (const auto& t : T) {
    const auto [tlo, thi] = box(t);
    lo = lo.cwiseMin(tlo);
    hi = hi.cwiseMax(thi);
    mean_size += (thi - tlo).maxCoeff();
  }
  mean_size /= nt;
  constexpr int kTileCells = 32;
  CheckGrid grid(lo, hi, mean_size, kTileCells);
  unsigned passes = kEdges | kCrossings;
  SurfaceCheckReport report;
  if (nt <= kWholeSoupEdges) {
    report = soup_edges(P, T, focus, check_params(grid, options), options);
    report.triangles = nt;
    if (options.crossings_only_when_unfolded && report.folds > 0) return report;
    passes = kCrossings;
  }
  // Cells about a triangle across, coarser while the triangles' boxes would meet many more tiles
  // than there are triangles (a few large triangles among many small ones).
  const TileRuns runs =
      sort_into_tiles(grid, lo, hi, T.size(), [&](size_t i) { return box(T[i]); });
  const SurfaceCheckReport tiles = check_tiles(
      runs.keys, grid,
      [&](size_t k, TileTriangles& out) {
        for (size_t e = runs.starts[k]; e < runs.starts[k + 1]; ++e) {
          const auto i = static_cast<int>(runs.item(e));
          const auto& t = T[i];
          out.add(P[t[0]], P[t[1]], P[t[2]], t, i,
                  !focus.empty() && focus[i] != 0 ? kInFocus : std::uint8_t{0});
        }
      },
      nt, options, !focus.empty(), passes);
  if (passes == (kEdges | kCrossings)) return tiles;
  merge(report, tiles, options.max_listed);
  return report;
}

}  // namespace detail

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

namespace {

/// SurfaceCheckReport::describe with `source`, the 1-based polygon of a triangle.
template <class Source>
std::string describe_report(const SurfaceCheckReport& r, Source&& src) {
  std::string s = fmt::format(
      "{} triangles: {} self-intersecting pairs, {} folded pairs, {} degenerate, {} "
      "inconsistently oriented edges\n",
      r.triangles, r.self_intersections, r.folds, r.degenerate, r.inconsistent_edges);
  for (const auto& p : r.intersecting_pairs)
    s += fmt::format("  intersecting: triangles {} and {} (of polygons {} and {})\n", p[0] + 1,
                     p[1] + 1, src(p[0]), src(p[1]));
  for (const auto& p : r.folded_pairs)
    s += fmt::format("  folded: triangles {} and {} (of polygons {} and {})\n", p[0] + 1, p[1] + 1,
                     src(p[0]), src(p[1]));
  for (int t : r.degenerate_triangles)
    s += fmt::format("  degenerate: triangle {} (of polygon {})\n", t + 1, src(t));
  return s;
}

}  // namespace

std::string SurfaceCheckReport::describe(const TriangleSoup& soup) const {
  return describe_report(*this, [&](int t) {
    return t < static_cast<int>(soup.source.size()) ? soup.source[t] + 1 : t + 1;
  });
}

std::string SurfaceCheckReport::describe_quads() const {
  return describe_report(*this, [](int t) { return t / 2 + 1; });
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
