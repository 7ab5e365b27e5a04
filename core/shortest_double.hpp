#pragma once
// The shortest text that reads back to the same double, laid out exactly as std::to_chars(first,
// last, x) lays it out (fixed or scientific, whichever is shorter, fixed on a tie; "-0", "inf",
// "nan"), about three times faster on telemetry's numbers: Dragonbox (Jeon 2020, Debian
// libdragonbox-dev) finds the digits and the exponent, this writes them. A kernel for the
// telemetry writer, which formats a million numbers per run; std::to_chars is its reference and
// its test (tests/core/shortest_double_test.cpp).
#include <cstddef>

namespace chaser {

// to_chars' shortest double is at most 24 characters ("-2.2250738585072014e-308").
inline constexpr std::size_t kMaxShortestDoubleChars = 24;
// The bytes at `out` the writer may use: it copies digits in blocks of a fixed 16 or 17 bytes and
// lets the text's end fall inside the last block, so the caller leaves this much room.
inline constexpr std::size_t kShortestDoubleRoom = 48;

// Writes the text (at most kMaxShortestDoubleChars characters) at `out`, using at most
// kShortestDoubleRoom bytes there; returns one past the text's last character.
char* write_shortest_double(char* out, double x);

}  // namespace chaser
