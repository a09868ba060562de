#include "stitch/tess/tessellate.hpp"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <vector>

#include "support/finite.hpp"
#include "support/fresh_storage.hpp"
#include "tess/layout.hpp"

namespace stitch {

namespace {

/// Output vertices [begin, end) of `layout` into `out`'s arrays from index 0, sized end - begin
/// with the attributes `options` asks for. Every range of output vertices is computed on its
/// own, so any split over threads (or into blocks) gives the same values; the finiteness scan
/// runs on each range while it is in cache, and the first bad sample is the least index found,
/// whatever the split. Throws InputError naming it.
void evaluate_vertices(const TessellationLayout& layout, const Surface& surface,
                       const TessellationOptions& options, std::int64_t begin, std::int64_t end,
                       TessellatedMesh& out) {
  const auto nv = static_cast<size_t>(end - begin);
  detail::size_for_overwrite(out.positions, nv);
  detail::size_for_overwrite(out.normals, nv);
  const auto attribute = [nv](auto& array, bool asked) {
    if (asked)
      detail::size_for_overwrite(array, nv);
    else
      array.clear();
  };
  attribute(out.uv, options.uv);
  attribute(out.patch, options.patch);
  attribute(out.level, options.level);
  std::atomic<std::int64_t> first_bad{end};
  tbb::parallel_for(
      tbb::blocked_range<std::int64_t>(begin, end, 1024),
      [&](const tbb::blocked_range<std::int64_t>& r) {
        const std::int64_t at = r.begin() - begin;
        const SampleAttributes attributes{options.uv ? out.uv.data() + at : nullptr,
                                          options.patch ? out.patch.data() + at : nullptr,
                                          options.level ? out.level.data() + at : nullptr};
        layout.evaluate(surface, r.begin(), r.end(), out.positions.data() + at,
                        out.normals.data() + at, attributes);
        const std::int64_t bad =
            detail::first_non_finite(out.positions.data() + at, out.normals.data() + at,
                                     static_cast<std::int64_t>(r.size()));
        if (bad < 0) return;
        const std::int64_t i = r.begin() + bad;
        std::int64_t seen = first_bad.load();
        while (i < seen && !first_bad.compare_exchange_weak(seen, i)) {
        }
      });
  // The input limits (limits.hpp) should make this impossible; whatever shows or writes these
  // samples (render, compare, the modeler) must not get a NaN.
  if (const std::int64_t bad = first_bad.load(); bad < end) {
    std::vector<GridSample> sharing;
    layout.samples(bad, sharing);
    throw InputError(
        fmt::format("the surface is not finite at sample {} (on the patch of corner "
                    "half-edge {})",
                    bad + 1, surface.corners()[sharing[0].corner].idx));
  }
}

}  // namespace

void tessellate(const HalfedgeMesh& mesh, const Surface& surface,
                const TessellationOptions& options, TessellatedMesh& out) {
  const TessellationLayout layout(mesh, surface.corners(), options.resolution, options.welded);
  // Checked before anything in `out` changes. The vertex count tells welded from unwelded
  // output, which have the same number of quads.
  const auto nq = static_cast<size_t>(layout.num_quads());
  const auto nv = static_cast<size_t>(layout.num_vertices());
  if (!options.index_buffer && (out.quads.size() != nq || out.positions.size() != nv))
    throw std::invalid_argument(fmt::format(
        "tessellate: kept quads were asked for, but the output holds {} vertices and {} quads "
        "where this mesh at resolution {} ({}) has {} and {}",
        out.positions.size(), out.quads.size(), options.resolution,
        options.welded ? "welded" : "unwelded", nv, nq));
  evaluate_vertices(layout, surface, options, 0, layout.num_vertices(), out);
  if (options.index_buffer) {
    detail::size_for_overwrite(out.quads, nq);
    static_assert(sizeof(std::array<int, 4>) == 4 * sizeof(int));
    tbb::parallel_for(tbb::blocked_range<std::int64_t>(0, layout.num_quads(), 4096),
                      [&](const tbb::blocked_range<std::int64_t>& r) {
                        layout.quads(r.begin(), r.end(), out.quads[r.begin()].data());
                      });
  }
}

void tessellate_blocks(const HalfedgeMesh& mesh, const Surface& surface,
                       const TessellationOptions& options, int patches_per_block,
                       const std::function<void(const TessellatedMesh&, int)>& visit) {
  if (options.welded || !options.index_buffer || patches_per_block < 1)
    throw std::invalid_argument(fmt::format(
        "tessellate_blocks: blocks of {} whole patches need welded = false and index_buffer",
        patches_per_block));
  const TessellationLayout layout(mesh, surface.corners(), options.resolution, false);
  const auto patches = static_cast<std::int64_t>(surface.corners().size());
  if (patches == 0) return;
  const std::int64_t n = options.resolution, samples = (n + 1) * (n + 1), cells = n * n;
  // Unwelded, patch k's quads are the first patch's moved by k grids: numbered from the block's
  // first sample, they stay small whatever the mesh.
  std::vector<std::array<int, 4>> first_quads(static_cast<size_t>(cells));
  layout.quads(0, cells, first_quads.front().data());
  TessellatedMesh block;  // its storage serves every block
  for (std::int64_t first = 0; first < patches; first += patches_per_block) {
    const std::int64_t count = std::min<std::int64_t>(patches_per_block, patches - first);
    evaluate_vertices(layout, surface, options, first * samples, (first + count) * samples, block);
    block.quads.resize(static_cast<size_t>(count * cells));
    for (std::int64_t k = 0; k < count; ++k)
      for (std::int64_t c = 0; c < cells; ++c)
        for (int m = 0; m < 4; ++m)
          block.quads[k * cells + c][m] = first_quads[c][m] + static_cast<int>(k * samples);
    visit(block, static_cast<int>(first));
  }
}

TessellatedMesh tessellate(const HalfedgeMesh& mesh, const Surface& surface,
                           const TessellationOptions& options) {
  TessellatedMesh out;
  tessellate(mesh, surface, options, out);
  return out;
}

}  // namespace stitch
