#include "control/joint_design.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "control/six_axis_design.hpp"

namespace chaser::control {

std::array<AxisDesignSpec, model::kArmJoints> joint_specs(const model::HinfLoopWeights& weights, double torque_limit_Nm,
                                                          const std::array<double, model::kArmJoints>& inertia_kgm2,
                                                          double delay_s) {
  if (!(torque_limit_Nm > 0.0) || !std::isfinite(torque_limit_Nm))
    throw std::invalid_argument(fmt::format("the joints' torque limit must be positive (got {} N m)", torque_limit_Nm));
  std::array<AxisDesignSpec, model::kArmJoints> specs;
  for (std::size_t j = 0; j < specs.size(); ++j) {
    if (!(inertia_kgm2[j] > 0.0) || !std::isfinite(inertia_kgm2[j]))
      throw std::invalid_argument(fmt::format("joint {}'s inertia must be positive (got {} kg m^2)", j + 1, inertia_kgm2[j]));
    AxisDesignSpec& spec = specs[j];
    spec.name = fmt::format("joint{}", j + 1);
    spec.authority = torque_limit_Nm / inertia_kgm2[j];  // [rad/s^2]
    spec.delay_s = delay_s;
    set_weights(spec, weights);
  }
  return specs;
}

}  // namespace chaser::control
