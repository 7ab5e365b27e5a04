// The fdi section: residual-generator design, detection, isolation and recovery (model/fdi.hpp).
#include <algorithm>

#include <fmt/format.h>

#include "io/scenario_sections.hpp"

namespace chaser::io {

namespace {

// Longest sliding window, in control periods: the on-board ring buffers have this many slots.
constexpr std::uint64_t kMaxFdiWindow = 128;

// A whole number in [lo, hi].
void read_count_in(MapReader& r, std::string_view key, std::uint64_t lo, std::uint64_t hi, int& out) {
  std::uint64_t value = 0;
  if (!r.count(key, value)) return;
  if (value < lo || value > hi) {
    r.diagnostics().add(r.path_of(key), fmt::format("must be a whole number in [{}, {}] (got {})", lo, hi, value));
    return;
  }
  out = static_cast<int>(value);
}

// Six distinct real eigenvalues strictly inside the unit circle (the assigned left eigenvectors
// must be real, and the observer stable: Fonod 2015, below eq. 38).
void read_eigenvalues(MapReader& r, std::array<double, 6>& out) {
  const auto node = r.child("eigenvalues", "a list of 6 numbers");
  if (!node) return;
  const std::string path = r.path_of("eigenvalues");
  Diagnostics& diag = r.diagnostics();
  if (!check_list(*node, path, 6, "a list of 6 numbers, each in (-1, 1)", diag)) return;
  std::array<double, 6> values{};
  bool ok = true;
  for (int i = 0; i < 6; ++i)
    ok &= read_number((*node)[i], join_path(path, std::to_string(i)), Range::open(-1.0, 1.0), diag, values[i]);
  if (!ok) return;
  std::array<double, 6> sorted = values;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
    diag.add(path, "must be 6 distinct values (the eigenstructure assignment needs distinct eigenvalues)");
    return;
  }
  out = values;
}

void read_isolation_method(MapReader& r, model::IsolationMethod& out) {
  r.choice("isolation_method",
           {{"paper", model::IsolationMethod::kPaper},
            {"signature", model::IsolationMethod::kSignature},
            {"deficit", model::IsolationMethod::kDeficit}},
           out);
}

void read_recovery(MapReader& r, model::RecoveryPolicy& out) {
  r.choice("recovery",
           {{"none", model::RecoveryPolicy::kNone},
            {"switch_group", model::RecoveryPolicy::kSwitchGroup},
            {"exclude", model::RecoveryPolicy::kExclude}},
           out);
}

// Window lengths are checked against each other and the control period in validate_scenario.
void read_deficit(MapReader& r, model::DeficitParams& out) {
  r.number("window_before_s", Range::positive(), out.window_before_s);
  r.number("window_after_s", Range::positive(), out.window_after_s);
  r.number("window_max_s", Range::positive(), out.window_max_s);
  r.number("pulse_uncertainty", Range::closed(0.0, 1.0), out.pulse_uncertainty);
  if (r.has("inertia_uncertainty")) r.number("inertia_uncertainty", Range::closed(0.0, 1.0), out.inertia_uncertainty);
  if (r.has("com_uncertainty_m")) r.number("com_uncertainty_m", Range::closed(0.0, 1.0), out.com_uncertainty_m);
  r.number("min_gain", Range::non_negative(), out.min_gain);
  r.number("min_margin", Range::non_negative(), out.min_margin);
  r.boolean("detection", out.detection);
  r.number("detection_window_s", Range::positive(), out.detection_window_s);
  r.number("detection_threshold", Range::positive(), out.detection_threshold);
  r.number("detection_min_constant", Range::closed(0.0, 1.0), out.detection_min_constant);
  r.number("detection_min_proportional", Range::closed(0.0, 1.0), out.detection_min_proportional);
  if (r.has("detection_statistic"))
    r.choice("detection_statistic",
             {{"gain", model::DetectionStatistic::kGain}, {"impulse", model::DetectionStatistic::kImpulse}},
             out.detection_statistic);
  if (r.has("impulse_window_s")) r.number("impulse_window_s", Range::positive(), out.impulse_window_s);
  if (r.has("impulse_baseline_s")) r.number("impulse_baseline_s", Range::positive(), out.impulse_baseline_s);
  if (r.has("impulse_threshold_Nms")) r.number("impulse_threshold_Nms", Range::positive(), out.impulse_threshold_Nms);
}

// The window and baseline against the control period are checked in validate_scenario.
void read_observer_bank(MapReader& r, model::ObserverBankParams& out) {
  if (r.has("enabled")) r.boolean("enabled", out.enabled);
  if (r.has("disturbance_torque_Nm")) r.number("disturbance_torque_Nm", Range::positive(), out.disturbance_torque_Nm);
  if (r.has("gamma_backoff")) r.number("gamma_backoff", Range::left_open(1.0, 10.0), out.gamma_backoff);
  if (r.has("window_s")) r.number("window_s", Range::positive(), out.window_s);
  if (r.has("baseline_s")) r.number("baseline_s", Range::positive(), out.baseline_s);
  if (r.has("threshold_Nm")) r.number("threshold_Nm", Range::positive(), out.threshold_Nm);
  if (r.has("isolation_ratio")) r.number("isolation_ratio", Range::open(0.0, 1.0), out.isolation_ratio);
}

// The thrusters against the active set, the slosh and the recovery policy are checked in validate_scenario.
void read_supervisor(MapReader& r, model::SupervisorParams& out) {
  if (r.has("enabled")) r.boolean("enabled", out.enabled);
  if (r.has("accommodate")) r.boolean("accommodate", out.accommodate);
  if (r.has("thrusters")) read_thruster_names(r, "thrusters", out.thrusters);
  if (r.has("forgetting_s")) r.number("forgetting_s", Range::positive(), out.forgetting_s);
  if (r.has("bias_s")) r.number("bias_s", Range::positive(), out.bias_s);
  if (r.has("settle_s")) r.number("settle_s", Range::non_negative(), out.settle_s);
  if (r.has("dwell_s")) r.number("dwell_s", Range::positive(), out.dwell_s);
  if (r.has("hysteresis")) r.number("hysteresis", Range::non_negative(), out.hysteresis);
  if (r.has("floor_radps")) r.number("floor_radps", Range::non_negative(), out.floor_radps);
}

// The on-times against the valve's minimum on-time, the control period and each other, and
// max_unverified_s against the period, are checked in validate_scenario.
void read_active_check(MapReader& r, model::ActiveCheckParams& out) {
  r.boolean("enabled", out.enabled);
  r.number("max_unverified_s", Range::positive(), out.max_unverified_s);
  r.number("informative_on_time_s", Range::positive(), out.informative_on_time_s);
  r.number("pulse_s", Range::positive(), out.pulse_s);
  r.number("keep_quiet_range_m", Range::non_negative(), out.keep_quiet_range_m);
  if (r.has("arm_range_m")) r.number("arm_range_m", Range::positive(), out.arm_range_m);
  if (r.has("recheck_fraction")) r.number("recheck_fraction", Range::left_open(0.0, 1.0), out.recheck_fraction);
}

void read_rate_check(MapReader& r, model::RateCheckParams& out) {
  if (r.has("enabled")) r.boolean("enabled", out.enabled);
  if (r.has("neighbours")) read_count_in(r, "neighbours", 2, model::kMaxRateCheckNeighbours, out.neighbours);
  if (r.has("threshold")) r.number("threshold", Range::open(0.0, 1.0), out.threshold);
  if (r.has("confirmations")) read_count_in(r, "confirmations", 1, 20, out.confirmations);
  if (r.has("stuck_closed_from")) r.number("stuck_closed_from", Range::open(0.0, 1.0), out.stuck_closed_from);
  if (r.has("max_uncertainty")) r.number("max_uncertainty", Range::positive(), out.max_uncertainty);
}

void read_scheme(MapReader& r, model::FdiSchemeParams& out) {
  r.boolean("enabled", out.enabled);
  read_count_in(r, "residual_dimension", 1, 3, out.residual_dimension);
  r.number("sigma0", Range::positive(), out.sigma0);
}

}  // namespace

