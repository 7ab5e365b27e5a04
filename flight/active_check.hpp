#pragma once
// Active checks of dormant thrusters (docs/fdi.md, "Active checks of dormant thrusters").
//
// A thruster the manoeuvre does not command cannot be diagnosed from its effects: a stuck-closed or
// weakened thruster waits, unseen, until it is needed. The flight software therefore keeps, per
// active thruster, the time of its last informative pulse (a commanded on-time of at least
// informative_on_time_s, or the time it joined the active set):
//
//   stale_i(t) = t - verified_i,   i in the active mask.
//
// When the stalest exceeds max_unverified_s, and the estimated range to the target is at least
// keep_quiet_range_m (and at most arm_range_m: checks kept for the last approach, before the phase
// that needs every thruster), the next period's allocation gives that one thruster the floor
// pulse_s / T >= informative_on_time_s / T on its on-time (allocate_thrusters_floored): the others
// cancel its force and torque, so the commanded wrench is unchanged and the check costs only
// propellant. The FDI sees the pulse
// through the ordinary on-time command; a thruster that does not deliver it leaves a deficit.
// One thruster at a time; checking resets its clock, so the stale ones take turns, stalest first.
//
// A pulse verifies only what it shows. When the deficit detector holds a material deficit on a
// thruster with a gain above recheck_gain (below its alarm threshold: the evidence so far is
// suggestive, not conclusive), that thruster is unverified whatever it fired, and stalest of all:
// it is checked again in the next period the window allows, and each check adds its evidence until
// the detector either alarms or lets the suspicion go. One check of a short pulse reads a 45 % loss
// at about the threshold; without the recheck the second look waited max_unverified_s.
#include <array>
#include <limits>
#include <string>
#include <vector>

#include "model/scenario.hpp"
#include "model/thrusters.hpp"

namespace chaser::flight {

struct ActiveCheckParams {
  bool enabled = false;
  double max_unverified_s = 25.0;   // [s] longest time without an informative pulse before a check
  double pulse_fraction = 0.05;     // [-] pulse_s / T: a check's floor on the on-time
  double informative_fraction = 0.05;  // [-] informative_on_time_s / T, at most pulse_fraction
  double keep_quiet_range_m = 2.0;  // [m] no check closer to the target than this (estimated range)
  double arm_range_m = std::numeric_limits<double>::infinity();  // [m] and none farther than this
  // [-] the deficit detector's material gain from which its suspect is rechecked at once
  // (recheck_fraction x detection_threshold; the threshold itself: never)
  double recheck_gain = std::numeric_limits<double>::infinity();
};

ActiveCheckParams make_active_check_params(const model::Scenario& scenario);

// Every problem of the parameters (empty: valid).
std::vector<std::string> validate(const ActiveCheckParams& params);

struct ActiveCheckState {
  model::ThrusterMask active = 0;                       // the set the clocks below belong to
  std::array<double, model::kMaxThrusters> verified_s{};  // [s] last informative pulse or joining
  int next = model::kNoThruster;                        // thruster to check in the next period
};

struct ActiveCheckInput {
  double t_s = 0;                  // [s] this period
  double range_m = 0;              // [m] estimated range to the target
  model::ThrusterMask active = 0;  // the active set after this period's recovery
  int suspect = model::kNoThruster;  // the FDI's suspect above recheck_gain (flight/fdir.hpp thruster_to_check_again)
  bool fdi_listening = true;          // false: the FDI has found its fault (or is disarmed); no check
};

// After the period's command `ton` (by thruster index) is final: records informative pulses and
// returns (and keeps in state.next) the thruster whose check the next period's allocation should
// fire, or kNoThruster. Disabled, it does nothing and returns kNoThruster.
int step_active_check(const ActiveCheckParams& params, ActiveCheckState& state, const ActiveCheckInput& in,
                      const model::ThrusterOnTimes& ton);

}  // namespace chaser::flight
