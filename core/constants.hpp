#pragma once

namespace chaser {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kStandardGravity = 9.80665;  // [m/s^2] g0, for specific impulse
inline constexpr double kDegToRad = kPi / 180.0;

}  // namespace chaser
