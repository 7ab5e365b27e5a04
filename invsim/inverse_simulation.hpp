#pragma once
// One inverse simulation of the manually controlled approach (Zhou 2018, Fig. 3): the inner loop
// (the inverse model replacing the astronaut) and the outer loop (forward simulation of the truth
// with the automatic attitude controller), at the IS step tau.
//
// Per step k (t = k tau):
//   1. measurement: the truth state, perfect, or under the paper reading with the sensor noise it
//      sets (the paper's measurement link, invsim/measurement_link.hpp);
//   2. inverse model: u_hill = weighted LS over the receding horizon to x_c(t + n tau)
//      (invsim/inverse_step.hpp), u_body = C_hb u_hill (eq. 8);
//   3. pulse conversion per body axis (App. B) with the nominal group acceleration (the pilot does
//      not know which thruster failed), or under the paper reading with inverse_model: faulted the
//      group's remaining one; a pulse opens its group at t for dtau;
//   4. forward simulation over [t, t + tau] in attitude periods dT: the phase-plane controller
//      (App. A) opens the attitude couples at the start of each period; every piece between valve
//      edges is integrated with its constant wrench (invsim/relative_dynamics.hpp);
//   5. figures: pulses, line of sight against the field of view, attitude against its limits,
//      propellant.
#include <array>
#include <vector>

#include "core/types.hpp"
#include "model/invsim.hpp"

namespace chaser::invsim {

// Pulses of one body axis: index 0 for the positive direction, 1 for the negative.
struct AxisPulses {
  std::array<int, 2> count{0, 0};          // pulses under the reading (invsim/paper_reading.hpp)
  std::array<double, 2> on_time_s{0.0, 0.0};  // [s] summed opening time of the group
};

struct InvSimResult {
  std::array<AxisPulses, 3> pulses;   // x, y, z body axes (Table 4 columns)
  int total_pulses = 0;               // P
  double k_p = 0.0;                   // operational amount P / P_thrust (eq. 22)
  double peak_azimuth_rad = 0.0;      // max |theta_az| over the run
  double peak_elevation_rad = 0.0;    // max |theta_el|
  Vec3 peak_attitude_rad = Vec3::Zero();  // max |phi|, |theta|, |psi|
  bool target_always_in_view = true;  // |az|, |el| within limits at every attitude period
  bool attitude_within_limits = true; // |phi|, |theta|, |psi| within the limit throughout
  bool docked = false;                // final position inside the docking envelope
  Vec3 final_r_hill_m = Vec3::Zero(); // [m]
  Vec3 final_v_hill_mps = Vec3::Zero();  // [m/s]
  double propellant_kg = 0.0;         // [kg] translation + attitude
  double attitude_propellant_kg = 0.0;  // [kg]
  Vec3 attitude_on_time_s = Vec3::Zero();  // [s] summed opening time of the attitude couples per body axis
  bool diverged = false;              // non-finite state or the chaser beyond 10 km: run stopped
};

// One row per IS step, for plots (written only when asked for).
struct InvSimSample {
  double t_s;                      // [s]
  Vec3 r_hill_m;                   // [m]
  Vec3 v_hill_mps;                 // [m/s]
  Vec3 r_desired_hill_m;           // [m]
  Vec3 euler_rad;                  // [rad] roll, pitch, yaw
  double azimuth_rad;              // [rad]
  double elevation_rad;            // [rad]
  Vec3 u_body_mps2;                // [m/s^2] inverse model output
  std::array<int, 3> pulse_direction;  // -1, 0, +1 per axis: the step's command (what is counted)
  std::array<int, 3> pulse_count;      // pulses counted in the step per axis under the reading
};

InvSimResult run_inverse_simulation(const model::InvSimParams& params,
                                    const model::InvSimFaultSet& faults,
                                    std::vector<InvSimSample>* history = nullptr);

// What a run takes from its thrusters and their faults: every group's wrench (force, torque, summed
// thrust) and acceleration that the run derives from them before its first step, in a fixed order.
// Two runs whose parameters differ only in their thrusters fly alike when their signatures are
// equal: moving both thrusters of a healthy, balanced pair, say, changes no wrench. Equal is ==, so
// a zero of either sign matches (a zero torque adds nothing to a nonzero one; the shipped studies'
// files are byte-identical either way). `chaser fmea` flies each such flight once (invsim/fmea.hpp).
std::vector<double> thruster_signature(const model::InvSimParams& params, const model::InvSimFaultSet& faults);

}  // namespace chaser::invsim
