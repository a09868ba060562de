// Numbers as text for the text mesh writers, which write hundreds of millions of them: doubles
// exactly as std::to_chars writes them, in a third of the time, and non-negative integers.
// Internal to the library.
#pragma once

#include <cstdint>

namespace stitch::detail {

/// Room enough for any double write_shortest writes ("-2.2250738585072014e-308").
inline constexpr int kMaxDoubleChars = 24;
/// Room enough for any std::uint64_t write_decimal writes.
inline constexpr int kMaxDecimalChars = 20;

/// Writes `x` at `at` exactly as std::to_chars(at, at + kMaxDoubleChars, x) does (the shortest
/// text that reads back as x, in fixed or scientific notation, whichever is shorter, fixed in a
/// tie; inf and nan as to_chars writes them) and returns the end. Shortest digits from fmt's
/// Dragonbox (the standard library's Ryu takes three times as long for the whole).
char* write_shortest(char* at, double x);

/// Writes `value` in decimal at `at` and returns the end.
char* write_decimal(char* at, std::uint64_t value);

}  // namespace stitch::detail
