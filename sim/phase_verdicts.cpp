#include "sim/phase_verdicts.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/rotation.hpp"
#include "sim/run.hpp"
#include "sim/run_phases.hpp"

namespace chaser::sim {

void add_phase_period(PhaseFigures& f, const MonitorSample& s, double clearance_m) {
  ++f.periods;
  if (clearance_m < f.min_clearance_m) f.min_clearance_m = clearance_m;
  f.final_position_error_m = (s.r_lvlh_m - s.r_ref_lvlh_m).norm();
  f.final_speed_error_mps = (s.v_lvlh_mps - s.v_ref_lvlh_mps).norm();
  f.final_attitude_error_rad = attitude_error_body(s.q_ref_inertial_from_body, s.q_inertial_from_body).norm();
  const Vec3 omega_ref_in_body = s.q_inertial_from_body.conjugate() * (s.q_ref_inertial_from_body * s.omega_ref_body_radps);
  f.final_rate_error_radps = (s.omega_body_radps - omega_ref_in_body).norm();
}

bool PhaseVerdict::met() const {
  return std::ranges::all_of(requirements, [](const Requirement& r) { return r.met; });
}

bool mission_met(const std::vector<PhaseVerdict>& verdicts) {
  return std::ranges::all_of(verdicts, [](const PhaseVerdict& v) { return v.met(); });
}

std::int64_t phases_not_met_bits(const std::vector<PhaseVerdict>& verdicts) {
  std::int64_t bits = 0;
  for (const PhaseVerdict& v : verdicts) {
    if (v.met()) continue;
    const auto at = std::ranges::find_if(kMissionPhases, [&](const char* name) { return v.phase == name; });
    bits |= std::int64_t{1} << std::distance(kMissionPhases.begin(), at);
  }
  return bits;
}

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

Requirement at_most(const char* name, double value, double limit) { return {name, value, limit, value <= limit}; }
Requirement at_least(const char* name, double value, double limit) { return {name, value, limit, value >= limit}; }
Requirement holds(const char* name, bool met) { return {.name = name, .met = met}; }

double largest(const std::array<double, model::kArmJoints>& v) { return *std::ranges::max_element(v); }

// The requirements of the phase `name` beyond the clearance (the header's list).
void add_phase_requirements(const model::Scenario& s, const std::string& name, const PhaseFigures& f,
                            const RunResult& r, std::vector<Requirement>& out) {
  const double repeated_peak_Nm = s.chaser.arm ? s.chaser.arm->torque_repeated_peak_Nm : 0.0;
  if (name == "capture_point_hold") {
    out.push_back(at_most("position_error_m", f.final_position_error_m, s.guidance.capture_position_tol_m));
    out.push_back(at_most("speed_error_mps", f.final_speed_error_mps, s.guidance.capture_speed_tol_mps));
    out.push_back(at_most("attitude_error_deg", kRadToDeg * f.final_attitude_error_rad,
                          kRadToDeg * s.guidance.capture_attitude_tol_rad));
    out.push_back(at_most("rate_error_deg_s", kRadToDeg * f.final_rate_error_radps, kTable1RateDegps));
  } else if (name == "reach") {
    out.push_back(holds("gripper_table2", gripper_meets_table2(r.reach)));
    out.push_back(at_most("peak_joint_torque_Nm", largest(r.reach.peak_joint_torque_Nm), repeated_peak_Nm));
  } else if (name == "capture") {
    out.push_back(holds("captured", std::string(r.reach.grasp.outcome) == "captured"));
    if (s.capture && s.capture->berthing) {  // the probe's: docked, the contact within its bound
      out.push_back(holds("hard_docked", std::isfinite(r.reach.berthing.hard_dock_s)));
      out.push_back(at_most("peak_contact_force_N", r.reach.berthing.peak_contact_N, r.reach.berthing.contact_force_limit_N));
    } else {
      out.push_back(holds("grasp_table2", grasp_meets_table2(r.reach.grasp)));
    }
  } else if (name == "rigidisation") {
    out.push_back(holds("brakes_engaged", std::isfinite(r.reach.rigidise.brakes_s)));
    out.push_back(at_most("peak_joint_torque_Nm", largest(r.reach.rigidise.peak_torque_Nm), repeated_peak_Nm));
  } else if (name == "stabilisation") {
    out.push_back(at_most("final_rate_deg_s", r.reach.stabilise.final_rate_target_degps.norm(), model::kStabilisedRateDegps));
    out.push_back(at_most("peak_brake_load_Nm", peak_brake_load_Nm(r.reach), repeated_peak_Nm));
  } else if (name == "escape_retreat" && s.capture && s.capture->escape) {
    out.push_back(holds("escape_requirements", escape_meets_requirements(r.escape, s)));
  }
}

}  // namespace

std::vector<PhaseVerdict> phase_verdicts(const model::Scenario& s, const PhaseSequenceParams& params,
                                         const RunResult& r) {
  std::vector<PhaseRequirements> requirements;  // by phase index, as the run attaches them
  for (const PlannedPhase& p : planned_phases(s)) requirements.push_back(p.requirements);
  for (const ConditionalPhase& p : conditional_phases(s)) requirements.push_back(p.requirements);
  std::vector<PhaseVerdict> out;
  for (const FlownPhase& flown : r.phases) {
    const int i = phase_index(params, flown.name);
    if (i < 0 || static_cast<std::size_t>(i) >= r.phase_figures.size()) continue;
    const PhaseFigures& f = r.phase_figures[static_cast<std::size_t>(i)];
    PhaseVerdict v{.phase = flown.name, .start_s = flown.start_s, .end_s = flown.end_s, .requirements = {}};
    if (checks_keep_out(s) && f.periods > 0)
      v.requirements.push_back(at_least("clearance_m", f.min_clearance_m,
                                        requirements[static_cast<std::size_t>(i)].synchronised ? 0.5 : 3.0));
    if (f.periods > 0) add_phase_requirements(s, flown.name, f, r, v.requirements);
    out.push_back(std::move(v));
  }
  return out;
}

}  // namespace chaser::sim
