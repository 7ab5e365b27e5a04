// The campaign section: dispersions, fault population, onset and horizon of a Monte Carlo campaign
// (model/campaign.hpp, docs/campaigns.md).
#include <cmath>

#include <fmt/format.h>

#include "io/scenario_sections.hpp"

namespace chaser::io {

namespace {

// A [min, max] pair of keys: min <= max, judged only when both were read cleanly.
void check_ordered(MapReader& r, std::string_view min_key, double min, std::string_view max_key, double max) {
  Diagnostics& d = r.diagnostics();
  const std::string min_path = r.path_of(min_key), max_path = r.path_of(max_key);
  if (!d.clean(min_path) || !d.clean(max_path) || min <= max) return;
  d.add(max_path, fmt::format("must be >= {} = {} (got {})", min_path, format_number(min), format_number(max)));
}

}  // namespace

void read_campaign(MapReader& r, model::CampaignParams& out) {
  r.count("seed", out.seed);
  r.number("onset_s", Range::right_open(0.0, kMaxCampaignRunS), out.onset_s);
  r.number("horizon_after_onset_s", Range::left_open(0.0, kMaxCampaignRunS), out.horizon_after_onset_s);
  double onset_max_s = 0.0;  // checked against onset_s and the run's end in validate_campaign
  if (r.has("onset_max_s") && r.number("onset_max_s", Range::right_open(0.0, kMaxCampaignRunS), onset_max_s))
    out.onset_max_s = onset_max_s;
  // That they fly at the start is checked in validate_campaign.
  if (r.has("fault_thrusters")) read_thruster_names(r, "fault_thrusters", out.fault_thrusters);
  // Below 1 a truncated draw keeps mass and moments positive: (1 - 3 sigma) > 0.
  r.number("mass_3sigma_rel", Range::right_open(0.0, 1.0), out.mass_3sigma_rel);
  r.number("inertia_3sigma_rel", Range::right_open(0.0, 1.0), out.inertia_3sigma_rel);
  r.number("com_3sigma_m", Range::non_negative(), out.com_3sigma_m);
  if (r.has("target_spin_rate_3sigma_rel"))  // checked against target.body in validate_campaign
    r.number("target_spin_rate_3sigma_rel", Range::right_open(0.0, 1.0), out.target_spin_rate_3sigma_rel);
  if (r.has("target_spin_axis_3sigma_deg"))
    r.angle_deg("target_spin_axis_3sigma_deg", Range::closed(0.0, 90.0), out.target_spin_axis_3sigma_rad);
  if (r.has("initial_position_3sigma_m"))
    r.number("initial_position_3sigma_m", Range::closed(0.0, 100.0), out.initial_position_3sigma_m);
  if (r.has("initial_velocity_3sigma_mps"))
    r.number("initial_velocity_3sigma_mps", Range::closed(0.0, 1.0), out.initial_velocity_3sigma_mps);
  r.number("leak_size_min", Range::left_open(0.0, 1.0), out.leak_size_min);
  r.number("leak_size_max", Range::left_open(0.0, 1.0), out.leak_size_max);
  r.number("leak_slope_per_s", Range::positive(), out.leak_slope_per_s);
  r.number("loss_size_min", Range::left_open(0.0, 1.0), out.loss_size_min);
  r.number("loss_size_max", Range::left_open(0.0, 1.0), out.loss_size_max);
  r.number("threshold_margin", Range::positive(), out.threshold_margin);
  std::uint64_t runs = 0;
  if (r.count("runs_per_case", runs)) {
    if (runs == 0)
      r.diagnostics().add(r.path_of("runs_per_case"), "must be a whole number >= 1 (got 0)");
    else
      out.runs_per_case = runs;
  }
  check_ordered(r, "leak_size_min", out.leak_size_min, "leak_size_max", out.leak_size_max);
  check_ordered(r, "loss_size_min", out.loss_size_min, "loss_size_max", out.loss_size_max);
}

// A campaign run flies onset_s + horizon_after_onset_s: a whole number of control periods, and
// short enough that the per-second GLR record of a run stays small.
void validate_campaign(const model::Scenario& s, Diagnostics& d) {
  // The spin dispersion turns a rigid-body target's initial rate.
  if (!s.target.body && (s.campaign.target_spin_rate_3sigma_rel > 0.0 || s.campaign.target_spin_axis_3sigma_rad > 0.0))
    d.add(s.campaign.target_spin_rate_3sigma_rel > 0.0 ? "campaign.target_spin_rate_3sigma_rel"
                                                       : "campaign.target_spin_axis_3sigma_deg",
          "needs target.body (a tumbling target); remove it or set it to 0");
  // A fault is drawn among thrusters that fly when it strikes.
  const model::ThrusterMask active = model::initial_active_set(s.thrusters);
  if (d.clean("campaign.fault_thrusters") && d.clean("thrusters.list") && (s.campaign.fault_thrusters & ~active) != 0) {
    for (int i = 0; i < model::kMaxThrusters; ++i)
      if ((s.campaign.fault_thrusters >> i) & 1U && !((active >> i) & 1U)) {
        d.add("campaign.fault_thrusters", fmt::format("{} is not in the starting active set (thrusters.list, "
                                                      "standby_groups)", model::thruster_name(i)));
        break;
      }
  }
  const char* path = "campaign.horizon_after_onset_s";
  if (!d.clean("control_period_s") || !d.clean("campaign.onset_s") || !d.clean(path)) return;
  const double end_s = s.campaign.onset_s + s.campaign.horizon_after_onset_s;
  if (s.campaign.onset_max_s && d.clean("campaign.onset_max_s") &&
      (*s.campaign.onset_max_s < s.campaign.onset_s || *s.campaign.onset_max_s >= end_s))
    d.add("campaign.onset_max_s", fmt::format("must be in [campaign.onset_s = {}, onset_s + horizon_after_onset_s = {}) "
                                              "(got {})", format_number(s.campaign.onset_s), format_number(end_s),
                                              format_number(*s.campaign.onset_max_s)));
  const double run_s = s.campaign.onset_s + s.campaign.horizon_after_onset_s;
  const double periods = run_s / s.control_period_s;
  if (run_s > kMaxCampaignRunS)
    d.add(path, fmt::format("campaign.onset_s + horizon_after_onset_s must be <= {} (got {})",
                            format_number(kMaxCampaignRunS), format_number(run_s)));
  else if (std::abs(periods - std::round(periods)) > 1e-6)
    d.add(path, fmt::format("campaign.onset_s + horizon_after_onset_s = {} must be a whole multiple of "
                            "control_period_s = {}", format_number(run_s), format_number(s.control_period_s)));
}

}  // namespace chaser::io
