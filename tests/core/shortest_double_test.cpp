// write_shortest_double against its reference, std::to_chars: the same characters for every double
// tried, and the text reads back (std::from_chars) to the same bits.
#include "core/shortest_double.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace chaser {
namespace {

// The text, checked to stay within its room: bytes past kShortestDoubleRoom keep their sentinel.
std::string ours(double x) {
  char buffer[kShortestDoubleRoom + 16];
  std::memset(buffer, '#', sizeof buffer);
  char* end = write_shortest_double(buffer, x);
  for (std::size_t j = kShortestDoubleRoom; j < sizeof buffer; ++j)
    if (buffer[j] != '#') ADD_FAILURE() << "wrote past its room for " << x;
  if (end - buffer > static_cast<std::ptrdiff_t>(kMaxShortestDoubleChars))
    ADD_FAILURE() << "longer than kMaxShortestDoubleChars for " << x;
  return std::string(buffer, end);
}

std::string reference(double x) {
  char buffer[64];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, x).ptr);
}

// Counts the doubles whose text differs from to_chars' or does not read back, and shows the first.
void expect_same_as_to_chars(const std::vector<double>& values, const char* what) {
  int mismatches = 0;
  for (const double x : values) {
    const std::string text = ours(x);
    double back = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), back);
    const bool reads_back = std::isnan(x) ? std::isnan(back)
                                          : std::bit_cast<std::uint64_t>(back) == std::bit_cast<std::uint64_t>(x);
    if (text != reference(x) || !reads_back) {
      if (mismatches++ == 0)
        ADD_FAILURE() << what << ": " << reference(x) << " written as " << text;
    }
  }
  EXPECT_EQ(mismatches, 0) << what << ", of " << values.size();
}

TEST(ShortestDouble, SpecialValuesAsToChars) {
  const double inf = std::numeric_limits<double>::infinity();
  expect_same_as_to_chars({0.0, -0.0, inf, -inf, std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest(),
                           std::numeric_limits<double>::min(), std::numeric_limits<double>::denorm_min(),
                           -std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::epsilon(),
                           -2.2250738585072014e-308, 1.0, -1.0, 0.1, 0.7071067811865476},
                          "special values");
}

// Where the layout changes: fixed against scientific (1e-5 .. 1e21 and the ties between them),
// whole numbers with trailing zeros, digits either side of the point.
TEST(ShortestDouble, LayoutBoundariesAsToChars) {
  std::vector<double> values;
  for (int p = -330; p <= 310; ++p)
    for (const double m : {1.0, 1.5, 2.0, 9.99, 1.0000000000000002, 123456789.0, 12345678901234567.0})
      for (const double sign : {1.0, -1.0}) values.push_back(sign * m * std::pow(10.0, p));
  for (std::int64_t k = -20000; k <= 20000; ++k) values.push_back(static_cast<double>(k));
  for (std::int64_t k = 1; k < 1'000'000'000'000'000'000; k *= 10)
    for (const std::int64_t d : {-1, 0, 1}) values.push_back(static_cast<double>(k + d));
  values.push_back(123456789012345680000.0);
  expect_same_as_to_chars(values, "layout boundaries");
}

// Uniform bit patterns cover every exponent, subnormals and non-finite values included.
TEST(ShortestDouble, RandomBitPatternsAsToChars) {
  std::mt19937_64 rng(20261125);
  std::vector<double> values(1'000'000);
  for (double& x : values) x = std::bit_cast<double>(rng());
  expect_same_as_to_chars(values, "random bit patterns");
}

// Telemetry's own kind of numbers: positions, rates and quaternion parts of a few significant
// digits' magnitude, most needing 15-17 digits, and short decimals such as times and thrusts.
TEST(ShortestDouble, TelemetryLikeValuesAsToChars) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> decade(-12, 4);
  std::vector<double> values;
  for (int j = 0; j < 1'000'000; ++j) values.push_back(unit(rng) * std::pow(10.0, decade(rng)));
  for (int j = 0; j <= 12'000; ++j) values.push_back(0.1 * j);  // t_s
  for (int j = 0; j <= 10'000; ++j) values.push_back(j * 1e-3 * 10.0 / 3.0);
  expect_same_as_to_chars(values, "telemetry-like values");
}

}  // namespace
}  // namespace chaser
