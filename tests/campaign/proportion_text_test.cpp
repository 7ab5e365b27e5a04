// How summary.md writes a proportion and its bounds: the three forms, outward rounding, digits near
// 0 % and 100 %.
#include "campaign/proportion_text.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace chaser::campaign {
namespace {

TEST(ProportionText, ThousandsSeparators) {
  EXPECT_EQ(with_thousands(0), "0");
  EXPECT_EQ(with_thousands(999), "999");
  EXPECT_EQ(with_thousands(1000), "1,000");
  EXPECT_EQ(with_thousands(1600), "1,600");
  EXPECT_EQ(with_thousands(1234567), "1,234,567");
  EXPECT_EQ(with_thousands(-2995), "-2,995");
}

// Two decimals, more where the value is within 0.1 % of 0 % or 100 % (two significant digits of
// the distance), bounds rounded outward, an exactly printable value left where it is.
TEST(ProportionText, PercentDigitsAndOutwardRounding) {
  EXPECT_EQ(percent(0.5), "50.00 %");
  EXPECT_EQ(percent(0.0018705809495948023, Rounding::kUp), "0.19 %");   // 1 - 0.05^(1/1600)
  EXPECT_EQ(percent(0.0018705809495948023, Rounding::kDown), "0.18 %");
  EXPECT_EQ(percent(0.19, Rounding::kUp), "19.00 %");                    // not pushed to 19.01
  EXPECT_EQ(percent(0.19, Rounding::kDown), "19.00 %");
  EXPECT_EQ(percent(2.9957e-5, Rounding::kUp), "0.0030 %");              // 1 - 0.05^(1/100000)
  EXPECT_EQ(percent(1 - 2.9957e-5, Rounding::kDown), "99.9970 %");       // not "100.00 %"
  EXPECT_EQ(percent(1.0), "100.00 %");
  EXPECT_EQ(percent(std::nan("")), "nan");
}

// The three forms of a summary.md cell, at 95 %:
//   0 of 1600: one-sided upper bound 1 - 0.05^(1/1600) = 0.18706 % -> "<= 0.19 %";
//   1600 of 1600: one-sided lower bound 0.05^(1/1600) = 99.81294 % -> ">= 99.81 %";
//   5 of 20: R's binom.test(5, 20) interval [0.08657147, 0.49104587] -> [8.65 %, 49.11 %] outward.
TEST(ProportionText, CellForms) {
  EXPECT_EQ(proportion_cell({0, 1600}), "0 of 1,600 (<= 0.19 %)");
  EXPECT_EQ(proportion_cell({1600, 1600}), "1,600 of 1,600 (>= 99.81 %)");
  EXPECT_EQ(proportion_cell({5, 20}), "25.00 % [8.65 %, 49.11 %]");
  EXPECT_EQ(proportion_cell({0, 1}), "0 of 1 (<= 95.00 %)");
  EXPECT_EQ(proportion_cell({0, 0}), "-");
}

}  // namespace
}  // namespace chaser::campaign
