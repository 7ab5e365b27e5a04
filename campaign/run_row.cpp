#include "campaign/run_row.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "campaign/table_cells.hpp"
#include "core/constants.hpp"
#include "sim/phase_verdicts.hpp"
#include "sim/run_phases.hpp"

namespace chaser::campaign {

namespace {

// Largest per-second GLR maximum over the whole seconds that end at or before the onset.
double glr_before(const sim::RunResult& result, int scheme, double onset_s) {
  const std::size_t seconds = std::isnan(onset_s) ? result.glr_max_per_s.size()
                                                  : std::min(result.glr_max_per_s.size(),
                                                             static_cast<std::size_t>(std::floor(onset_s)));
  double best = 0.0;
  for (std::size_t s = 0; s < seconds; ++s) best = std::max(best, static_cast<double>(result.glr_max_per_s[s][scheme]));
  return best;
}

// alarm_s / isolated_s are run times (-1: none); with a fault, the paper's t_d and t_i from the onset.
SchemeOutcome judge(double alarm_s, double isolated_s, int isolated, int fault_thruster, double onset_s,
                    double glr_max) {
  const bool fault = fault_thruster != model::kNoThruster;
  const bool alarm = alarm_s >= 0.0;
  const bool alarm_after = fault && alarm && alarm_s >= onset_s;
  SchemeOutcome o{};
  o.false_alarm = alarm && !alarm_after;
  o.missed = fault && !alarm_after;
  o.detection_s = alarm_after ? alarm_s - onset_s : kNaN;
  o.isolation_s = alarm_after && isolated_s >= onset_s ? isolated_s - onset_s : kNaN;
  o.isolated = isolated;
  o.wrong_isolation = o.isolated != model::kNoThruster && o.isolated != fault_thruster;
  o.glr_max_before_onset = glr_max;
  return o;
}

SchemeOutcome judge_scheme(const sim::SchemeResult& s, const RunRecord& r, double glr_max) {
  return judge(s.alarm_s, s.isolated_s, s.isolated_thruster, r.fault_thruster, r.onset_s, glr_max);
}

// The FDIR as a whole (sim::FdirResult): the first alarm of any scheme; the confirmation the
// recovery acted on, or with recovery off the first confirmation of any scheme.
SchemeOutcome judge_fdir(const sim::FdirResult& f, const RunRecord& r) {
  const bool recovered = f.recovery_s >= 0.0;
  return judge(f.detection_s, recovered ? f.recovery_s : f.isolation_s,
               recovered ? f.recovered_thruster : f.isolated_thruster, r.fault_thruster, r.onset_s,
               std::max(r.schemes[flight::kPositionScheme].glr_max_before_onset,
                        r.schemes[flight::kAttitudeScheme].glr_max_before_onset));
}

ReachFigures reach_figures(const sim::ReachResult& reach) {
  if (!reach.flown) {
    const Vec3 none = Vec3::Constant(kNaN);
    return {none, none, none, none, none, none, none, none, kNaN, kNaN, false, kNaN, false, kNaN, none, kNaN, kNaN, false};
  }
  const sim::StabiliseResult& st = reach.stabilise;
  const plant::GripperTruth& g = reach.final_gripper;
  const double deg = 1.0 / kDegToRad;
  return {g.r_m,
          g.v_mps,
          g.attitude_rad * deg,
          g.omega_radps * deg,
          reach.max_gripper_error_m,
          reach.max_gripper_velocity_mps,
          reach.max_gripper_attitude_rad * deg,
          reach.max_gripper_rate_radps * deg,
          *std::max_element(reach.peak_joint_torque_Nm.begin(), reach.peak_joint_torque_Nm.end()),
          reach.min_tool_clearance_m,
          sim::gripper_meets_table2(reach),
          reach.grasp.captured_s,
          sim::grasp_meets_table2(reach.grasp),
          st.flown ? st.below_goal_s - st.start_s : kNaN,
          st.flown ? st.final_rate_target_degps : Vec3::Constant(kNaN).eval(),
          st.flown ? sim::peak_brake_load_Nm(reach) : kNaN,
          st.flown ? st.propellant_kg : kNaN,
          sim::stabilise_meets_table3(reach)};
}

RunRecord base_record(const RunSetup& setup) {
  RunRecord r;
  r.run = setup.run;
  r.seed = setup.seed;
  r.fault_case = setup.fault_case;
  r.fault_thruster = setup.fault ? setup.fault->thruster : model::kNoThruster;
  r.fault_size = fault_size(setup.fault);
  r.onset_s = setup.fault ? setup.fault->onset_s : kNaN;
  r.chaser = setup.truth.chaser;
  return r;
}

bool finite_figures(const sim::RunResult& result) {
  return std::isfinite(result.propellant_used_kg) && std::isfinite(result.figures.final_position_error_m) &&
         std::isfinite(result.figures.final_attitude_error_rad);
}

void number(std::string& out, double v) { append_number(out, v); }
void flag(std::string& out, bool v) { out += v ? '1' : '0'; }
void integer(std::string& out, std::int64_t v) { fmt::format_to(std::back_inserter(out), "{}", v); }
// A thruster in a numeric table: n of its name Tn, 0 for none (docs/style.md, "Naming and layout").
void thruster_number(std::string& out, int index) { integer(out, model::thruster_number(index)); }

// A scheme's outcome by its slot, -1 the FDIR's as a whole.
const SchemeOutcome& outcome(const RunRecord& r, int s) { return s < 0 ? r.fdir : r.schemes[static_cast<std::size_t>(s)]; }

// One scheme's columns, in the spec's order: six, and for a diagnosis scheme (not the FDIR as a
// whole) the largest GLR statistic before the onset.
void scheme_columns(std::vector<RunColumn>& columns, const std::string& name, int s) {
  columns.push_back({name + "_detection_s", ColumnKind::kNumber,
                     [](const RunRecord& r, int i, std::string& o) { number(o, outcome(r, i).detection_s); }, s});
  columns.push_back({name + "_isolation_s", ColumnKind::kNumber,
                     [](const RunRecord& r, int i, std::string& o) { number(o, outcome(r, i).isolation_s); }, s});
  columns.push_back({name + "_isolated", ColumnKind::kInteger,
                     [](const RunRecord& r, int i, std::string& o) { thruster_number(o, outcome(r, i).isolated); }, s});
  columns.push_back({name + "_false_alarm", ColumnKind::kFlag,
                     [](const RunRecord& r, int i, std::string& o) { flag(o, outcome(r, i).false_alarm); }, s});
  columns.push_back({name + "_missed", ColumnKind::kFlag,
                     [](const RunRecord& r, int i, std::string& o) { flag(o, outcome(r, i).missed); }, s});
  columns.push_back({name + "_wrong_isolation", ColumnKind::kFlag,
                     [](const RunRecord& r, int i, std::string& o) { flag(o, outcome(r, i).wrong_isolation); }, s});
  if (s >= 0)
    columns.push_back({name + "_glr_max_before_onset", ColumnKind::kNumber,
                       [](const RunRecord& r, int i, std::string& o) { number(o, outcome(r, i).glr_max_before_onset); }, s});
}

// The reach's columns (ReachFigures): per figure and axis, then the torque, the clearance and the
// verdict; then the grasp's two.
void reach_columns(std::vector<RunColumn>& columns) {
  // index: (4 over_hold + figure) * 3 + axis, in ReachFigures' order.
  static constexpr std::array<Vec3 ReachFigures::*, 8> kFields = {
      &ReachFigures::final_error_m,    &ReachFigures::final_velocity_mps, &ReachFigures::final_attitude_deg,
      &ReachFigures::final_rate_deg_s, &ReachFigures::max_error_m,        &ReachFigures::max_velocity_mps,
      &ReachFigures::max_attitude_deg, &ReachFigures::max_rate_deg_s};
  for (int k = 0; k < 8; ++k)
    for (int axis = 0; axis < 3; ++axis)
      columns.push_back({reach_column_name(k >= 4, k % 4, axis), ColumnKind::kNumber,
                         [](const RunRecord& r, int i, std::string& o) {
                           number(o, (r.reach.*kFields[static_cast<std::size_t>(i / 3)])(i % 3));
                         },
                         k * 3 + axis});
  columns.insert(columns.end(), {
      {"reach_peak_joint_torque_Nm", ColumnKind::kNumber, [](const RunRecord& r, int, std::string& o) { number(o, r.reach.peak_joint_torque_Nm); }},
      {"reach_min_tool_clearance_m", ColumnKind::kNumber, [](const RunRecord& r, int, std::string& o) { number(o, r.reach.min_tool_clearance_m); }},
      {"reach_table2_met", ColumnKind::kFlag, [](const RunRecord& r, int, std::string& o) { flag(o, r.reach.table2_met); }},
      {"grasp_captured_s", ColumnKind::kNumber, [](const RunRecord& r, int, std::string& o) { number(o, r.reach.grasp_captured_s); }},
      {"grasp_table2_met", ColumnKind::kFlag, [](const RunRecord& r, int, std::string& o) { flag(o, r.reach.grasp_table2_met); }},
      {"stabilise_below_goal_s", ColumnKind::kNumber, [](const RunRecord& r, int, std::string& o) { number(o, r.reach.stabilise_below_goal_s); }},
  });
  for (int axis = 0; axis < 3; ++axis)
    columns.push_back({fmt::format("stabilise_final_rate_{}_deg_s", "xyz"[axis]), ColumnKind::kNumber,
                       [](const RunRecord& r, int i, std::string& o) { number(o, r.reach.stabilise_final_rate_deg_s(i)); }, axis});
  columns.insert(columns.end(), {
      {"stabilise_peak_load_Nm", ColumnKind::kNumber, [](const RunRecord& r, int, std::string& o) { number(o, r.reach.stabilise_peak_load_Nm); }},
      {"stabilise_propellant_kg", ColumnKind::kNumber, [](const RunRecord& r, int, std::string& o) { number(o, r.reach.stabilise_propellant_kg); }},
      {"stabilise_table3_met", ColumnKind::kFlag, [](const RunRecord& r, int, std::string& o) { flag(o, r.reach.stabilise_table3_met); }},
      {"mission_met", ColumnKind::kFlag, [](const RunRecord& r, int, std::string& o) { flag(o, r.mission_met); }},
      {"phases_not_met", ColumnKind::kInteger, [](const RunRecord& r, int, std::string& o) { integer(o, r.phases_not_met); }},
  });
}

}  // namespace

std::string_view to_string(RunStatus s) {
  switch (s) {
    case RunStatus::kOk: return "ok";
    case RunStatus::kDiverged: return "diverged";
    case RunStatus::kError: return "error";
  }
  return "error";
}

void append_number(std::string& out, double value) {
  if (std::isnan(value)) {
    out += "nan";
    return;
  }
  fmt::format_to(std::back_inserter(out), "{:.17g}", value);
}

RunRecord make_record(const RunSetup& setup, const sim::RunResult& result, double planned_s) {
  RunRecord r = base_record(setup);
  const double half_period_s = 0.5 * setup.truth.control_period_s;
  const bool short_run = result.simulated_s < planned_s - half_period_s;
  r.status = result.figures.diverged || short_run || !finite_figures(result) ? RunStatus::kDiverged : RunStatus::kOk;
  for (std::size_t i = 0; i < result.fdir.schemes.size(); ++i)
    r.schemes[i] = judge_scheme(result.fdir.schemes[i], r, glr_before(result, static_cast<int>(i), r.onset_s));
  r.fdir = judge_fdir(result.fdir, r);
  r.recovery_s = result.fdir.recovery_s >= 0.0 ? result.fdir.recovery_s : kNaN;
  r.capture = result.figures.capture_achieved;
  r.corridor_kept = result.figures.corridor_violation_periods == 0;
  r.target_in_view = result.figures.out_of_view_periods == 0;
  r.propellant_kg = result.propellant_used_kg;
  r.simulated_s = result.simulated_s;
  const sim::MissionFigures& f = result.figures;
  r.final_position_error_m = f.final_position_error_m;
  r.final_speed_mps = f.final_speed_mps;
  r.final_attitude_error_deg = f.final_attitude_error_rad / kDegToRad;
  r.final_rate_error_deg_s = f.final_rate_error_radps / kDegToRad;
  r.min_clearance_unsynchronised_m = std::isfinite(f.min_clearance_unsynchronised_m) ? f.min_clearance_unsynchronised_m : kNaN;
  r.min_clearance_synchronised_m = std::isfinite(f.min_clearance_synchronised_m) ? f.min_clearance_synchronised_m : kNaN;
  r.supervisor_switches = result.supervisor.switches;
  r.supervisor_thruster = result.supervisor.thruster;
  r.supervisor_fault = result.supervisor.fault;
  r.supervisor_first_switch_s = result.supervisor.log.empty() ? kNaN : result.supervisor.log.front().t_s;
  r.reach = reach_figures(result.reach);
  if (setup.truth.capture && setup.truth.guidance.synchronised) {
    const std::vector<sim::PhaseVerdict> verdicts = sim::phase_verdicts(setup.truth, sim::run_phases(setup.truth), result);
    r.mission_met = sim::mission_met(verdicts);
    r.phases_not_met = sim::phases_not_met_bits(verdicts);
  }
  return r;
}

RunRecord error_record(const RunSetup& setup) {
  RunRecord r = base_record(setup);
  r.status = RunStatus::kError;
  const SchemeOutcome empty{kNaN, kNaN, model::kNoThruster, false, false, false, kNaN};
  r.schemes.fill(empty);
  r.fdir = empty;
  r.recovery_s = kNaN;
  r.propellant_kg = kNaN;
  r.final_position_error_m = r.final_speed_mps = r.final_attitude_error_deg = r.final_rate_error_deg_s = kNaN;
  r.min_clearance_unsynchronised_m = r.min_clearance_synchronised_m = kNaN;
  r.supervisor_first_switch_s = kNaN;
  r.reach = reach_figures(sim::ReachResult{});
  return r;
}

namespace {

// The one table of runs.csv columns (docs/campaigns.md), in file order.
std::vector<RunColumn> build_run_columns(const std::vector<flight::DiagnosisScheme>& schemes) {
  std::vector<RunColumn> columns = {
      {"run", ColumnKind::kInteger, [](const RunRecord& r, int, std::string& o) { integer(o, r.run); }},
      {"seed", ColumnKind::kUnsigned, [](const RunRecord& r, int, std::string& o) { fmt::format_to(std::back_inserter(o), "{}", r.seed); }},
      {"case", ColumnKind::kText, [](const RunRecord& r, int, std::string& o) { o += to_string(r.fault_case); }},
      {"status", ColumnKind::kText, [](const RunRecord& r, int, std::string& o) { o += to_string(r.status); }},
      {"fault_thruster", ColumnKind::kInteger, [](const RunRecord& r, int, std::string& o) { thruster_number(o, r.fault_thruster); }},
      {"fault_size", ColumnKind::kNumber, [](const RunRecord& r, int, std::string& o) { number(o, r.fault_size); }},
      {"onset_s", ColumnKind::kNumber, [](const RunRecord& r, int, std::string& o) { number(o, r.onset_s); }},
      {"mass_kg", ColumnKind::kNumber, [](const RunRecord& r, int, std::string& o) { number(o, r.chaser.mass_kg); }},
      {"inertia_xx_kgm2", ColumnKind::kNumber, [](const RunRecord& r, int, std::string& o) { number(o, r.chaser.inertia_kgm2(0, 0)); }},
      {"inertia_yy_kgm2", ColumnKind::kNumber, [](const RunRecord& r, int, std::string& o) { number(o, r.chaser.inertia_kgm2(1, 1)); }},
      {"inertia_zz_kgm2", ColumnKind::kNumber, [](const RunRecord& r, int, std::string& o) { number(o, r.chaser.inertia_kgm2(2, 2)); }},
      {"com_x_m", ColumnKind::kNumber, [](const RunRecord& r, int, std::string& o) { number(o, r.chaser.com_body_m(0)); }},
      {"com_y_m", ColumnKind::kNumber, [](const RunRecord& r, int, std::string& o) { number(o, r.chaser.com_body_m(1)); }},
      {"com_z_m", ColumnKind::kNumber, [](const RunRecord& r, int, std::string& o) { number(o, r.chaser.com_body_m(2)); }},
  };
  for (std::size_t i = 0; i < schemes.size(); ++i) scheme_columns(columns, schemes[i].name, static_cast<int>(i));
  scheme_columns(columns, "fdir", -1);
  columns.insert(columns.end(), {
      {"recovery_s", ColumnKind::kNumber, [](const RunRecord& r, int, std::string& o) { number(o, r.recovery_s); }},
      {"capture", ColumnKind::kFlag, [](const RunRecord& r, int, std::string& o) { flag(o, r.capture); }},
      {"corridor_kept", ColumnKind::kFlag, [](const RunRecord& r, int, std::string& o) { flag(o, r.corridor_kept); }},
      {"target_in_view", ColumnKind::kFlag, [](const RunRecord& r, int, std::string& o) { flag(o, r.target_in_view); }},
      {"propellant_kg", ColumnKind::kNumber, [](const RunRecord& r, int, std::string& o) { number(o, r.propellant_kg); }},
      {"simulated_s", ColumnKind::kNumber, [](const RunRecord& r, int, std::string& o) { number(o, r.simulated_s); }},
      {"final_position_error_m", ColumnKind::kNumber, [](const RunRecord& r, int, std::string& o) { number(o, r.final_position_error_m); }},
      {"final_speed_mps", ColumnKind::kNumber, [](const RunRecord& r, int, std::string& o) { number(o, r.final_speed_mps); }},
      {"final_attitude_error_deg", ColumnKind::kNumber, [](const RunRecord& r, int, std::string& o) { number(o, r.final_attitude_error_deg); }},
      {"final_rate_error_deg_s", ColumnKind::kNumber, [](const RunRecord& r, int, std::string& o) { number(o, r.final_rate_error_deg_s); }},
      {"min_clearance_unsynchronised_m", ColumnKind::kNumber, [](const RunRecord& r, int, std::string& o) { number(o, r.min_clearance_unsynchronised_m); }},
      {"min_clearance_synchronised_m", ColumnKind::kNumber, [](const RunRecord& r, int, std::string& o) { number(o, r.min_clearance_synchronised_m); }},
      {"supervisor_switches", ColumnKind::kInteger, [](const RunRecord& r, int, std::string& o) { integer(o, r.supervisor_switches); }},
      {"supervisor_thruster", ColumnKind::kInteger, [](const RunRecord& r, int, std::string& o) { thruster_number(o, r.supervisor_thruster); }},
      {"supervisor_fault", ColumnKind::kText, [](const RunRecord& r, int, std::string& o) { o += flight::fdi::to_string(r.supervisor_fault); }},
      {"supervisor_first_switch_s", ColumnKind::kNumber, [](const RunRecord& r, int, std::string& o) { number(o, r.supervisor_first_switch_s); }},
  });
  return columns;
}

}  // namespace

std::string reach_column_name(bool over_hold, int figure, int axis) {
  static constexpr std::array<const char*, 4> kFigures = {"error_{}_m", "velocity_{}_mps", "attitude_{}_deg", "rate_{}_deg_s"};
  return std::string(over_hold ? "reach_max_" : "reach_final_") +
         fmt::format(fmt::runtime(kFigures[static_cast<std::size_t>(figure)]), "xyz"[axis]);
}

RunColumnSet run_column_set(const model::Scenario& scenario) {
  return scenario.capture ? RunColumnSet::kReach : RunColumnSet::kStandard;
}

const std::vector<RunColumn>& run_columns(RunColumnSet set) {
  // The diagnosis schemes' columns come from their table, read once (flight/diagnosis_schemes.hpp).
  static const std::vector<RunColumn> standard = build_run_columns(flight::diagnosis_schemes());
  static const std::vector<RunColumn> with_reach = [] {
    std::vector<RunColumn> columns = standard;
    reach_columns(columns);
    return columns;
  }();
  return set == RunColumnSet::kReach ? with_reach : standard;
}

std::string runs_header(RunColumnSet set) {
  std::string out;
  for (const RunColumn& c : run_columns(set)) {
    if (!out.empty()) out += ',';
    out += c.name;
  }
  return out;
}

std::optional<RunColumnSet> run_column_set_of(std::string_view header) {
  for (const RunColumnSet set : {RunColumnSet::kStandard, RunColumnSet::kReach})
    if (header == runs_header(set)) return set;
  return std::nullopt;
}

std::string format_row(const RunRecord& r, RunColumnSet set) {
  std::string out;
  out.reserve(set == RunColumnSet::kReach ? 1280 : 640);
  bool first = true;
  for (const RunColumn& c : run_columns(set)) {
    if (!first) out += ',';
    first = false;
    c.write(r, c.index, out);
  }
  return out;
}

}  // namespace chaser::campaign
