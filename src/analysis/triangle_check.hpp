// The surface check's core, over triangles from any source: a soup held in memory
// (check_surface(TriangleSoup), the local check's scratch soup) or the patches of a surface
// evaluated a region at a time (check_surface(mesh, surface, ...), which never holds the
// tessellation). Space is cut into cubic cells about a triangle across, grouped into tiles;
// each tile's triangles are gathered, checked and let go, tiles in parallel. A pair of triangles
// is checked in the one cell (so the one tile) that holds the lowest corner of the intersection
// of their boxes, an edge shared by triangles in the one that holds the lowest corner of its
// box: every pair once, with no set of the pairs seen and no global table of edges. Internal.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "stitch/analysis/surface_check.hpp"
#include "support/scratch.hpp"

namespace stitch::detail {

/// TileTriangles::flags: edge k (vertex k to vertex k + 1) lies on a crease (kCreaseEdge << k),
/// vertex k is a cone point (kConeVertex << k): a pair meeting there is no fold. kInFocus: the
/// triangle's problems count (check_surface(soup, focus, ...)).
inline constexpr std::uint8_t kCreaseEdge = 1;
inline constexpr std::uint8_t kConeVertex = 8;
inline constexpr std::uint8_t kInFocus = 64;

/// The triangles of one tile, as gathered for it.
struct TileTriangles {
  ScratchVector<Vec3> corners;                 ///< three per triangle
  ScratchVector<std::array<int, 3>> vertices;  ///< the surface's vertex numbers: shared = equal
  ScratchVector<int> ids;                      ///< as the report numbers the triangles
  ScratchVector<std::uint8_t> flags;

  [[nodiscard]] int size() const { return static_cast<int>(ids.size()); }
  void clear() {
    corners.clear();
    vertices.clear();
    ids.clear();
    flags.clear();
  }
  void add(const Vec3& a, const Vec3& b, const Vec3& c, const std::array<int, 3>& v, int id,
           std::uint8_t f) {
    corners.insert(corners.end(), {a, b, c});
    vertices.push_back(v);
    ids.push_back(id);
    flags.push_back(f);
  }
};

/// The cells and tiles of a check over the box [lo, hi].
class CheckGrid {
 public:
  using Cell = std::array<int, 3>;
  /// Cells of about `cell` across (larger where the box would need more than 1024 tiles along
  /// an axis), `tile` cells along each side of a tile.
  CheckGrid(const Vec3& lo, const Vec3& hi, double cell, int tile);

  /// The cell of a point of the box (clamped, for round-off at its far side).
  [[nodiscard]] Cell cell(const Vec3& p) const {
    Cell c;
    for (int a = 0; a < 3; ++a)  // truncation is floor here: the point is not below origin_
      c[a] = std::clamp(static_cast<int>((p[a] - origin_[a]) * inverse_), 0, last_[a]);
    return c;
  }
  [[nodiscard]] int tile_cells() const { return tile_; }
  [[nodiscard]] double cell_size() const { return cell_; }
  [[nodiscard]] double diagonal() const { return diagonal_; }
  /// A tile's key: its coordinates, 10 bits each.
  [[nodiscard]] std::uint32_t tile_key(const Cell& c) const {
    return static_cast<std::uint32_t>((c[0] / tile_) << 20 | (c[1] / tile_) << 10 | c[2] / tile_);
  }
  /// The first cell of the tile `key`.
  [[nodiscard]] Cell tile_origin(std::uint32_t key) const {
    return {static_cast<int>(key >> 20) * tile_, static_cast<int>(key >> 10 & 1023) * tile_,
            static_cast<int>(key & 1023) * tile_};
  }
  /// Tiles the box [lo, hi] meets.
  [[nodiscard]] std::int64_t count_tiles(const Vec3& lo, const Vec3& hi) const;
  template <class Visit>
  void for_each_tile(const Vec3& lo, const Vec3& hi, Visit&& visit) const {
    const Cell a = cell(lo), b = cell(hi);
    for (int x = a[0] / tile_; x <= b[0] / tile_; ++x)
      for (int y = a[1] / tile_; y <= b[1] / tile_; ++y)
        for (int z = a[2] / tile_; z <= b[2] / tile_; ++z)
          visit(static_cast<std::uint32_t>(x << 20 | y << 10 | z));
  }

 private:
  Vec3 origin_;
  double cell_ = 1, inverse_ = 1, diagonal_ = 0;
  int tile_ = 1;
  Cell last_{};  ///< the last cell along each axis
};

/// Items (triangles or patches) sorted into the tiles their boxes meet: tile keys[k] holds the
/// items item(e) for e in [starts[k], starts[k + 1]).
struct TileRuns {
  std::vector<std::uint32_t> keys;
  std::vector<size_t> starts;
  ScratchVector<std::uint64_t> entries;  ///< (tile << 32 | item), sorted
  [[nodiscard]] std::uint32_t item(size_t e) const {
    return static_cast<std::uint32_t>(entries[e] & 0xffffffffu);
  }
};

/// Sorts runs.entries (in parallel) and finds the runs of each tile.
void sort_entries(TileRuns& runs);

/// Makes `grid` coarser (cells twice as large, over [lo, hi]) while the boxes of the `count`
/// items, box_of(i) -> {lo, hi}, would meet many more tiles than there are items (a few large
/// ones among many small), then sorts the items into the tiles.
template <class BoxOf>
TileRuns sort_into_tiles(CheckGrid& grid, const Vec3& lo, const Vec3& hi, size_t count,
                         BoxOf&& box_of) {
  for (;;) {
    std::int64_t entries = 0;
    for (size_t i = 0; i < count; ++i) {
      const auto [blo, bhi] = box_of(i);
      entries += grid.count_tiles(blo, bhi);
    }
    if (entries <= 4 * static_cast<std::int64_t>(count) + 4096) break;
    grid = CheckGrid(lo, hi, 2 * grid.cell_size(), grid.tile_cells());
  }
  TileRuns runs;
  for (size_t i = 0; i < count; ++i) {
    const auto [blo, bhi] = box_of(i);
    grid.for_each_tile(blo, bhi, [&](std::uint32_t key) {
      runs.entries.push_back(static_cast<std::uint64_t>(key) << 32 | static_cast<std::uint32_t>(i));
    });
  }
  sort_entries(runs);
  return runs;
}

/// The checks of a pass: folds and orientation over shared edges (and degenerate triangles),
/// crossings of the other pairs.
enum CheckPass : unsigned { kEdges = 1, kCrossings = 2 };

/// Checks every tile of `keys` (one gather(index, triangles) each, indices into `keys`, in
/// parallel) and merges what they found into one report of `triangles` triangles; with
/// options.crossings_only_when_unfolded, every tile's edges first and its crossings only when
/// no pair folds (then each tile is gathered twice). `focused_only`: only triangles flagged
/// kInFocus count, and pairs with at least one of them. `passes`: the checks made (one alone
/// for a caller that makes the other itself).
SurfaceCheckReport check_tiles(std::span<const std::uint32_t> keys, const CheckGrid& grid,
                               const std::function<void(size_t, TileTriangles&)>& gather,
                               int triangles, const SurfaceCheckOptions& options,
                               bool focused_only = false, unsigned passes = kEdges | kCrossings);

/// check_surface(soup, focus, options) for the soup of these positions and triangles; `focus`
/// empty for the whole surface, else one flag per triangle.
SurfaceCheckReport check_triangles(std::span<const Vec3> positions,
                                   std::span<const std::array<int, 3>> triangles,
                                   std::span<const char> focus, const SurfaceCheckOptions& options);

}  // namespace stitch::detail
