#pragma once
// The H-infinity rigidisation's loops (COMRADE 2018 Table 7's H-infinity column; capture.rigidise.law:
// hinf): one S/KS design per joint on its angle. Behind the law's torque tau = H* u (H* the
// free-floating composite's joint inertia at the held angles, flight/arm/free_floating_inertia.hpp)
// each joint is the double integrator q_j'' = u_j of control/axis_design.hpp, in rad and rad/s^2.
//
// Authority: the drive's repeated peak over the joint's own inertia, M / H*_jj: the acceleration
// the drive gives the joint alone. Delay: half the joint loop's period (the hold) plus the drive's
// torque loop, 1 / its bandwidth.
#include <array>

#include "control/axis_design.hpp"
#include "model/arm.hpp"
#include "model/gnc.hpp"

namespace chaser::control {

// Joint j's spec, named "joint1" ... "joint7". Throws std::invalid_argument for an inertia or a
// limit that is not positive and finite.
std::array<AxisDesignSpec, model::kArmJoints> joint_specs(const model::HinfLoopWeights& weights, double torque_limit_Nm,
                                                          const std::array<double, model::kArmJoints>& inertia_kgm2,
                                                          double delay_s);

}  // namespace chaser::control
