#pragma once
// Battin's f(q) = (1 + q)^(3/2) - 1, evaluated without cancellation for small q (q > -1) (Battin
// 1999, sec. 8.4): the difference of two gravity accelerations at nearly the same radius without
// subtracting them (plant/relative_orbit.hpp, plant/earth/gravity.hpp).
#include <cmath>

namespace chaser {

inline double battin_f(double q) {
  const double cube_ratio = (1.0 + q) * std::sqrt(1.0 + q);  // (1 + q)^(3/2)
  return q * (3.0 + q * (3.0 + q)) / (1.0 + cube_ratio);
}

}  // namespace chaser
