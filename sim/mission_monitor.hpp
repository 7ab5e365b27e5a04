#pragma once
// The run's figures of merit, judged on the truth: corridor, target in view, attitude error against
// the guidance reference, and capture at the end of the run.
#include <limits>

#include "core/types.hpp"
#include "model/scenario.hpp"

namespace chaser::sim {

struct MissionFigures {
  int corridor_violation_periods = 0;      // periods with the chaser outside the approach cone
  double first_corridor_violation_s = -1;  // [s] -1 when the corridor was kept
  double max_corridor_angle_rad = 0;       // [rad] largest angle from the approach axis (outside min range)
  int out_of_view_periods = 0;             // periods with the target outside the LIDAR field of view
  double max_line_of_sight_angle_rad = 0;  // [rad] largest angle between body +x and the target
  double max_attitude_error_rad = 0;       // [rad] against the target-pointing reference
  double max_position_error_m = 0;         // [m] against the guidance reference
  double final_position_error_m = 0;       // [m] from the capture point at the end
  double final_speed_mps = 0;              // [m/s] relative speed at the end
  double final_attitude_error_rad = 0;     // [rad] at the end
  double final_rate_error_radps = 0;       // [rad/s] body rate against the reference's, at the end
  // The chaser's clearance from the target's keep-out volume (target.body.keep_out less
  // chaser.keep_out_radius_m; COMRADE 2018 Table 4), with the volume given.
  double min_target_clearance_m = std::numeric_limits<double>::infinity();  // [m]
  double min_target_clearance_at_s = -1;   // [s]
  // The same, split at the rotation's synchronisation (Table 4: 3 m before it, 0.5 m after;
  // synchronised_from_s).
  double min_clearance_unsynchronised_m = std::numeric_limits<double>::infinity();  // [m]
  double min_clearance_unsynchronised_at_s = -1;  // [s]
  double min_clearance_synchronised_m = std::numeric_limits<double>::infinity();    // [m]
  double min_clearance_synchronised_at_s = -1;    // [s]
  bool capture_achieved = false;
  bool diverged = false;                   // a state became non-finite or left the bounds
  double diverged_at_s = -1;               // [s]
};

// Truth and reference at one period start, as the monitor needs them.
struct MonitorSample {
  double t_s;
  Vec3 r_lvlh_m, v_lvlh_mps;
  Quat q_inertial_from_body;
  Vec3 r_ref_lvlh_m, v_ref_lvlh_mps;
  Quat q_ref_inertial_from_body;
  Quat q_inertial_from_lvlh;
  Quat q_inertial_from_target = Quat::Identity();  // the truth; used with a keep-out volume only
  Vec3 omega_body_radps = Vec3::Zero();            // [rad/s] the truth's body rate (final judgement)
  Vec3 omega_ref_body_radps = Vec3::Zero();        // [rad/s] the reference's
  bool synchronised = false;  // the phase flown judges the synchronisation (sim/run_phases.hpp)
};

// From when the chaser's rotation is synchronised with the target's (COMRADE 2018 Table 4): on the
// line from the start if the target turns with LVLH (its given rate within kSynchronisedRate_radps
// of LVLH's: ASSIST), else never; from the start in the synchronised final approach; from the end of
// the rotation's synchronisation with guidance.synchronised.approach.
inline constexpr double kSynchronisedRate_radps = 1e-7;  // [rad/s] 0.02 deg an hour
double synchronised_from_s(const model::Scenario& scenario);

// Whether the scenario's target has a keep-out volume to check (the simulation then supplies
// MonitorSample::q_inertial_from_target every period).
bool checks_keep_out(const model::Scenario& scenario);

// The chaser's clearance from the target's keep-out volume at a sample [m] (negative inside): the
// distance of its CoM from the volume less chaser.keep_out_radius_m. Needs checks_keep_out.
double keep_out_clearance_m(const model::Scenario& scenario, const MonitorSample& sample);

// Divergence bound: far outside anything a 20 m approach can reach under control.
inline constexpr double kDivergedDistance_m = 1e4;

// Updates the running figures; returns false when the run has diverged and must stop.
bool monitor_period(const model::Scenario& scenario, const MonitorSample& sample, MissionFigures& figures);

// Final-state figures and the capture verdict.
void monitor_final(const model::Scenario& scenario, const MonitorSample& sample, MissionFigures& figures);

}  // namespace chaser::sim
