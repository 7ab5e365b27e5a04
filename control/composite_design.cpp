#include "control/composite_design.hpp"

#include <algorithm>
#include <limits>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "control/six_axis_design.hpp"
#include "model/recovery.hpp"
#include "model/thruster_geometry.hpp"
#include "model/thruster_set_analysis.hpp"

namespace chaser::control {

std::array<AxisDesignSpec, 3> composite_specs(const model::Scenario& scenario) {
  if (!scenario.capture || !scenario.capture->stabilise)
    throw std::invalid_argument("the scenario has no capture.stabilise section: nothing to design (docs/scenario.md)");
  const model::HinfLoopWeights& w = scenario.capture->stabilise->hinf;
  const model::ThrusterMask active = model::initial_configuration(scenario.thrusters).active;
  const model::AttainableAxes axes =
      model::attainable_axes(model::configuration_columns(scenario.thrusters, active, scenario.chaser.com_body_m));
  double weakest = std::numeric_limits<double>::infinity();
  for (int k = 3; k < 6; ++k)  // signed axes 2k (+) and 2k + 1 (-) of the torque's components
    weakest = std::min({weakest, axes.value[static_cast<std::size_t>(2 * k)], axes.value[static_cast<std::size_t>(2 * k + 1)]});
  if (!(weakest > 0.0))
    throw std::invalid_argument("the active thrusters cannot turn the chaser about every body axis: no couple to design for");
  std::array<AxisDesignSpec, 3> specs;
  for (std::size_t i = 0; i < specs.size(); ++i) {
    AxisDesignSpec& spec = specs[i];
    spec.name = kCompositeAxisNames[i];
    spec.authority = weakest;  // [N m]: Phi'' = T
    spec.delay_s = loop_delay_s(scenario);
    set_weights(spec, w);
  }
  return specs;
}

AxisUncertainty composite_uncertainty(const model::Scenario& scenario, double inertia_relative_error) {
  const auto& box = scenario.control.hinf ? scenario.control.hinf->robustness : std::nullopt;
  const double thrust = box ? box->thrust_uncertainty : 0.0;
  AxisUncertainty u;
  u.gain_lo = (1.0 - thrust) * (1.0 - inertia_relative_error);
  u.gain_hi = (1.0 + thrust) * (1.0 + inertia_relative_error);
  const double fixed = 0.5 * scenario.control_period_s + 0.5 * scenario.thrusters.rise_time_s;
  u.delay_lo_s = fixed;
  u.delay_hi_s = fixed + scenario.thrusters.delay_max_s;
  u.points_per_range = box ? box->points_per_range : 5;
  return u;
}

}  // namespace chaser::control
