// Evaluating many points of a few patches after another, as tessellation does: the modified de
// Casteljau splits of an extraordinary net are made once and kept while the points stay on that
// patch, so each further point costs one polynomial evaluation instead of a descent of its own.
// The results are bit for bit Surface::evaluate's. Internal.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "polynomial.hpp"
#include "stitch/eval/surface.hpp"

namespace stitch {

class PatchSampler {
 public:
  /// `resolution`: the grid evaluate_grid samples (0 when it is not used).
  explicit PatchSampler(const Surface& surface, int resolution = 0);
  /// The Bézier patches of `nets` (indexed by corner) for method mdc or asc, without a Surface
  /// (IncrementalSurface keeps its own nets): the same points as a Surface with these nets.
  PatchSampler(Method method, const std::vector<ControlNet>& nets, int resolution);
  /// Surface::evaluate(c, u, v). Cheapest when the calls stay on the last few corners (a side
  /// shared by two patches is sampled from both in turn).
  SurfacePoint evaluate(Corner c, double u, double v);
  /// Surface::evaluate(c, i / n, j / n) for the resolution n. A polynomial patch keeps its net
  /// summed against the basis at every j (the inner sums of evaluate_polynomial), so a point of
  /// a patch sampled many times costs 12 multiply-adds and a normal.
  SurfacePoint evaluate_grid(Corner c, int i, int j);

 private:
  struct Split {
    std::uint64_t path;
    std::array<ControlNet, 4> children;
  };
  /// What is kept of one corner's net: the splits made so far (extraordinary nets), or its rows
  /// summed against the basis at each grid j (polynomial ones).
  struct Patch {
    int corner = -1;
    ControlNet relative;  ///< the corner's net minus its first point
    std::vector<Split> splits;
    std::vector<std::array<Vec3, 4>> rows, rows_dv;  ///< [j][a]: sum over b, of b(v) and b'(v)
    std::vector<char> row_ready;                     ///< [j]: rows[j] and rows_dv[j] are summed
    double tiny = 0;                                 ///< detail::degenerate_threshold
  };
  Patch& patch(Corner c);
  /// Surface::evaluate(c, u, v), with no caching.
  [[nodiscard]] SurfacePoint direct(Corner c, double u, double v) const;
  const std::array<ControlNet, 4>& split_at(Patch& patch, const ControlNet& net,
                                            std::uint64_t path);

  const Surface* surface_;  ///< null: the Bézier patches of nets_ alone (not cc)
  Method method_;
  const std::vector<ControlNet>& nets_;
  int resolution_;
  std::vector<detail::CubicBasis> basis_;  ///< at t = k / resolution, k = 0..resolution
  std::array<Patch, 4> patches_;
  int next_ = 0;                                   ///< the slot a new corner takes (round robin)
  std::array<std::array<ControlNet, 4>, 2> deep_;  ///< uncached splits, alternately
  int latest_deep_ = 0;
};

}  // namespace stitch
