#pragma once
// The stabilisation's H-infinity loops (COMRADE 2018, sec. 6.1.4; capture.stabilise.law: hinf):
// one S/KS design per inertial axis on the composite's angular impulse Phi = integral of H dt (H the
// inertial angular momentum). For the braked composite, a rigid body, dH/dt = T exactly (T the
// couple in inertial axes), so behind the reference's couple dH_ref/dt each axis is the double
// integrator Phi'' = T of control/axis_design.hpp, in N m and N m s^2, whatever the composite's
// inertia: the inertia enters only the momentum the flight software estimates, H = R J w, a gain
// error on the loop's measurement that the robustness grid spans (composite_uncertainty).
//
// Authority: the thrusters' pure couple about the weakest body axis (a pure couple about an
// inertial axis turns in the body as the composite tumbles). Delay: the loop's, as the
// synchronisation's (control/six_axis_design.hpp).
#include <array>

#include "control/axis_design.hpp"
#include "control/robustness.hpp"
#include "model/scenario.hpp"

namespace chaser::control {

inline constexpr std::array<const char*, 3> kCompositeAxisNames = {"Hx", "Hy", "Hz"};

// The three specs from capture.stabilise.hinf. Throws std::invalid_argument without a
// capture.stabilise section, or when the active thrusters cannot turn the chaser about a body axis.
std::array<AxisDesignSpec, 3> composite_specs(const model::Scenario& scenario);

// The grid a composite loop is checked over: a measurement gain in [1 - e, 1 + e] (e the inertia's
// relative error: the momentum estimated with J off by e, and the thrust level's uncertainty
// control.hinf.robustness.thrust_uncertainty where the scenario has it) and the loop's delay over
// the valves' range; no flexible modes (the braked arm is rigid in the plant).
AxisUncertainty composite_uncertainty(const model::Scenario& scenario, double inertia_relative_error);

}  // namespace chaser::control
