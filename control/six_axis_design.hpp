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
//  - weights: control.hinf.translation for x, y, z, control.hinf.rotation for rx, ry, rz.
// Design-time code: allocates.
#include <array>

#include "control/axis_design.hpp"
#include "model/scenario.hpp"

namespace chaser::control {

inline constexpr std::array<const char*, 6> kAxisNames = {"x", "y", "z", "rx", "ry", "rz"};

// The loop delay of the header: T / 2 + delay_max / 2 + rise_time / 2.
double loop_delay_s(const model::Scenario& scenario);

// The six specs (x, y, z, rx, ry, rz). Throws std::invalid_argument if the scenario has no
// control.hinf section or an axis has no authority (the set cannot push along it).
std::array<AxisDesignSpec, 6> six_axis_specs(const model::Scenario& scenario);

struct SixAxisDesign {
  double delay_s = 0.0;
  std::array<AxisDesign, 6> axes;
  bool ok() const;  // every axis synthesised and stable on the true plant
};

SixAxisDesign design_six_axes(const model::Scenario& scenario);

}  // namespace chaser::control
