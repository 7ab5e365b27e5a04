#include "control/six_axis_design.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "model/recovery.hpp"
#include "model/thruster_geometry.hpp"
#include "model/thruster_set_analysis.hpp"

namespace chaser::control {

double loop_delay_s(const model::Scenario& scenario) {
  return 0.5 * scenario.control_period_s + 0.5 * scenario.thrusters.delay_max_s + 0.5 * scenario.thrusters.rise_time_s;
}

void set_weights(AxisDesignSpec& spec, const model::HinfLoopWeights& w) {
  spec.bandwidth_radps = w.bandwidth_radps;
  spec.peak_sensitivity = w.peak_sensitivity;
  spec.low_frequency_gain = w.low_frequency_gain;
  spec.error_scale = w.error_scale;
  spec.input_disturbance = w.input_disturbance;
}

std::array<AxisDesignSpec, 6> six_axis_specs(const model::Scenario& scenario) {
  if (!scenario.control.hinf)
    throw std::invalid_argument("the scenario has no control.hinf section: nothing to design (docs/scenario.md)");
  const model::HinfDesignParams& hinf = *scenario.control.hinf;
  const model::ThrusterMask active = model::initial_configuration(scenario.thrusters).active;
  const model::AttainableAxes axes =
      model::attainable_axes(model::configuration_columns(scenario.thrusters, active, scenario.chaser.com_body_m));
  const double delay_s = loop_delay_s(scenario);
  std::array<AxisDesignSpec, 6> specs;
  for (int k = 0; k < 6; ++k) {
    // Signed axes 2k (+) and 2k + 1 (-) of wrench component k.
    const double pure = std::min(axes.value[static_cast<std::size_t>(2 * k)], axes.value[static_cast<std::size_t>(2 * k + 1)]);
    if (!(pure > 0.0))
      throw std::invalid_argument(fmt::format("the active thrusters cannot {} along body {}: no authority to design for",
                                              k < 3 ? "push" : "turn", k < 3 ? "xyz"[k] : "xyz"[k - 3]));
    const bool translation = k < 3;
    const model::HinfLoopWeights& w = translation ? hinf.translation : hinf.rotation;
    AxisDesignSpec& spec = specs[static_cast<std::size_t>(k)];
    spec.name = kAxisNames[static_cast<std::size_t>(k)];
    spec.authority = translation ? pure / scenario.chaser.mass_kg : pure / scenario.chaser.inertia_kgm2(k - 3, k - 3);
    spec.delay_s = delay_s;
    set_weights(spec, w);
  }
  return specs;
}

AxisUncertainty axis_uncertainty(const model::Scenario& scenario, const model::HinfRobustnessParams& box, int axis) {
  AxisUncertainty u;
  u.gain_lo = (1.0 - box.thrust_uncertainty) / (1.0 + box.mass_uncertainty);
  u.gain_hi = (1.0 + box.thrust_uncertainty) / (1.0 - box.mass_uncertainty);
  const double fixed = 0.5 * scenario.control_period_s + 0.5 * scenario.thrusters.rise_time_s;
  u.delay_lo_s = fixed;
  u.delay_hi_s = fixed + scenario.thrusters.delay_max_s;
  for (const model::UncertainModeSpec& m : axis < 3 ? box.translation_modes : box.rotation_modes)
    u.modes.push_back({m.name, m.frequency_lo_radps, m.frequency_hi_radps, m.modal_fraction, m.damping});
  u.points_per_range = box.points_per_range;
  return u;
}

bool SixAxisDesign::ok() const {
  return std::all_of(axes.begin(), axes.end(), [](const AxisDesign& a) { return a.ok(); });
}

bool SixAxisDesign::robust() const {
  return ok() && (!checked_robustness || std::all_of(robustness.begin(), robustness.end(),
                                                     [](const RobustnessResult& r) { return r.robustly_stable(); }));
}

SixAxisDesign design_six_axes(const model::Scenario& scenario) {
  SixAxisDesign design;
  design.delay_s = loop_delay_s(scenario);
  const std::array<AxisDesignSpec, 6> specs = six_axis_specs(scenario);
  for (std::size_t k = 0; k < specs.size(); ++k) design.axes[k] = design_axis(specs[k]);
  const auto& box = scenario.control.hinf->robustness;
  if (!box || !design.ok()) return design;
  design.checked_robustness = true;
  for (std::size_t k = 0; k < specs.size(); ++k) {
    design.boxes[k] = axis_uncertainty(scenario, *box, static_cast<int>(k));
    design.robustness[k] = robust_stability_grid(design.axes[k], design.boxes[k]);
    design.mu[k] = loop_mu(design.axes[k], design.boxes[k]);
  }
  return design;
}

}  // namespace chaser::control
