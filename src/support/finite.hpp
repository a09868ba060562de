// A pass over many samples that says whether all of them are finite, cheap enough to run on
// every range a tessellation or a writer produces before anything trusts it. Over Eigen's
// Vector3d, the core's Vec3, since support/ comes before the mesh stage that names it.
#pragma once

#include <Eigen/Core>
#include <cstdint>

namespace stitch::detail {

/// Whether all `count` vectors from `v` are finite: x - x is 0 for a finite x and NaN for an
/// infinite or NaN one, and a sum with a NaN in it is NaN. Eigen sums in vector registers:
/// checked vector by vector with allFinite, the test cost as many instructions as writing the
/// sample (tessellate) or half as many as formatting the binary PLY it guards (the streamed
/// writer); a branch-free test of the exponent bits cost 1.5 times this sum (callgrind).
inline bool all_finite(const Eigen::Vector3d* v, std::int64_t count) {
  static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double));
  if (count <= 0) return true;
  const Eigen::Map<const Eigen::ArrayXd> x(v->data(), 3 * count);
  return (x - x).sum() == 0.0;
}

/// The first of `count` samples whose position or normal is not finite, or -1 when there is
/// none: all_finite over both arrays, and only when that fails a look sample by sample.
inline std::int64_t first_non_finite(const Eigen::Vector3d* positions,
                                     const Eigen::Vector3d* normals, std::int64_t count) {
  if (all_finite(positions, count) && all_finite(normals, count)) return -1;
  for (std::int64_t i = 0; i < count; ++i)
    if (!positions[i].allFinite() || !normals[i].allFinite()) return i;
  return -1;
}

}  // namespace stitch::detail
