#pragma once
// Parameters of the inverse simulation of a manually controlled rendezvous (Zhou 2018).
//
// Frame: the paper's Hill frame ("Zhou" in core/rotation.hpp): x along the target's orbital
// velocity, z towards the Earth, y completing the right-handed triad (opposite the orbit normal).
// The chaser body axes coincide with the Hill axes at zero attitude; body positions are measured
// from the centre of mass. Loaded by io/invsim_loader.hpp from scenarios/manual_rvd.yaml; every
// value is validated there and never changes during a run.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace chaser::model {

// Which loop a thruster serves (Zhou 2018, Fig. 5).
enum class InvSimThrusterRole { kEngine, kAttitude, kTranslation };

// One thruster. Table 1's switching logic follows from (role, axis, sign):
//  - translation: fires when the pilot commands `sign` along body `axis` (d1: x, +1);
//  - attitude: fires with polarity `sign` * (attitude command) on body `axis`, its force along
//    +direction for polarity +1 and along -direction for -1 (a: x, +1; a~: x, -1);
//  - engine: the orbit manoeuvre engine, never fired during the approach.
struct InvSimThruster {
  std::string name;                                   // "d1", "e1~", ...
  InvSimThrusterRole role = InvSimThrusterRole::kTranslation;
  int axis = 0;                                       // body axis 0, 1, 2 (x, y, z)
  int sign = 1;                                       // +1 or -1, see above
  double thrust_N = 0.0;                              // [N] fixed amplitude when open
  Vec3 position_body_m = Vec3::Zero();                // [m] from the centre of mass
  Vec3 direction_body = Vec3::UnitX();                // unit force direction (positive polarity)
};

// Desired trajectory: constant approach velocity along x until damping_start_s, then the
// exponential "index damping" towards dock_x_m (Zhou 2018, section 3.2); y and z are held at 0.
// The approach velocity follows from continuity of x and x' at damping_start_s.
struct InvSimTrajectoryParams {
  double dock_x_m = 10.0;                 // [m] x of the chaser's centre of mass at docking
  double damping_start_s = 800.0;         // [s] start of the exponential phase
  double damping_time_constant_s = 100.0; // [s] time constant of the exponential phase
};

// MPC-structured inverse model (Zhou 2018, section 2.2, eqs. 17-21).
struct InvSimInverseParams {
  int horizon_steps = 3;                           // receding horizon n (steps of step_s)
  std::array<double, 6> state_weights{};           // diagonal of Q: [1/m^2] x3, [s^2/m^2] x3
};

// How App. B's pulses are read and counted (docs/invsim.md, "Readings of App. B"; invsim/paper_reading.hpp).
//  - smooth (Chaser's default): a pulse is a step in which a group fired (the pilot's stick pulse);
//  - paper: a pulse is one valve opening of at most pulse_width_s: a step's opening dtau counts
//    ceil(dtau / pulse_width_s) pulses, so P measures the commanded opening time (the paper's
//    "operational impulse amounts"), and Q of eq. 20 is the reading's own, both calibrated on the
//    nominal case only (python/invsim_study/calibrate_invsim.py).
enum class InvSimReading { kSmooth, kPaper };

// Which spacecraft the inverse model inverts under the paper reading: the nominal one (the pilot
// flies as if nothing had failed; feedback alone compensates) or the faulted one (inverse
// simulation of the faulted spacecraft: the inputs it needs to fly the desired trajectory, each
// group with the thrust it has left, so a group that lost one of its two thrusters opens twice as
// long for the same impulse).
enum class InvSimInverseModel { kNominal, kFaulted };

// Noise of the measurement link (Zhou 2018, Fig. 3) under the paper reading: the sensor's range
// and line-of-sight angles (eqs. 12-15) with white Gaussian errors drawn once per IS step. The
// sequence depends on the seed only, so every fault mode of a study meets the same noise (one
// recorded approach, flown with each fault).
struct InvSimMeasurementNoise {
  double range_sigma_m = 0.0;    // [m] 1-sigma error of the measured range
  double angle_sigma_rad = 0.0;  // [rad] 1-sigma error of the measured azimuth and elevation
  std::uint64_t seed = 1;        // the noise sequence (the first one with draws > 1)
  // Noise sequences flown per fault mode, seeds seed, seed + 1, ... (invsim/noise_draws.hpp): a
  // study row is then the mean workload over the draws and the worst deviation.
  std::uint64_t draws = 1;
  bool enabled() const { return range_sigma_m > 0.0 || angle_sigma_rad > 0.0; }
};

// What happens to an opening longer than the IS step under the paper reading
// (invsim/carried_opening.hpp): capped at the step (the rest of the impulse is lost), or carried
// into the next steps until the commanded impulse is given.
enum class InvSimOpening { kCapped, kCarried };

