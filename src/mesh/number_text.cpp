#include "mesh/number_text.hpp"

#include <fmt/format.h>

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>

namespace stitch::detail {

namespace {

// "00" to "99", two characters each.
constexpr std::array<char, 200> kTwoDigits = [] {
  std::array<char, 200> table{};
  for (int i = 0; i < 100; ++i) {
    table[2 * i] = static_cast<char>('0' + i / 10);
    table[2 * i + 1] = static_cast<char>('0' + i % 10);
  }
  return table;
}();

constexpr std::array<std::uint64_t, 20> kPowersOfTen = [] {
  std::array<std::uint64_t, 20> powers{};
  std::uint64_t power = 1;
  for (std::uint64_t& p : powers) {
    p = power;
    power *= 10;
  }
  return powers;
}();

int decimal_length(std::uint64_t value) {
  // log10(2) ~ 1233 / 4096 gives the length from the bit length, or one more than it.
  if (value == 0) return 1;
  const int guess = (std::bit_width(value) * 1233) >> 12;
  return guess + (value >= kPowersOfTen[static_cast<size_t>(guess)] ? 1 : 0);
}

/// The digits of value < 10^8 ending at `end`, two at a time from the right, in 32-bit steps.
void put_small(char* end, std::uint32_t value) {
  while (value >= 100) {
    end -= 2;
    std::memcpy(end, &kTwoDigits[2 * (value % 100)], 2);
    value /= 100;
  }
  if (value >= 10) {
    end -= 2;
    std::memcpy(end, &kTwoDigits[2 * value], 2);
  } else {
    *--end = static_cast<char>('0' + value);
  }
}

/// The digits of `value` ending at `end`: eight at a time, then the rest.
void put_digits(char* end, std::uint64_t value) {
  constexpr std::uint64_t kEight = 100000000;
  while (value >= kEight) {
    auto low = static_cast<std::uint32_t>(value % kEight);
    value /= kEight;
    for (int k = 0; k < 4; ++k) {
      end -= 2;
      std::memcpy(end, &kTwoDigits[2 * (low % 100)], 2);
      low /= 100;
    }
  }
  put_small(end, static_cast<std::uint32_t>(value));
}

}  // namespace

char* write_decimal(char* at, std::uint64_t value) {
  const int length = decimal_length(value);
  put_digits(at + length, value);
  return at + length;
}

char* write_shortest(char* at, double x) {
  if (!std::isfinite(x) || x == 0) return std::to_chars(at, at + kMaxDoubleChars, x).ptr;
  if (std::signbit(x)) {
    *at++ = '-';
    x = -x;
  }
  // x = digits * 10^exponent, with the fewest digits that read back as x (fmt's Dragonbox; an
  // internal but exported function of fmt, checked against std::to_chars in the tests).
  const auto decimal = fmt::detail::dragonbox::to_decimal(x);
  const std::uint64_t digits = decimal.significand;
  const int exponent = decimal.exponent;
  const int length = decimal_length(digits);
  // The power of ten of the first digit, and what each notation needs.
  const int scientific_exponent = exponent + length - 1;
  const int exponent_digits = std::abs(scientific_exponent) >= 100 ? 3 : 2;
  const int scientific = length + (length > 1 ? 1 : 0) + 2 + exponent_digits;
  const int fixed = exponent >= 0        ? length + exponent
                    : -exponent < length ? length + 1
                                         : 2 - exponent;
  if (fixed <= scientific) {
    // A whole number past its shortest digits gets all its digits, as printf("%.0f") writes
    // them (rare in a mesh): the standard library's text.
    if (exponent > 0) return std::to_chars(at, at + kMaxDoubleChars, x).ptr;
    if (exponent == 0) {
      put_digits(at + length, digits);
    } else if (-exponent < length) {  // digits with a point inside
      const int whole = length + exponent;
      put_digits(at + length + 1, digits);
      for (int k = 0; k < whole; ++k) at[k] = at[k + 1];  // mostly one digit: no call
      at[whole] = '.';
    } else {  // 0.000digits
      const int zeros = -exponent - length;
      at[0] = '0';
      at[1] = '.';
      std::memset(at + 2, '0', static_cast<size_t>(zeros));
      put_digits(at + 2 + zeros + length, digits);
    }
    return at + fixed;
  }
  // d.ddde+XX
  put_digits(at + length + 1, digits);
  at[0] = at[1];
  char* end = at + 1;
  if (length > 1) {
    *end = '.';
    end += length;
  }
  *end++ = 'e';
  *end++ = scientific_exponent < 0 ? '-' : '+';
  const int magnitude = std::abs(scientific_exponent);
  if (magnitude >= 100) {
    *end++ = static_cast<char>('0' + magnitude / 100);
    std::memcpy(end, &kTwoDigits[2 * (magnitude % 100)], 2);
  } else {
    std::memcpy(end, &kTwoDigits[2 * magnitude], 2);
  }
  return end + 2;
}

}  // namespace stitch::detail
