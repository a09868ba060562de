#include "stitch/tess/tessellate.hpp"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <vector>

#include "layout.hpp"

namespace stitch {

TessellatedMesh tessellate(const HalfedgeMesh& mesh, const Surface& surface,
                           const TessellationOptions& options) {
  const TessellationLayout layout(mesh, surface.corners(), options.resolution, options.welded);
  const auto nv = static_cast<size_t>(layout.num_vertices());
  TessellatedMesh out;
  out.positions.resize(nv);
  out.normals.resize(nv);
  if (options.sample_attributes) {
    out.uv.resize(nv);
    out.patch.resize(nv);
    out.level.resize(nv);
  }
  // Every range of output vertices is computed on its own, so any split over threads gives the
  // same arrays.
  tbb::parallel_for(tbb::blocked_range<std::int64_t>(0, layout.num_vertices(), 1024),
                    [&](const tbb::blocked_range<std::int64_t>& r) {
                      SampleAttributes at;
                      if (options.sample_attributes)
                        at = {out.uv.data() + r.begin(), out.patch.data() + r.begin(),
                              out.level.data() + r.begin()};
                      layout.evaluate(surface, r.begin(), r.end(), out.positions.data() + r.begin(),
                                      out.normals.data() + r.begin(), at);
                    });
  out.quads.resize(static_cast<size_t>(layout.num_quads()));
  tbb::parallel_for(tbb::blocked_range<std::int64_t>(0, layout.num_quads(), 4096),
                    [&](const tbb::blocked_range<std::int64_t>& r) {
                      std::vector<int> corners(static_cast<size_t>(4 * (r.end() - r.begin())));
                      layout.quads(r.begin(), r.end(), corners.data());
                      for (std::int64_t q = r.begin(); q < r.end(); ++q) {
                        const int* c = corners.data() + 4 * (q - r.begin());
                        out.quads[q] = {c[0], c[1], c[2], c[3]};
                      }
                    });
  // The input limits (limits.hpp) should make this impossible; whatever shows or writes these
  // samples (render, compare, the modeler) must not get a NaN.
  if (const int bad = first_non_finite_sample(out); bad >= 0)
    throw InputError(
        fmt::format("the surface is not finite at sample {}{}", bad + 1,
                    options.sample_attributes
                        ? fmt::format(" (on the patch of corner half-edge {})", out.patch[bad])
                        : std::string()));
  return out;
}

}  // namespace stitch
