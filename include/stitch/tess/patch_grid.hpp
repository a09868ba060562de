// The sample layout of one patch at a resolution n: its (n + 1)^2 grid samples, row-major
// (sample s = (i, j) with s = i * (n + 1) + j, at u = i / n, v = j / n), and the n^2 quads between
// them, counter-clockwise seen from the normal side. The unwelded tessellation (one block per
// patch, tessellate(..., welded = false)) and IncrementalSurface's per-slot blocks both lay their
// blocks out with it, so the two agree sample for sample by construction.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace stitch {

class PatchGrid {
 public:
  /// Throws UsageError for a resolution below 1.
  explicit PatchGrid(int resolution);

  [[nodiscard]] int resolution() const { return n_; }
  [[nodiscard]] int num_samples() const { return (n_ + 1) * (n_ + 1); }
  [[nodiscard]] int num_quads() const { return n_ * n_; }
  /// The number of sample (i, j) within its block.
  [[nodiscard]] int sample(int i, int j) const { return i * (n_ + 1) + j; }
  [[nodiscard]] int row(int s) const { return s / (n_ + 1); }     ///< i of sample s
  [[nodiscard]] int column(int s) const { return s % (n_ + 1); }  ///< j of sample s
  /// (u, v) = (i / n, j / n) of sample s.
  [[nodiscard]] const Eigen::Vector2d& uv(int s) const { return uv_[static_cast<size_t>(s)]; }
  /// Quad q (cell (q / n, q % n)) of a block whose sample 0 is vertex `base`.
  [[nodiscard]] std::array<std::int64_t, 4> quad(int q, std::int64_t base) const {
    const auto& c = quads_[static_cast<size_t>(q)];
    return {base + c[0], base + c[1], base + c[2], base + c[3]};
  }
  /// The block's num_quads() quads, with vertex numbers offset by `base`, into `out`.
  void quads(int base, std::array<int, 4>* out) const;

 private:
  int n_;
  std::vector<Eigen::Vector2d> uv_;
  std::vector<std::array<int, 4>> quads_;  ///< of a block at base 0
};

}  // namespace stitch