struct InvSimPaperReadingParams {
  double pulse_width_s = 0.1;                          // [s] one counted valve opening at most
  std::array<double, 6> state_weights{1, 1, 1, 1, 1, 1};  // diagonal of Q under this reading
  InvSimInverseModel inverse_model = InvSimInverseModel::kNominal;
  InvSimOpening opening = InvSimOpening::kCapped;
  InvSimMeasurementNoise measurement_noise;            // none unless set
  // [s] the designed lateral trajectory: y and z return from their initial state to 0 with this
  // critically damped time constant (invsim/desired_trajectory.hpp); 0 holds them at 0 from the
  // start, as the smooth reading does.
  double lateral_time_constant_s = 0.0;
  // [m/s^2] with a lateral return, the designed trajectory first brakes each lateral axis's
  // initial velocity at this constant deceleration, then returns from where it stopped; 0: no
  // brake (the return starts at once from the initial state). Needs lateral_time_constant_s > 0.
  double lateral_brake_mps2 = 0.0;
};

// Pulse conversion (Zhou 2018, App. B eqs. 1-4) and the operational amount (eq. 22).
struct InvSimPulseParams {
  InvSimReading reading = InvSimReading::kSmooth;
  double time_sensitivity = 0.35;          // k_t [-]
  double acceleration_sensitivity = 0.35;  // k_f [-]
  double basic_pulse_amount = 3000.0;      // P_thrust [-]
  InvSimPaperReadingParams paper;          // used with reading kPaper only
};

// Phase-plane attitude control (Zhou 2018, App. A), the same for the three axes except a0, which
// follows from the attitude thrusters and the inertia.
struct InvSimPhasePlaneParams {
  double period_s = 0.25;             // [s] sampling period DeltaT of the attitude loop
  double d_rad = 0.0;                 // [rad] opening-line offset d (angle precision)
  double delta_rad = 0.0;             // [rad] hysteresis delta between opening and closing lines
  double rate_border_s_radps = 0.0;   // [rad/s] large rate border theta'_s
  double rate_border_t_radps = 0.0;   // [rad/s] small rate border theta'_t
  double btc1 = 0.0;                  // [-] opening time / DeltaT in the closing area R0
  double btc2 = 0.0;                  // [-] ... in the step-control areas R12, R13
  double btc3 = 1.0;                  // [-] ... in the full-opening areas R11
};

// Relative-navigation sensor (Zhou 2018, eqs. 12-16) and the mission limits (Table 3).
struct InvSimSensorParams {
  Vec3 position_body_m = Vec3::Zero();  // [m] p_s, measurement centre from the centre of mass
  double azimuth_limit_rad = 0.0;       // [rad] |theta_az|max
  double elevation_limit_rad = 0.0;     // [rad] |theta_el|max
  double attitude_limit_rad = 0.0;      // [rad] |phi|, |theta|, |psi| max
};

struct InvSimParams {
  std::string name;
  // Target orbit: circular (eq. 1 with omega_tar' = 0).
  double mu_m3ps2 = 3.986004418e14;     // [m^3/s^2] Earth
  double body_radius_m = 6.378137e6;    // [m]
  double altitude_m = 400e3;            // [m]
  // Chaser.
  double mass_kg = 8000.0;              // [kg] held constant (the paper's model has no mass loss)
  Mat3 inertia_kgm2 = Mat3::Identity(); // [kg m^2] principal axes = body axes
  double isp_s = 290.0;                 // [s] for the propellant figure only
  // Initial relative state (Hill) and attitude (Euler 3-2-1, Hill to body).
  Vec3 r0_hill_m = Vec3::Zero();        // [m]
  Vec3 v0_hill_mps = Vec3::Zero();      // [m/s]
  Vec3 euler0_rad = Vec3::Zero();       // [rad] roll phi, pitch theta, yaw psi
  Vec3 omega0_rel_body_radps = Vec3::Zero();  // [rad/s] body rate relative to the Hill frame
  // Run.
  double step_s = 1.0;                  // [s] inverse-simulation step tau
  double duration_s = 1300.0;           // [s]
  Vec3 envelope_m = Vec3(4.0, 2.42, 2.42);  // [m] docking box (full sizes) centred on (dock_x, 0, 0)
  InvSimTrajectoryParams trajectory;
  InvSimInverseParams inverse;
  InvSimPulseParams pulses;
  InvSimPhasePlaneParams attitude;
  InvSimSensorParams sensor;
  std::vector<InvSimThruster> thrusters;

  double radius_m() const { return body_radius_m + altitude_m; }
};

// Thrusters shut down from the start (Zhou 2018, section 3.1): bit i = thrusters[i] failed.
struct InvSimFaultSet {
  std::uint64_t failed_mask = 0;
  bool failed(std::size_t i) const { return ((failed_mask >> i) & 1U) != 0; }
};

inline constexpr std::size_t kMaxInvSimThrusters = 64;

}  // namespace chaser::model
