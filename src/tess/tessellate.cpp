#include "stitch/tess/tessellate.hpp"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "support/finite.hpp"
#include "support/fresh_storage.hpp"
#include "tess/layout.hpp"

namespace stitch {

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
  // Every range of output vertices is computed on its own, so any split over threads gives the
  // same arrays; the finiteness scan runs on each range while it is in cache, and the first bad
  // sample is the least index found, whatever the split.
  std::atomic<std::int64_t> first_bad{layout.num_vertices()};
  tbb::parallel_for(
      tbb::blocked_range<std::int64_t>(0, layout.num_vertices(), 1024),
      [&](const tbb::blocked_range<std::int64_t>& r) {
        const SampleAttributes at{options.uv ? out.uv.data() + r.begin() : nullptr,
                                  options.patch ? out.patch.data() + r.begin() : nullptr,
                                  options.level ? out.level.data() + r.begin() : nullptr};
        layout.evaluate(surface, r.begin(), r.end(), out.positions.data() + r.begin(),
                        out.normals.data() + r.begin(), at);
        const std::int64_t bad = detail::first_non_finite(out.positions.data() + r.begin(),
                                                          out.normals.data() + r.begin(),
                                                          static_cast<std::int64_t>(r.size()));
        if (bad < 0) return;
        const std::int64_t i = r.begin() + bad;
        std::int64_t seen = first_bad.load();
        while (i < seen && !first_bad.compare_exchange_weak(seen, i)) {
        }
      });
  if (options.index_buffer) {
    detail::size_for_overwrite(out.quads, nq);
    static_assert(sizeof(std::array<int, 4>) == 4 * sizeof(int));
    tbb::parallel_for(tbb::blocked_range<std::int64_t>(0, layout.num_quads(), 4096),
                      [&](const tbb::blocked_range<std::int64_t>& r) {
                        layout.quads(r.begin(), r.end(), out.quads[r.begin()].data());
                      });
  }
  // The input limits (limits.hpp) should make this impossible; whatever shows or writes these
  // samples (render, compare, the modeler) must not get a NaN.
  if (const std::int64_t bad = first_bad.load(); bad < layout.num_vertices()) {
    std::vector<GridSample> sharing;
    layout.samples(bad, sharing);
    throw InputError(
        fmt::format("the surface is not finite at sample {} (on the patch of corner "
                    "half-edge {})",
                    bad + 1, surface.corners()[sharing[0].corner].idx));
  }
}

TessellatedMesh tessellate(const HalfedgeMesh& mesh, const Surface& surface,
                           const TessellationOptions& options) {
  TessellatedMesh out;
  tessellate(mesh, surface, options, out);
  return out;
}

}  // namespace stitch
