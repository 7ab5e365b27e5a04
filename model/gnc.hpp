#pragma once
// Parameters of the flight software: navigation, guidance, control, modulation and management.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace chaser::model {

struct NavigationParams {
  // Kalman filter on the discrete HCW model; process noise as acceleration spectral density.
  double position_process_noise_mps2 = 1e-5;   // [m/s^2] 1-sigma unmodelled acceleration per period
  // Attitude complementary filter: star-tracker correction gain per period and gyro-bias gain.
  double attitude_gain = 0.1;                  // [-] fraction of the attitude error removed per period
  double gyro_bias_gain = 0.001;               // [1/s] gyro-bias estimate gain
  // The target attitude estimator's torque noise (flight/target_estimator.hpp): what its torque-free
  // model leaves out, gravity gradient first (ENVISAT: up to ~0.4 N m), as white noise.
  double target_torque_noise_Nm = 1.0;         // [N m / sqrt(s)]
};

// The synchronised final approach (flight/sync_guidance.hpp): the chaser starts at a hold
// point of the tumbling target's frame, its rotation synchronised with the target's, moves to the
// capture point (target.body.capture_point_target_m) and holds there. Needs target.body and
// sensors.target_pose (the reference follows the flight software's estimate of the target).
// The steps of COMRADE's synchronisation phase before the transfer (COMRADE 2018, sec. 2.1;
// flight/sync_approach.hpp): from the line's end (guidance.capture_distance_m on its axis) a
// spherical fly-around to the target's angular-momentum axis, an approach along that axis, the
// synchronisation of the rotation (the attitude turns from pointing at the target to turning with
// it, the position from the inertial axis to the target frame), then the transfer below.
struct SyncApproachParams {
  double fly_around_start_s = 1200.0;         // [s] leaves the line's end (>= guidance.approach_duration_s)
  double fly_around_duration_s = 600.0;       // [s] along the sphere of the line's end distance
  double axis_distance_m = 12.0;              // [m] where the approach along the axis ends
  double axis_approach_duration_s = 400.0;    // [s]
  double rotation_sync_duration_s = 200.0;    // [s]
  double rotation_sync_end_s() const {
    return fly_around_start_s + fly_around_duration_s + axis_approach_duration_s + rotation_sync_duration_s;
  }
};

struct SyncGuidanceParams {
  // With `approach` the chaser flies the steps before (start_target_m is then the axis point where
  // the rotation's synchronisation starts, fixed by the flight software from its estimate).
  std::optional<SyncApproachParams> approach;
  Vec3 start_target_m = Vec3::Zero();           // [m] the hold point it starts from, target axes
  double transfer_start_s = 0.0;                // [s] when it leaves it
  double transfer_duration_s = 300.0;           // [s] rest to rest to the capture point
  Quat q_target_from_body = Quat::Identity();   // the chaser's attitude in the target's frame
};

// Forced straight-line approach along approach_axis_lvlh towards the target (Fonod 2015, Fig. 5).
struct GuidanceParams {
  Vec3 approach_axis_lvlh = Vec3(0.0, -1.0, 0.0);  // unit vector from target towards the chaser start
  double start_distance_m = 20.0;       // [m]
  double capture_distance_m = 1.0;      // [m] capture point on the approach axis
  double approach_duration_s = 1150.0;  // [s] time to go from start to capture point
  double blend_time_s = 60.0;           // [s] acceleration and deceleration phases of the profile
  double corridor_half_angle_rad = 0.17453292519943295;  // [rad] approach cone about the axis
  double corridor_min_distance_m = 0.5; // [m] inside this range the cone is not checked
  double capture_position_tol_m = 0.1;  // [m] capture: position error at the end
  double capture_speed_tol_mps = 0.01;  // [m/s] capture: relative speed at the end
  double capture_attitude_tol_rad = 0.0349;  // [rad] capture: attitude error at the end
  std::optional<SyncGuidanceParams> synchronised;  // present: the synchronised approach replaces the line
};

// The H-infinity mixed-sensitivity design of one family of loops, translation or rotation
// (control/axis_design.hpp; COMRADE 2018, sec. 5; docs/control.md, "Six-axis design"): after the
// computed-torque precompensation each axis is a double integrator in commanded acceleration, with
// W_S = (s / M + omega_B) / (s + omega_B A) on the error and W_KS = error_scale / authority on the
// commanded acceleration.
struct HinfLoopWeights {
  double bandwidth_radps = 0.05;     // [rad/s] omega_B: |S| crosses 1 near it
  double peak_sensitivity = 2.0;     // [-] M: |S| below M gamma at high frequency
  double low_frequency_gain = 1e-3;  // [-] A: |S| below A gamma at low frequency (A > 0: SB10AD's A3)
  double error_scale = 1.0;          // [m | rad] an error this large may ask for the axis's authority
  // [-] An input disturbance of this fraction of the authority weighs like an error of error_scale
  // (W_d = input_disturbance authority / error_scale; 0: none, the plain S/KS problem). Without it
  // the design cancels the double integrator's (shifted) poles and flies a slow drift under any
  // constant acceleration error (docs/control.md, "Input disturbance").
  double input_disturbance = 0.003;
};

