#pragma once
// What the campaign's tables share: the missing figure, the arm's torque limit the COMRADE tables
// judge against, and how a figure is written into a cell.
#include <cmath>
#include <limits>
#include <string>

#include <fmt/format.h>

#include "model/arm.hpp"

namespace chaser::campaign {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();  // a figure not there

// [N m] the joints' repeated peak torque: COMRADE 2018's, the default arm's.
inline const double kRepeatedPeakTorqueNm = model::ArmParams{}.torque_repeated_peak_Nm;

// v in the fmt format ("{:.2f}"), "-" where it is not finite.
inline std::string cell_number(double v, const char* format) {
  return std::isfinite(v) ? fmt::format(fmt::runtime(format), v) : "-";
}

}  // namespace chaser::campaign
