#pragma once
// COMRADE 2018's combined compliance controller (sec. 6.2.1): one law over the servicer's 13
// degrees of freedom (6 platform + 7 joints) that makes the hub hold its pose relative to the
// target and the tool follow its path, with the closed loop of PD+ tracking control (Paden and
// Panja 1988, the paper's ref. [16]) in the extended task space of flight/arm/task_space.hpp:
//
//   nu_ref = J^-1 x'_ref,   nu_ref' = J^-1 (x''_ref - J'(q, v) nu_ref)        (J nu_ref = x'_ref at all times)
//   tau    = H(q) nu_ref' + C(q, v) nu_ref - J' (K e + D e')                    (J' the transpose)
//
// with e and e' the task's errors (attitudes as the vector part eps of q q_ref^-1), K and D
// diagonal and positive, each attitude's stiffness the same on its three axes, and C the
// factorisation with dH/dt - 2 C skew (flight/arm/coriolis_force.hpp). With s = v - nu_ref
// (so J s = e'), H s' + C s = -J' (K e + D e') and
//   V = s' H s / 2 + U(e),  U = sum k_p |e_p|^2 / 2 + sum 2 k_o (1 - eta) + k_j e_j^2 / 2,
//   dV/dt = -e'' D e' <= 0
// for any positive gains, in continuous time, on the full nonlinear dynamics (no linearisation),
// as the paper states; with J square, LaSalle gives e -> 0. What it leaves out, and the tests
// measure: the sampling (1 kHz here), the platform's force realised by thrusters at a slower
// rate, the joint torques' limits. The gains are chosen from a bandwidth per task on the
// linearised system (the paper's words), compliance_gains below.
//
// tau is the generalized force of servicer_arm.hpp's v: the force on the hub in world axes [N],
// the torque about the hub's CoM in hub axes [N m], the seven joint torques [N m].
#include <string>
#include <vector>

#include "core/types.hpp"
#include "flight/arm/arm_kinematics.hpp"
#include "flight/arm/servicer_arm.hpp"
#include "flight/arm/task_space.hpp"

namespace chaser::flight::arm {

struct ComplianceGains {
  TaskVector stiffness = TaskVector::Zero();  // K: [N/m] positions, [N m] attitudes (per unit eps), [N m/rad] the joint
  TaskVector damping = TaskVector::Zero();    // D: [N s/m], [N m s/rad], [N m s/rad]
};

// The natural frequency wanted of each task and the damping ratio.
struct ComplianceBandwidths {
  double hub_radps = 0.5;
  double tool_radps = 2.0;
  double joint_radps = 1.0;
  double damping_ratio = 1.0;
};

// K = m w^2, D = 2 zeta m w per task, m the task's inertia seen at the configuration given (the
// mean of its block's diagonal in Lambda = (J H^-1 J')^-1, the operational-space inertia): each
// task then behaves, linearised and decoupled, as a mass-spring-damper of that frequency.
ComplianceGains compliance_gains(const ServicerArmParams& params, const ArmKinematics& kinematics,
                                 const ComplianceBandwidths& bandwidths);

// Every problem at once: gains finite and > 0, each attitude's stiffness equal on its axes.
std::vector<std::string> validate(const ComplianceGains& gains);

struct ComplianceOutput {
  ServicerVector generalized_force = ServicerVector::Zero();  // tau
  TaskErrors errors;
  double storage_J = 0.0;  // V = s' H s / 2 + U(e): non-increasing in the law's nominal closed loop
};

ComplianceOutput compliance_control(const ServicerArmParams& params, const ArmKinematics& kinematics,
                                    const JointVector& joint_angles_rad, const ServicerVector& velocity,
                                    const TaskReference& reference, const ComplianceGains& gains);

// U(e) of the law's springs [J].
double compliance_potential(const ComplianceGains& gains, const TaskVector& pose_errors);

}  // namespace chaser::flight::arm
