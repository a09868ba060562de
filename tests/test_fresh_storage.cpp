// The storage of large output arrays (support/fresh_storage.hpp): reused when large enough,
// replaced and advised into huge pages when not.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "support/fresh_storage.hpp"

namespace stitch::detail {
namespace {

TEST(FreshStorage, LargeEnoughStorageIsKeptAndTooSmallIsReplaced) {
  std::vector<double> v(1000, 1.0);
  const double* const before = v.data();
  size_for_overwrite(v, 600);
  EXPECT_EQ(v.size(), 600U);
  EXPECT_EQ(v.data(), before);  // no allocation: tessellating again writes into the same pages
  size_for_overwrite(v, 1000);
  EXPECT_EQ(v.data(), before);
  size_for_overwrite(v, 5000);
  EXPECT_EQ(v.size(), 5000U);
  EXPECT_GE(v.capacity(), 5000U);
}

// The transparent huge page mode of this kernel ("always", "madvise" or "never"), or "" where
// there is none (other systems, containers without /sys).
std::string huge_page_mode() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string line;
  if (!std::getline(in, line)) return {};
  const auto open = line.find('['), close = line.find(']');
  return open == std::string::npos || close == std::string::npos
             ? std::string()
             : line.substr(open + 1, close - open - 1);
}

TEST(FreshStorage, HugePagesAreAskedForOnlyForLargeRegions) {
  std::vector<char> small(1 << 20);
  EXPECT_FALSE(prefer_huge_pages(small.data(), small.size()));  // not one whole 2 MB page inside
  EXPECT_FALSE(prefer_huge_pages(nullptr, std::size_t{64} << 20));
  const std::string mode = huge_page_mode();
  if (mode != "always" && mode != "madvise")
    GTEST_SKIP() << "transparent huge pages are '" << mode << "' here";
  std::vector<char> large;
  large.reserve(std::size_t{16} << 20);
  EXPECT_TRUE(prefer_huge_pages(large.data(), large.capacity()));
}

}  // namespace
}  // namespace stitch::detail
