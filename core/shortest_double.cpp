#include "core/shortest_double.hpp"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <dragonbox/dragonbox.h>

namespace chaser {

namespace {

constexpr char kTwoDigits[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

void two_digits(char* out, std::uint32_t v) { std::memcpy(out, kTwoDigits + 2 * v, 2); }

// Exactly eight digits of v < 10^8, leading zeros included: four pairs that do not wait on each
// other (a digit-by-digit loop is a chain of divisions).
void eight_digits(char* out, std::uint32_t v) {
  const std::uint32_t high = v / 10000, low = v % 10000;
  two_digits(out, high / 100);
  two_digits(out + 2, high % 100);
  two_digits(out + 4, low / 100);
  two_digits(out + 6, low % 100);
}

constexpr std::uint64_t kPowersOfTen[] = {
    1ULL, 10ULL, 100ULL, 1000ULL, 10000ULL, 100000ULL, 1000000ULL, 10000000ULL, 100000000ULL,
    1000000000ULL, 10000000000ULL, 100000000000ULL, 1000000000000ULL, 10000000000000ULL,
    100000000000000ULL, 1000000000000000ULL, 10000000000000000ULL, 100000000000000000ULL,
    1000000000000000000ULL};

// Digits of 0 < v < 10^18 without a loop: log10(2) ~ 1233 / 4096 turns the bit length into the
// digit count or one more, which one comparison settles.
int decimal_length(std::uint64_t v) {
  const int guess = (std::bit_width(v) * 1233) >> 12;  // floor(log10(v)) or one more
  return guess + 1 - (v < kPowersOfTen[guess] ? 1 : 0);
}

}  // namespace

char* write_shortest_double(char* out, double x) {
  if (x == 0.0) {  // most of a telemetry row: "0" or "-0", as to_chars writes them, without it
    if (std::signbit(x)) *out++ = '-';
    *out = '0';
    return out + 1;
  }
  if (!std::isfinite(x)) return std::to_chars(out, out + kMaxShortestDoubleChars, x).ptr;
  // |x| ~ significand * 10^exponent: the shortest significand that rounds back to x (the nearest
  // such where several have that length), without trailing zeros.
  const auto decimal = jkj::dragonbox::to_decimal(x);
  const std::uint64_t significand = decimal.significand;  // < 10^17
  const int n = decimal_length(significand);              // 1..17
  const int e = decimal.exponent;                         // of the last digit
  const int sci_exponent = e + n - 1;                     // of the first digit
  const int abs_sci = sci_exponent < 0 ? -sci_exponent : sci_exponent;
  const int sci_length = n + (n > 1 ? 1 : 0) + 2 + (abs_sci >= 100 ? 3 : 2);  // d.ddde+XX
  const int fixed_length = e >= 0 ? n + e : (-e < n ? n + 1 : 2 - e);          // ddd000, dd.d, 0.0ddd
  const bool fixed = fixed_length <= sci_length;
  if (fixed && e > 0 && std::fabs(x) >= 0x1p53) {
    // to_chars writes a whole number of 2^53 or more in full (1234567890123456768, not the
    // shortest digits and zeros 1234567890123456800): rare, left to it.
    return std::to_chars(out, out + kMaxShortestDoubleChars, x).ptr;
  }
  // All 24 digit places, the significand right-aligned, then copies of a fixed 16 or 17 bytes
  // (the places past the n digits are overwritten or past the end): no loop and no branch on the
  // digit count, which varies from number to number.
  char places[48] = {};  // read past the 24 places by the fixed-size copies, never written out
  const auto top = static_cast<std::uint32_t>(significand / 10'000'000'000'000'000);
  const std::uint64_t rest = significand % 10'000'000'000'000'000;
  eight_digits(places, top);
  eight_digits(places + 8, static_cast<std::uint32_t>(rest / 100'000'000));
  eight_digits(places + 16, static_cast<std::uint32_t>(rest % 100'000'000));
  const char* digits = places + 24 - n;
  if (decimal.is_negative) *out++ = '-';
  if (fixed) {
    if (e >= 0) {  // a whole number below 2^53: its digits and zeros are its exact value
      std::memcpy(out, digits, 17);
      std::memset(out + n, '0', static_cast<std::size_t>(e));
      return out + n + e;
    }
    if (-e >= n) {  // 0.00ddd
      const int zeros = -e - n;
      out[0] = '0';
      out[1] = '.';
      std::memset(out + 2, '0', static_cast<std::size_t>(zeros));
      std::memcpy(out + 2 + zeros, digits, 17);
      return out + 2 - e;
    }
    const int whole = n + e;  // dd.ddd
    std::memcpy(out, digits, 16);
    out[whole] = '.';
    std::memcpy(out + whole + 1, digits + whole, 16);
    return out + n + 1;
  }
  out[0] = digits[0];  // d.dddde+XX
  if (n > 1) {
    out[1] = '.';
    std::memcpy(out + 2, digits + 1, 16);
    out += n + 1;
  } else {
    out += 1;
  }
  *out++ = 'e';
  *out++ = sci_exponent < 0 ? '-' : '+';
  if (abs_sci >= 100) *out++ = static_cast<char>('0' + abs_sci / 100);
  two_digits(out, static_cast<std::uint32_t>(abs_sci % 100));
  return out + 2;
}

}  // namespace chaser
