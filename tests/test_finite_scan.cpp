// detail::all_finite (support/finite.hpp), the scan tessellate and the streamed writers run over
// every range of samples: any infinite or NaN component anywhere is found, and nothing finite
// (zeros, subnormals, the largest doubles) is taken for one.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "stitch/tess/tessellated_mesh.hpp"
#include "support/finite.hpp"

namespace stitch::detail {
namespace {

TEST(FiniteScan, FindsInfinityAndNaNInAnyComponentAndPassesEveryFiniteValue) {
  constexpr double kMax = std::numeric_limits<double>::max();
  constexpr double kTiny = std::numeric_limits<double>::denorm_min();
  std::vector<Vec3> v(37, Vec3(1.0, -0.0, 0.0));
  v[3] = Vec3(kMax, -kMax, kTiny);
  v[4] = Vec3(-kTiny, std::numeric_limits<double>::min(), 1e300);
  EXPECT_TRUE(all_finite(v.data(), static_cast<std::int64_t>(v.size())));
  EXPECT_TRUE(all_finite(v.data(), 0));
  for (const double bad : {std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity(), std::nan(""), -std::nan("")})
    for (size_t at = 0; at < v.size(); at += 6)
      for (int axis = 0; axis < 3; ++axis) {
        std::vector<Vec3> w = v;
        w[at][axis] = bad;
        EXPECT_FALSE(all_finite(w.data(), static_cast<std::int64_t>(w.size())))
            << bad << " at " << at << ", axis " << axis;
        // Only the vectors asked about are looked at.
        EXPECT_TRUE(all_finite(w.data(), static_cast<std::int64_t>(at)));
      }
}

// first_non_finite_sample, which checks a held tessellation before it is written, names the first
// bad sample, whether its position or its normal is bad, also when the mesh has fewer normals.
TEST(FiniteScan, FirstNonFiniteSampleNamesTheFirstBadSample) {
  TessellatedMesh mesh;
  mesh.positions.assign(20, Vec3(1, 2, 3));
  mesh.normals.assign(20, Vec3(0, 0, 1));
  EXPECT_EQ(first_non_finite_sample(mesh), -1);
  mesh.positions[12].y() = std::nan("");
  EXPECT_EQ(first_non_finite_sample(mesh), 12);
  mesh.normals[7].x() = std::numeric_limits<double>::infinity();
  EXPECT_EQ(first_non_finite_sample(mesh), 7);
  mesh.normals.resize(5);  // the bad normal is no longer there
  EXPECT_EQ(first_non_finite_sample(mesh), 12);
}

}  // namespace
}  // namespace stitch::detail
