#pragma once
// Event resolution for the isolation decision of eq. 42 (Fonod 2015, Remark 2): cases 1 and 3
// (stuck open, leak) burn more propellant than commanded, cases 2 and 4 (blocked, thrust loss)
// burn less or as much. The chaser measures the propellant used; flight software predicts it from
// its own commands, sum_i T_on,i T mdot_i with the nominal mass flow mdot_i = F_i / (Isp g0).
//
// From the first period with the alarm raised, the excess
//   e(k) = (m_meas(k) - m_meas(k_a)) - sum_{k_a < j <= k} expected_increment(j)
// is compared with the threshold
//   threshold(k) = k_sigma sqrt(2) sigma_m + relative_margin * expected_since_alarm(k) + absolute_margin,
// sqrt(2) sigma_m being the noise of a difference of two measurements with independent errors of
// std sigma_m, and the margins covering the model error of the prediction (thrust, Isp, rise).
// over_consumption = e(k) > threshold(k); it latches once true (the decision of eq. 42 must not
// flicker while eq. 45 counts), and it stays false before the alarm. False-alarm bound with the
// margins not needed (exact model): a noise-only excess is Gaussian with std sqrt(2) sigma_m, so
// P(e(k) > threshold) <= Q(k_sigma) per period (2.9e-7 for k_sigma = 5), and over K periods after
// the alarm at most K Q(k_sigma) (union bound).
#include <array>
#include <string>
#include <vector>

#include "flight/fdi/watched_set.hpp"

namespace chaser::flight::fdi {

struct EventResolutionParams {
  double sensor_sigma_kg = 1e-3;    // [kg] 1-sigma noise of one propellant-used measurement
  double k_sigma = 5.0;             // [-] multiple of the difference noise sqrt(2) sigma_m
  double relative_margin = 0.05;    // [-] relative model error of the predicted consumption
  double absolute_margin_kg = 0.0;  // [kg] further fixed margin
};

struct EventResolutionState {
  bool active = false;                 // the alarm has been seen
  double reference_kg = 0.0;           // [kg] measured propellant used at the first alarm period
  double expected_since_alarm_kg = 0.0;  // [kg] predicted consumption since then
  bool over_consumption = false;       // latched decision
};

// Problems with the parameters (empty when valid), each naming the field.
std::vector<std::string> validate(const EventResolutionParams& params);

// Nominal mass flow of each watched thruster, F_i / (Isp g0) [kg/s].
std::array<double, kMaxWatchedThrusters> nominal_mass_flow_kgps(const model::ThrusterSetParams& thrusters,
                                                             const WatchedSet& watched, double isp_s);

// Predicted propellant used over one period: sum_i T_on,i T mdot_i [kg].
double expected_propellant_increment_kg(const WatchedTon& ton,
                                        const std::array<double, kMaxWatchedThrusters>& mass_flow_kgps,
                                        double period_s);

// One period. measured_used_kg: the sensor reading (cumulative) at this period; expected_increment_kg:
// the predicted consumption between the previous reading and this one, read only while the
// resolution is active (state.active: from the period after the first alarm), so a caller may skip
// computing it before. Returns over_consumption.
bool step_event_resolution(const EventResolutionParams& params, EventResolutionState& state,
                           double measured_used_kg, double expected_increment_kg, bool alarm);

}  // namespace chaser::flight::fdi
