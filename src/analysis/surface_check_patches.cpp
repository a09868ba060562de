// check_surface on a Surface's welded tessellation without holding it: the patches' boxes first
// (one evaluation of every grid), then tile by tile the patches whose boxes meet the tile are
// evaluated again and split into the tessellation's triangles, with the creases and cone points
// the surface knows marked on them (triangle_check.hpp). Memory: the mesh, its surface, two
// boxes and a few tile entries per patch, and each thread's tile.
#include <fmt/format.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include "analysis/triangle_check.hpp"
#include "eval/patch_sampler.hpp"
#include "stitch/analysis/surface_check.hpp"
#include "stitch/mesh/limits.hpp"
#include "stitch/mesh/polygon.hpp"
#include "tess/layout.hpp"

namespace stitch {

namespace {

/// By vertex index, whether the surface has a cone point there (no tangent plane, so that the
/// triangles around it may meet at any angle): a sector its K-gons could not flatten
/// (KgonSet::cone), three or more sharp edges, or a corner tag.
std::vector<std::uint8_t> cone_points(const HalfedgeMesh& mesh, const KgonSet& kgons) {
  std::vector<std::uint8_t> cone(static_cast<size_t>(mesh.vertex_capacity()), 0);
  for (Vertex v : mesh.vertices()) {
    int sharp = 0;
    bool flagged = mesh.sharpness(v) > 0;
    for (Halfedge h : mesh.vertex_fan(v)) {
      sharp += kgons.sharp(HalfedgeMesh::edge(h)) ? 1 : 0;
      flagged = flagged || (!kgons.cone.empty() && kgons.cone[h.idx] != 0);
    }
    cone[v.idx] = flagged || sharp >= 3 ? 1 : 0;
  }
  return cone;
}

/// One thread's sampler and a patch's grid.
struct PatchSamples {
  PatchSampler sampler;
  std::vector<Vec3> positions, scratch;
  std::vector<std::int64_t> vertices;
  std::vector<detail::CheckGrid::Cell> cells;
};

}  // namespace

namespace {

/// check_surface of the patches of `corners`, evaluated by samplers from `sampler`, with the
/// creases and cone points of `kgons`.
SurfaceCheckReport check_patches_surface(const HalfedgeMesh& mesh,
                                         const std::vector<Corner>& corners, const KgonSet& kgons,
                                         const std::function<PatchSampler()>& sampler,
                                         int resolution, const SurfaceCheckOptions& options) {
  limits::check_resolution(resolution, "check_surface: the resolution");
  const int n = resolution, side = n + 1;
  const TessellationLayout layout(mesh, corners, n, true);
  const std::int64_t triangles = 2 * layout.num_quads();
  if (triangles > std::numeric_limits<int>::max())
    throw UsageError(fmt::format(
        "{} triangles at resolution {} are more than the check numbers (2^31 - 1): check at a "
        "lower resolution",
        triangles, n));
  if (corners.empty()) return {};
  const auto samples = static_cast<size_t>(side) * side;
  tbb::enumerable_thread_specific<PatchSamples> grids([&] {
    return PatchSamples{sampler(),
                        std::vector<Vec3>(samples),
                        {},
                        std::vector<std::int64_t>(samples),
                        std::vector<detail::CheckGrid::Cell>(samples)};
  });

  // Each patch's box, and the first patch (by index) with a sample that is not finite.
  std::vector<std::array<Vec3, 2>> boxes(corners.size());
  std::atomic<size_t> first_bad{corners.size()};
  tbb::parallel_for(size_t{0}, corners.size(), [&](size_t k) {
    PatchSamples& g = grids.local();
    layout.grid_positions(g.sampler, static_cast<int>(k), g.positions.data(), g.scratch);
    Vec3 lo = g.positions[0], hi = lo;
    for (const Vec3& p : g.positions) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    boxes[k] = {lo, hi};
    if (lo.allFinite() && hi.allFinite()) return;
    size_t seen = first_bad.load();
    while (k < seen && !first_bad.compare_exchange_weak(seen, k)) {
    }
  });
  if (const size_t bad = first_bad.load(); bad < corners.size())
    throw InputError(fmt::format("the surface is not finite on the patch of corner half-edge {}",
                                 corners[bad].idx));
  Vec3 lo = boxes[0][0], hi = boxes[0][1];
  double mean_size = 0;
  for (const auto& [blo, bhi] : boxes) {
    lo = lo.cwiseMin(blo);
    hi = hi.cwiseMax(bhi);
    mean_size += (bhi - blo).maxCoeff();
  }
  // Cells about a triangle across (a patch's n-th part); tiles about eight patches across, so
  // that few patches are evaluated for more than one tile.
  mean_size /= static_cast<double>(corners.size()) * n;
  const int tile = std::clamp(8 * n, 32, 128);
  detail::CheckGrid grid(lo, hi, mean_size, tile);
  // Coarser while a few large patches among many small ones would meet many tiles.
  const detail::TileRuns runs = detail::sort_into_tiles(
      grid, lo, hi, corners.size(), [&](size_t k) { return std::pair(boxes[k][0], boxes[k][1]); });

  const std::vector<std::uint8_t> cone = cone_points(mesh, kgons);
  const auto gather = [&](size_t t, detail::TileTriangles& out) {
    PatchSamples& g = grids.local();
    const detail::CheckGrid::Cell origin = grid.tile_origin(runs.keys[t]);
    // Whether a triangle's box meets the tile: along each axis, one of its corners' cells is at
    // or past the tile's first and one before its end.
    const auto meets_tile = [&](const std::array<int, 3>& tri) {
      for (int axis = 0; axis < 3; ++axis) {
        const int a = g.cells[tri[0]][axis], b = g.cells[tri[1]][axis], c = g.cells[tri[2]][axis];
        if (std::max({a, b, c}) < origin[axis] ||
            std::min({a, b, c}) >= origin[axis] + grid.tile_cells())
          return false;
      }
      return true;
    };
    for (size_t e = runs.starts[t]; e < runs.starts[t + 1]; ++e) {
      const auto k = static_cast<int>(runs.item(e));
      const Corner c = corners[static_cast<size_t>(k)];
      layout.grid_positions(g.sampler, k, g.positions.data(), g.scratch);
      layout.grid_vertices(k, g.vertices.data());
      for (size_t m = 0; m < samples; ++m) g.cells[m] = grid.cell(g.positions[m]);
      // Side j = 0 of the grid lies on edge(c), side i = 0 on edge(prev(c)), sample (0, 0) on
      // the corner's vertex.
      const bool sharp_j0 = kgons.sharp(HalfedgeMesh::edge(c));
      const bool sharp_i0 = kgons.sharp(HalfedgeMesh::edge(mesh.prev(c)));
      const bool cone_at_0 = cone[mesh.origin(c).idx] != 0;
      const auto on_crease = [&](int a, int b) {
        return (sharp_j0 && a % side == 0 && b % side == 0) ||
               (sharp_i0 && a / side == 0 && b / side == 0);
      };
      for (int cell = 0; cell < n * n; ++cell) {
        const int at = cell / n * side + cell % n;
        // Counter-clockwise as TessellationLayout::quads walks the cell.
        const std::array<int, 4> loop{at, at + side, at + side + 1, at + 1};
        const auto split = quad_triangles(loop, g.positions);
        for (int s = 0; s < 2; ++s) {
          const std::array<int, 3>& tri = split[s];
          const std::array<int, 3> v{static_cast<int>(g.vertices[tri[0]]),
                                     static_cast<int>(g.vertices[tri[1]]),
                                     static_cast<int>(g.vertices[tri[2]])};
          // A cell at a collapsed side repeats a vertex: no triangle (as triangulate does).
          if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) continue;
          const Vec3 &p0 = g.positions[tri[0]], &p1 = g.positions[tri[1]],
                     &p2 = g.positions[tri[2]];
          if (!meets_tile(tri)) continue;
          std::uint8_t flags = 0;
          for (int m = 0; m < 3; ++m) {
            if (on_crease(tri[m], tri[(m + 1) % 3])) flags |= detail::kCreaseEdge << m;
            if (cone_at_0 && tri[m] == 0) flags |= detail::kConeVertex << m;
          }
          const std::int64_t quad = static_cast<std::int64_t>(k) * n * n + cell;
          out.add(p0, p1, p2, v, static_cast<int>(2 * quad + s), flags);
        }
      }
    }
  };
  return detail::check_tiles(runs.keys, grid, gather, static_cast<int>(triangles), options);
}

}  // namespace

SurfaceCheckReport check_surface(const HalfedgeMesh& mesh, const Surface& surface, int resolution,
                                 const SurfaceCheckOptions& options) {
  return check_patches_surface(
      mesh, surface.corners(), surface.bezier().kgons,
      [&] { return PatchSampler(surface, resolution); }, resolution, options);
}

SurfaceCheckReport check_surface(const HalfedgeMesh& mesh, Method method, const KgonSet& kgons,
                                 const std::vector<ControlNet>& nets, int resolution,
                                 const SurfaceCheckOptions& options) {
  if (method == Method::cc)
    throw UsageError("check_surface: the Catmull-Clark surface has no nets of its own");
  const std::vector<Corner> corners = mesh.patch_corners();
  return check_patches_surface(
      mesh, corners, kgons, [&] { return PatchSampler(method, nets, resolution); }, resolution,
      options);
}

}  // namespace stitch
