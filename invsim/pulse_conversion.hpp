#pragma once
// Conversion of the inverse model's continuous acceleration into a pulse of a fixed-thrust
// (relay) thruster group held over one step (Zhou 2018, App. B eqs. 1-4).
//
//   eq. 1: u_max dtau = u* tau                  (impulse equivalence over the step tau)
//   eq. 3: dtau = 0 if dtau <= k_t tau           (time sensitivity)
//   eq. 4: |u|  = 0 if |u| <= k_f u_max, else u_max (acceleration sensitivity: relay amplitude)
// Since dtau / tau = |u| / u_max, eqs. 3 and 4 test the same ratio; the system's sensitivity is
// k = min(k_t, k_f) (App. B), i.e. the pulse is suppressed only when both tests suppress it. The
// test is |u| / dead_zone_u_max > k, which is that ratio whenever dead_zone_u_max = u_max.
// Above the dead zone the pulse carries exactly the commanded impulse, up to the saturation
// dtau = tau (the group open for the whole step).

namespace chaser::invsim {

struct PulseParams {
  double u_max_mps2;        // [m/s^2] acceleration of the thruster group when open (eq. 1)
  double step_s;            // [s] tau
  double time_sensitivity;  // k_t [-]
  double accel_sensitivity; // k_f [-]
  // [m/s^2] the u_max the dead zone of eqs. 3-4 is measured against: the pilot's sense of a small
  // correction. u_max_mps2 itself, except when the inverse model knows a group lost a thruster
  // (the paper reading's inverse_model: faulted): then the nominal group's, since the sensitivity
  // is to the offset from the desired state (App. B), which a fault does not change, while eq. 1
  // opens the weakened group longer for the same impulse.
  double dead_zone_u_max_mps2;
};

struct Pulse {
  int direction;      // +1, -1, or 0 (no pulse)
  double on_time_s;   // [s] dtau in [0, tau]
};

// The pulse for one body axis given the commanded acceleration u (signed).
Pulse convert_to_pulse(const PulseParams& p, double u_mps2);

// The same opening before the saturation: dtau = |u| tau / u_max may exceed tau (eq. 1 as
// printed; invsim/carried_opening.hpp keeps the group open into the next steps).
Pulse convert_to_opening(const PulseParams& p, double u_mps2);

}  // namespace chaser::invsim