// design_delay_max_s against the control period is checked in validate_scenario.
void read_fdi(MapReader& r, model::FdiParams& out) {
  read_eigenvalues(r, out.eigenvalues);
  read_count_in(r, "taylor_order", 1, 8, out.taylor_order);
  r.number("design_delay_max_s", Range::positive(), out.design_delay_max_s);
  read_count_in(r, "glr_window", 2, kMaxFdiWindow, out.glr_window);
  r.number("glr_threshold", Range::positive(), out.glr_threshold);
  read_count_in(r, "isolation_window", 1, kMaxFdiWindow, out.isolation_window);
  read_count_in(r, "confirmation_window", 1, kMaxFdiWindow, out.confirmation_window);
  read_isolation_method(r, out.isolation_method);
  read_count_in(r, "isolation_settle", 0, 10 * kMaxFdiWindow, out.isolation_settle);
  r.boolean("glr_increase_only", out.glr_increase_only);
  read_section(r, "deficit", [&](MapReader& m) { read_deficit(m, out.deficit); });
  if (r.has("observer_bank"))  // optional: model/fdi.hpp's defaults, the bank off
    read_section(r, "observer_bank", [&](MapReader& m) { read_observer_bank(m, out.observer_bank); });
  if (r.has("supervisor"))  // optional: model/fdi.hpp's defaults, off
    read_section(r, "supervisor", [&](MapReader& m) { read_supervisor(m, out.supervisor); });
  r.number("over_consumption_threshold_kg", Range::positive(), out.over_consumption_threshold_kg);
  read_recovery(r, out.recovery);
  r.number("rearm_after_recovery_s", Range::non_negative(), out.rearm_after_recovery_s);
  read_section(r, "active_check", [&](MapReader& m) { read_active_check(m, out.active_check); });
  if (r.has("rate_check"))  // optional: model/fdi.hpp's defaults, off
    read_section(r, "rate_check", [&](MapReader& m) { read_rate_check(m, out.rate_check); });
  read_section(r, "position", [&](MapReader& m) { read_scheme(m, out.position); });
  read_section(r, "attitude", [&](MapReader& m) { read_scheme(m, out.attitude); });
}

}  // namespace chaser::io
