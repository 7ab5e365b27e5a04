#pragma once
// The scaling the allocators use to make their tolerances dimensionless without rounding.
#include <cmath>

namespace chaser {

// 2^k with value / 2^k in [0.5, 1) (1 for value <= 0 or NaN): dividing by it is exact in binary
// floating point.
inline double power_of_two_above(double value) {
  if (!(value > 0.0)) return 1.0;
  int exponent = 0;
  std::frexp(value, &exponent);
  return std::ldexp(1.0, exponent);
}

}  // namespace chaser