// A mode the rigid design model leaves out (propellant slosh, a flexible appendage), as the loops
// see it: a zero-pole pair at omega_z and omega_z / sqrt(1 - modal_fraction) (control/robustness.hpp).
struct UncertainModeSpec {
  std::string name;
  double frequency_lo_radps = 0.1;  // [rad/s] omega_z range: the mode's frequency with the body held
  double frequency_hi_radps = 0.1;  // [rad/s]
  double modal_fraction = 0.0;      // [-] the share of the mass (inertia) in the mode, [0, 1)
  double damping = 0.005;           // [-] the mode's damping ratio, [0, 1)
};

// The box `chaser control design` checks each loop over, point by point (docs/control.md,
// "Robustness"); the delay range comes from the thrusters (T/2 + [0, delay_max] + rise/2).
struct HinfRobustnessParams {
  double mass_uncertainty = 0.05;    // [-] relative error of the mass and inertia the precompensation uses
  double thrust_uncertainty = 0.01;  // [-] relative error of the thrust level
  int points_per_range = 5;          // [-] grid points along each range, [2, 20]
  std::vector<UncertainModeSpec> translation_modes;  // seen by x, y, z
  std::vector<UncertainModeSpec> rotation_modes;     // seen by rx, ry, rz
};

struct HinfDesignParams {
  HinfLoopWeights translation;                          // the relative position, per body axis
  HinfLoopWeights rotation{0.3, 2.0, 1e-3, 0.05};       // the attitude, per body axis
  std::optional<HinfRobustnessParams> robustness;       // absent: no robustness check
};

// The norm the thrust allocation minimises among the on-times that realise the wrench (
// flight/norm_allocation.hpp): p = 1 least propellant (Fonod 2015's TMF), p = 2 least energy,
// p = infinity least peak on-time (COMRADE 2018, sec. 6.3, names the three).
enum class AllocationNorm : std::uint8_t { kOne, kTwo, kInfinity };

// The feedback law the flight software flies: the LQR pair of Fonod 2015 (flight/position_control,
// flight/attitude_control), or the six H-infinity loops of control.hinf behind the computed-torque
// precompensation (flight/hinf_control.hpp; COMRADE 2018, sec. 5).
enum class ControlLaw : std::uint8_t { kLqr, kHinf };

struct ControlParams {
  // LQR weights: state cost diag(q_pos * I, q_vel * I), input cost r_force * I (position), and the
  // same shape for attitude. Gains are computed from these and the scenario's mass and inertia.
  // For a double integrator of mass m these give w_n^2 = sqrt(q_pos / r) / m and
  // (2 zeta w_n)^2 = q_vel / (r m^2) + 2 w_n^2 (docs/gnc.md). Defaults, for m = 2500 kg and
  // I = diag(2000, 2500, 3000) kg m^2: position w_n = 0.04 rad/s, zeta = 0.9 (time constant 28 s);
  // attitude w_n = 0.135-0.166 rad/s, zeta = 0.87-0.94 (time constant 6.4-8.5 s).
  double position_q_pos = 16.0;        // [1/m^2]
  double position_q_vel = 12000.0;     // [s^2/m^2]
  double position_r_force = 1.0;       // [1/N^2]
  double attitude_q_angle = 3000.0;    // [1/rad^2]
  double attitude_q_rate = 170000.0;   // [s^2/rad^2]
  double attitude_r_torque = 1.0;      // [1/(N m)^2]
  // Thruster modulation unit: impulse accumulated per axis before a pulse is released. About one
  // minimum impulse bit (22 N x 5 ms = 0.11 N s), so a released pulse is long enough to fire.
  double tmu_force_threshold_Ns = 0.1;     // [N s]
  double tmu_torque_threshold_Nms = 0.1;   // [N m s]
  // Accumulator clamp (anti-windup) in periods of full per-axis thruster authority.
  double tmu_windup_periods = 3.0;         // [-]
  AllocationNorm allocation_norm = AllocationNorm::kOne;
  ControlLaw law = ControlLaw::kLqr;
  // The mass the position loop and the navigation's prediction divide by: false, the scenario's
  // chaser.mass_kg throughout; true, that less the tank gauge's propellant used, every period
  // (flight/position_control.hpp, with_mass; docs/gnc.md, "The mass on board"); the gauge's noise
  // then at most 1e-3 of the mass (io/scenario_validation.cpp).
  bool mass_from_gauge = false;
  // The H-infinity design (`chaser control design`); absent: the scenario has none.
  std::optional<HinfDesignParams> hinf;
};

}  // namespace chaser::model
