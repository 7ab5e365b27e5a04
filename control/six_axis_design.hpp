#pragma once
// The six loops of a scenario's H-infinity design (control.hinf; COMRADE 2018, sec. 5): after the
// computed-torque precompensation, three translation axes and three rotation axes, each a double
// integrator in commanded acceleration (control/axis_design.hpp), designed one by one.
//
// Per axis, from the scenario:
//  - authority: the smaller of the largest pure +/- force (torque) the active thrusters give along
//    the body axis (model::attainable_axes, COMRADE 2018 sec. 6.3's analysis), divided by the mass
//    (by the inertia's diagonal element): the acceleration one period of full on-time can command
//    without disturbing the other five axes;
//  - delay: what the loop waits between a measurement and the thrust it causes: half a control
//    period (the zero-order hold of a sampled command), the valve electronics' mean delay
//    (delay_max / 2: uniform in [0, delay_max), Fonod 2015 eq. 1) and the rise's equivalent delay
//    (rise_time / 2, plant/thruster_hardware.hpp);
//  - weights: control.hinf.translation for x, y, z, control.hinf.rotation for rx, ry, rz;
//  - with control.hinf.robustness, each loop is then checked over its box (robust_stability_grid),
//    and its gain and delay by AB13MD's mu bound (loop_mu; the modes stay with the grid).
// Design-time code: allocates.
#include <array>

#include "control/axis_design.hpp"
#include "control/loop_mu.hpp"
#include "control/robustness.hpp"
#include "model/scenario.hpp"

namespace chaser::control {

inline constexpr std::array<const char*, 6> kAxisNames = {"x", "y", "z", "rx", "ry", "rz"};

// The loop delay of the header: T / 2 + delay_max / 2 + rise_time / 2.
double loop_delay_s(const model::Scenario& scenario);

// A loop family's weights into a spec: omega_B, M, A, the error scale, the input disturbance.
void set_weights(AxisDesignSpec& spec, const model::HinfLoopWeights& weights);

// The six specs (x, y, z, rx, ry, rz). Throws std::invalid_argument if the scenario has no
// control.hinf section or an axis has no authority (the set cannot push along it).
std::array<AxisDesignSpec, 6> six_axis_specs(const model::Scenario& scenario);

// The box of control.hinf.robustness for axis k (0-2 translation, 3-5 rotation): the gain range
// [(1 - d_F) / (1 + d_m), (1 + d_F) / (1 - d_m)] (control/robustness.hpp), the delay over the valves'
// range T/2 + [0, delay_max] + rise/2, and the family's modes.
AxisUncertainty axis_uncertainty(const model::Scenario& scenario, const model::HinfRobustnessParams& box, int axis);

struct SixAxisDesign {
  double delay_s = 0.0;
  std::array<AxisDesign, 6> axes;
  bool checked_robustness = false;          // control.hinf.robustness was given
  std::array<AxisUncertainty, 6> boxes;     // when checked
  std::array<RobustnessResult, 6> robustness;
  std::array<LoopMu, 6> mu;                 // when checked
  bool ok() const;      // every axis synthesised and stable on the true plant
  bool robust() const;  // and, where checked, stable at every grid point
};

SixAxisDesign design_six_axes(const model::Scenario& scenario);

}  // namespace chaser::control
