#include "stitch/tess/patch_grid.hpp"

#include "stitch/error.hpp"

namespace stitch {

PatchGrid::PatchGrid(int resolution) : n_(resolution) {
  if (n_ < 1) throw UsageError("the resolution must be at least 1");
  uv_.reserve(static_cast<size_t>(num_samples()));
  for (int i = 0; i <= n_; ++i)
    for (int j = 0; j <= n_; ++j)
      uv_.emplace_back(static_cast<double>(i) / n_, static_cast<double>(j) / n_);
  quads_.reserve(static_cast<size_t>(num_quads()));
  for (int i = 0; i < n_; ++i)
    for (int j = 0; j < n_; ++j)
      quads_.push_back({sample(i, j), sample(i + 1, j), sample(i + 1, j + 1), sample(i, j + 1)});
}

void PatchGrid::quads(int base, std::array<int, 4>* out) const {
  for (const auto& c : quads_) *out++ = {base + c[0], base + c[1], base + c[2], base + c[3]};
}

}  // namespace stitch
