// The text writers' number formatting: doubles come out byte for byte as std::to_chars writes
// them (so the files are the same as before, and read back exactly), integers as decimal.
#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <random>
#include <string>

#include "mesh/number_text.hpp"

namespace stitch::detail {
namespace {

std::string standard_text(double x) {
  char text[64];
  return {text, std::to_chars(text, text + sizeof text, x).ptr};
}

std::string fast_text(double x) {
  char text[kMaxDoubleChars];
  return {text, write_shortest(text, x)};
}

TEST(NumberText, DoublesAsTheStandardLibraryWritesThem) {
  // Random bit patterns cover every exponent, subnormals, inf and nan; the uniform ones the
  // coordinates and normals of a mesh.
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> coordinate(-3, 3);
  for (int i = 0; i < 300000; ++i) {
    const double any = std::bit_cast<double>(random());
    ASSERT_EQ(fast_text(any), standard_text(any)) << "bits " << std::bit_cast<std::uint64_t>(any);
    const double x = coordinate(random);
    ASSERT_EQ(fast_text(x), standard_text(x)) << "bits " << std::bit_cast<std::uint64_t>(x);
  }
  // Where the notation changes (fixed or scientific, whichever is shorter), and the extremes.
  for (int e = -325; e <= 308; ++e)
    for (const double m : {1.0, 1.5, 9.999, 123456.0, 1.0 / 3, 0.7})
      for (const double sign : {1.0, -1.0}) {
        const double x = sign * m * std::pow(10.0, e);
        ASSERT_EQ(fast_text(x), standard_text(x)) << "bits " << std::bit_cast<std::uint64_t>(x);
      }
  using limits = std::numeric_limits<double>;
  for (const double x :
       {0.0, -0.0, 1.0, 100.0, 1e15, 1e16, 1e21, 1e22, 123456789012345680000.0, 1e-5, 1e-4,
        limits::min(), limits::denorm_min(), limits::max(), limits::lowest(), limits::infinity(),
        -limits::infinity(), limits::quiet_NaN(), std::nextafter(1.0, 2.0)})
    EXPECT_EQ(fast_text(x), standard_text(x)) << x;
  // The longest text fits the room promised.
  EXPECT_EQ(fast_text(-2.2250738585072014e-308).size(), static_cast<size_t>(kMaxDoubleChars));
}

TEST(NumberText, IntegersInDecimal) {
  std::mt19937_64 random(5);
  const auto check = [](std::uint64_t value) {
    char fast[kMaxDecimalChars], standard[32];
    ASSERT_EQ(std::string(fast, write_decimal(fast, value)),
              std::string(standard, std::to_chars(standard, standard + 32, value).ptr));
  };
  for (const std::uint64_t value : std::initializer_list<std::uint64_t>{
           0, 9, 10, 99, 100, 99999999, 100000000, std::numeric_limits<std::uint64_t>::max()})
    check(value);
  for (int i = 0; i < 100000; ++i) check(random() >> (random() % 64));
}

}  // namespace
}  // namespace stitch::detail
