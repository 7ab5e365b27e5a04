#include "sim/summary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "core/constants.hpp"
#include "sim/run_phases.hpp"

namespace chaser::sim {

namespace {

constexpr double kRadToDeg = 1.0 / kDegToRad;

// A thruster at the boundary: its name, or null for none (model/thrusters.hpp).
// A figure that exists (with the keep-out volume) and was reached (a time with no sample stays
// infinite or -1): its value; else null.
nlohmann::json finite_or_null(bool exists, double value) {
  return exists && std::isfinite(value) && value != -1 ? nlohmann::json(value) : nlohmann::json();
}

// The guidance's phases and their times (COMRADE 2018 sec. 2.1 with guidance.synchronised.approach;
// the line and its hold otherwise), each ending where the next starts and the last at duration_s.
nlohmann::json phases_json(const model::Scenario& s) {
  nlohmann::json out = nlohmann::json::array();
  for (const PlannedPhase& p : planned_phases(s)) {
    out.push_back({{"name", p.name}, {"start_s", p.start_s}, {"duration_s", p.duration_s},
                   {"requirements", p.requirements.synchronised ? nlohmann::json::array({"synchronised"})
                                                                : nlohmann::json::array()}});
    if (s.capture) out.back()["arm"] = p.configuration.arm_awake ? "awake" : "stowed";  // the plant's configuration
  }
  return out;
}

// The phases as flown: a run ended early ends its last phase there.
nlohmann::json phases_flown_json(const RunResult& r) {
  nlohmann::json out = nlohmann::json::array();
  for (const FlownPhase& p : r.phases)
    out.push_back({{"name", p.name}, {"start_s", p.start_s}, {"end_s", p.end_s}, {"end_reason", p.end_reason}});
  return out;
}

nlohmann::json thruster_json(int index) {
  return index == model::kNoThruster ? nlohmann::json(nullptr) : nlohmann::json(model::thruster_name(index));
}

nlohmann::json faults_json(const model::Scenario& scenario) {
  nlohmann::json faults = nlohmann::json::array();
  for (const auto& f : scenario.faults) {
    nlohmann::json j{{"thruster", model::thruster_name(f.thruster)},
                     {"kind", std::string(model::to_string(f.kind))},
                     {"onset_s", f.onset_s}};
    if (f.kind == model::FaultKind::kLeak) j["leak_size"] = f.leak_size, j["leak_slope_per_s"] = f.leak_slope_per_s;
    if (f.kind == model::FaultKind::kLoss) j["loss_size"] = f.loss_size;
    faults.push_back(j);
  }
  return faults;
}

// The deficit bank's reading of the fault, null when it made none.
nlohmann::json diagnosis_json(const SchemeResult& r) {
  if (!r.diagnosed_kind) return nullptr;
  return nlohmann::json{{"fault", std::string(model::to_string(*r.diagnosed_kind))},
                        {"size", r.diagnosed_size},
                        {"onset_s", r.estimated_onset_s}};
}

// Times relative to the fault onset where there is a fault (detection and isolation delays, the
// paper's t_d and t_i), absolute otherwise (a false alarm's time).
nlohmann::json scheme_json(const SchemeResult& r, double onset_s) {
  const auto since = [&](double t) { return t < 0 ? nlohmann::json(nullptr) : nlohmann::json(t - onset_s); };
  return nlohmann::json{{"enabled", r.enabled},
                        {"alarm_s", r.alarm_s < 0 ? nlohmann::json(nullptr) : nlohmann::json(r.alarm_s)},
                        {"detection_time_s", since(r.alarm_s)},
                        {"isolation_time_s", since(r.isolated_s)},
                        {"isolated_thruster", thruster_json(r.isolated_thruster)},
                        {"diagnosis", diagnosis_json(r)}};
}

double first_onset_s(const model::Scenario& scenario) {
  return scenario.faults.empty() ? 0.0 : scenario.faults.front().onset_s;
}

// One scheme within one watch, absolute times (a watch after a recovery has no single onset).
nlohmann::json watch_scheme_json(const SchemeResult& r) {
  const auto at = [](double t) { return t < 0 ? nlohmann::json(nullptr) : nlohmann::json(t); };
  return nlohmann::json{{"enabled", r.enabled},
                        {"alarm_s", at(r.alarm_s)},
                        {"isolation_s", at(r.isolated_s)},
                        {"isolated_thruster", thruster_json(r.isolated_thruster)},
                        {"diagnosis", diagnosis_json(r)}};
}

// Every watch of the FDI in order (it watches again after a recovery), absolute times: the first
// from the start of the run, each later one from its re-arming after a recovery.
nlohmann::json diagnoses_json(const FdirResult& f) {
  nlohmann::json list = nlohmann::json::array();
  const std::vector<flight::DiagnosisScheme>& schemes = flight::diagnosis_schemes();
  for (const FdirResult& e : f.episodes) {
    nlohmann::json watch{
        {"detection_s", e.detection_s < 0 ? nlohmann::json(nullptr) : nlohmann::json(e.detection_s)},
        {"isolation_s", e.isolation_s < 0 ? nlohmann::json(nullptr) : nlohmann::json(e.isolation_s)},
        {"isolated_thruster", thruster_json(e.isolated_thruster)},
        {"recovery_s", e.recovery_s < 0 ? nlohmann::json(nullptr) : nlohmann::json(e.recovery_s)},
    };
    for (std::size_t i = 0; i < schemes.size(); ++i) watch[schemes[i].name + "_scheme"] = watch_scheme_json(e.schemes[i]);
    list.push_back(std::move(watch));
  }
  return list;
}

nlohmann::json fdir_json(const model::Scenario& scenario, const FdirResult& f) {
  const double onset = first_onset_s(scenario);
  nlohmann::json out{
      {"glr_threshold", scenario.fdi.glr_threshold},                   // position and attitude schemes
      // deficit scheme: on its gain or, with the impulse statistic, in N m s
      {"deficit_threshold", scenario.fdi.deficit.detection_statistic == model::DetectionStatistic::kImpulse
                                ? scenario.fdi.deficit.impulse_threshold_Nms
                                : scenario.fdi.deficit.detection_threshold},
      {"detection_time_s", f.detection_s < 0 ? nlohmann::json(nullptr) : nlohmann::json(f.detection_s - onset)},
      {"isolation_time_s", f.isolation_s < 0 ? nlohmann::json(nullptr) : nlohmann::json(f.isolation_s - onset)},
      {"isolated_thruster", thruster_json(f.isolated_thruster)},
      {"recovery_s", f.recovery_s < 0 ? nlohmann::json(nullptr) : nlohmann::json(f.recovery_s)},
      {"recovered_thruster",
       thruster_json(f.recovered_thruster)},
      {"diagnoses", diagnoses_json(f)},
      {"stood_down_s", f.stood_down_s < 0 ? nlohmann::json(nullptr) : nlohmann::json(f.stood_down_s)},
  };
  const std::vector<flight::DiagnosisScheme>& schemes = flight::diagnosis_schemes();
  for (std::size_t i = 0; i < schemes.size(); ++i) out[schemes[i].name + "_scheme"] = scheme_json(f.schemes[i], onset);
  return out;
}

// The supervisor's switches (null without it): how many, the last mode, and the first ones in order.
nlohmann::json supervisor_json(const SupervisorResult& s) {
  if (!s.enabled) return nullptr;
  nlohmann::json log = nlohmann::json::array();
  for (const flight::fdi::SupervisorSwitch& w : s.log) log.push_back({{"t_s", w.t_s}, {"mode", w.mode}});
  return {{"mode_switches", s.switches},
          {"thruster", thruster_json(s.thruster)},
          {"fault", flight::fdi::to_string(s.fault)},
          {"switches", std::move(log)}};
}

// faulty_thruster: the truth's index, model::kNoThruster when the run has no fault.
std::string scheme_text(const std::string& name, const SchemeResult& r, double onset_s, int faulty_thruster) {
  const bool has_fault = faulty_thruster != model::kNoThruster;
  if (!r.enabled) return fmt::format("  {} scheme: off\n", name);
  if (r.alarm_s < 0) return fmt::format("  {} scheme: no alarm\n", name);
  std::string out = has_fault ? fmt::format("  {} scheme: alarm {:.1f} s after onset", name, r.alarm_s - onset_s)
                              : fmt::format("  {} scheme: FALSE ALARM at {:.1f} s", name, r.alarm_s);
  // Without a fault there is no onset: the isolation's own time, as the false alarm's.
  if (r.isolated_thruster != model::kNoThruster && !has_fault)
    out += fmt::format(", {} isolated at {:.1f} s", model::thruster_name(r.isolated_thruster), r.isolated_s);
  else if (r.isolated_thruster != model::kNoThruster)
    out += fmt::format(", {} isolated {:.1f} s after onset{}", model::thruster_name(r.isolated_thruster),
                       r.isolated_s - onset_s,
                       r.isolated_thruster != faulty_thruster
                           ? fmt::format(" (WRONG: the fault is on {})", model::thruster_name(faulty_thruster))
                           : "");
  if (r.diagnosed_kind)
    out += fmt::format(" [{} {:.2f}, onset {:.1f} s]", model::to_string(*r.diagnosed_kind), r.diagnosed_size,
                       r.estimated_onset_s);
  return out + "\n";
}

nlohmann::json vec_json(const Vec3& v, double scale = 1.0) { return {scale * v.x(), scale * v.y(), scale * v.z()}; }

// The grasp against COMRADE Table 2 at the jaws' closure (sim/reach_result.hpp).
nlohmann::json grasp_json(const GraspResult& g) {
  const plant::GripperTruth& a = g.at_closure;
  const auto judged = [&](const nlohmann::json& value) { return g.judged ? value : nlohmann::json(nullptr); };
  return nlohmann::json{
      {"attempted", g.attempted},
      {"outcome", g.outcome},
      {"closure_s", finite_or_null(true, g.closure_s)},
      {"lock_s", finite_or_null(true, g.lock_s)},
      {"captured_s", finite_or_null(true, g.captured_s)},
      {"at_closure", judged(nlohmann::json{
                         {"axes", "the fixture's: x the approach"},
                         {"gripper_error_m", vec_json(a.r_m)},
                         {"gripper_velocity_mps", vec_json(a.v_mps)},
                         {"gripper_attitude_error_deg", vec_json(a.attitude_rad, kRadToDeg)},
                         {"gripper_rate_deg_s", vec_json(a.omega_radps, kRadToDeg)},
                         {"chaser_position_error_m", g.chaser_position_m},
                         {"chaser_velocity_error_mps", g.chaser_velocity_mps},
                         {"chaser_attitude_error_deg", g.chaser_attitude_deg},
                         {"chaser_rate_error_deg_s", g.chaser_rate_deg_s},
                     })},
      {"table2_met", grasp_meets_table2(g)},
  };
}

// ASSIST's berthing (sim/berth_result.hpp): null where the scenario does not berth.
nlohmann::json berth_json(const BerthResult& b) {
  if (!b.flown) return nullptr;
  const bool latched = std::isfinite(b.soft_dock_s);
  return nlohmann::json{
      {"soft_dock_s", finite_or_null(true, b.soft_dock_s)},
      {"latch_offset_mm", latched ? vec_json(b.latch_offset_m, 1e3) : nlohmann::json(nullptr)},
      {"latch_offset_axes", "the fixture's: x the approach"},
      {"latch_attitude_error_deg", finite_or_null(true, b.latch_attitude_deg)},
      {"pins_jammed", b.pins_jammed},
      {"hard_dock_s", finite_or_null(true, b.hard_dock_s)},
      {"mate_offset_mm", finite_or_null(true, 1e3 * b.mate_offset_m)},
      {"mate_attitude_error_deg", finite_or_null(true, b.mate_attitude_deg)},
      {"peak_contact_force_N", b.peak_contact_N},
      {"contact_force_limit_N", b.contact_force_limit_N},
      {"peak_hold_force_N", b.peak_hold_N},
      {"met", berth_meets_requirements(b)},
  };
}

// The rigidisation (sim/reach_result.hpp): null where it was not flown.
nlohmann::json rigidise_json(const model::Scenario& scenario, const RigidiseResult& r) {
  if (!r.flown) return nullptr;
  std::array<double, model::kArmJoints> angle_deg{}, rate_deg_s{};
  for (std::size_t j = 0; j < angle_deg.size(); ++j) {
    angle_deg[j] = kRadToDeg * r.final_angle_error_rad[j];
    rate_deg_s[j] = kRadToDeg * r.final_rate_radps[j];
  }
  return nlohmann::json{
      {"law", model::to_string(scenario.capture->rigidise->law)},
      {"start_s", r.start_s},
      {"brakes_s", finite_or_null(true, r.brakes_s)},
      {"peak_joint_torque_Nm", r.peak_torque_Nm},
      {"final_joint_angle_error_deg", angle_deg},
      {"final_joint_rate_deg_s", rate_deg_s},
      {"peak_brake_load_Nm", r.peak_brake_load_Nm},
  };
}

// The stabilisation (sim/reach_result.hpp): null where it was not flown. Judged against COMRADE
// Table 3: the rate below 0.5 deg/s at the end, every braked joint's load within the repeated peak.
nlohmann::json stabilise_json(const model::Scenario& scenario, const ReachResult& reach) {
  const StabiliseResult& s = reach.stabilise;
  if (!s.flown) return nullptr;
  return nlohmann::json{
      {"law", model::to_string(scenario.capture->stabilise->law)},
      {"start_s", s.start_s},
      {"initial_rate_deg_s", s.initial_rate_degps},
      {"below_goal_s", finite_or_null(true, s.below_goal_s)},
      {"goal_rate_deg_s", model::kStabilisedRateDegps},
      {"final_rate_target_deg_s", vec_json(s.final_rate_target_degps)},
      {"peak_joint_load_Nm", peak_brake_load_Nm(reach)},
      {"load_limit_Nm", s.load_limit_Nm},
      {"propellant_kg", s.propellant_kg},
      {"table3_met", stabilise_meets_table3(reach)},
  };
}

// The escape against Chaser's requirements (sim/escape_result.hpp); with capture.escape only.
nlohmann::json escape_json(const model::Scenario& scenario, const EscapeResult& e) {
  const model::EscapeParams& params = *scenario.capture->escape;
  return nlohmann::json{
      {"flown", e.flown},
      {"trigger", e.trigger},
      {"start_s", finite_or_null(true, e.start_s)},
      {"refused_s", finite_or_null(true, e.refused_s)},
      {"desynchronise_s", finite_or_null(true, e.desynchronise_s)},
      {"hold_s", finite_or_null(true, e.hold_s)},
      {"min_clearance_synchronised_m", finite_or_null(true, e.min_clearance_synchronised_m)},
      {"min_clearance_synchronised_at_s", finite_or_null(true, e.min_clearance_synchronised_at_s)},
      {"min_clearance_unsynchronised_m", finite_or_null(true, e.min_clearance_unsynchronised_m)},
      {"min_clearance_unsynchronised_at_s", finite_or_null(true, e.min_clearance_unsynchronised_at_s)},
      {"min_tool_clearance_m", finite_or_null(true, e.min_tool_clearance_m)},
      {"min_tool_clearance_at_s", finite_or_null(true, e.min_tool_clearance_at_s)},
      {"max_camera_angle_deg", finite_or_null(true, kRadToDeg * e.max_camera_angle_rad)},
      {"max_camera_angle_at_s", finite_or_null(true, e.max_camera_angle_at_s)},
      {"camera_fov_half_angle_deg", finite_or_null(true, kRadToDeg * arm_camera_fov_rad(scenario))},
      {"final_distance_m", finite_or_null(true, e.final_distance_m)},
      {"safe_distance_m", params.safe_distance_m},
      {"brakes_s", finite_or_null(true, e.brakes_s)},
      {"peak_brake_load_Nm", finite_or_null(true, e.peak_brake_load_Nm)},
      {"requirements_met", escape_meets_requirements(e, scenario)},
  };
}

// The escape's line of the text report (with capture.escape).
std::string escape_text(const model::Scenario& scenario, const EscapeResult& e) {
  const model::EscapeParams& params = *scenario.capture->escape;
  const std::string refused =
      std::isnan(e.refused_s) ? std::string() : fmt::format(" (commanded at {:.1f} s with the jaws closed: refused)", e.refused_s);
  if (!e.flown) return fmt::format("  escape: not triggered{}\n", refused);
  const std::string braked =
      std::isnan(e.brakes_s) ? std::string()
                             : fmt::format("; arm braked from {:.1f} s, peak joint load {:.2f} N m (limit {:.0f})",
                                           e.brakes_s, e.peak_brake_load_Nm, scenario.chaser.arm->torque_repeated_peak_Nm);
  return fmt::format(
      "  escape ({}): from {:.1f} s{}, desynchronised at {:.1f} s, holding from {:.1f} s; least clearance {:.3f} m "
      "synchronised (>= {:g}), {:.3f} m after (>= {:g}); tool point {:.3f} m from the keep-out (> 0); camera axis "
      "within {:.1f} deg of the target's centre (field of view {:.0f}); {:.2f} m from the target at {:.1f} s (safe "
      "distance {:g} +- {:g}){}: requirements {}\n",
      e.trigger, e.start_s, refused, e.desynchronise_s, e.hold_s, e.min_clearance_synchronised_m,
      model::kEscapeSynchronisedClearanceM, e.min_clearance_unsynchronised_m, model::kEscapeUnsynchronisedClearanceM,
      e.min_tool_clearance_m, kRadToDeg * e.max_camera_angle_rad, kRadToDeg * arm_camera_fov_rad(scenario),
      e.final_distance_m, e.final_t_s, params.safe_distance_m, model::kEscapeDistanceTolM, braked,
      escape_meets_requirements(e, scenario) ? "met" : "NOT met");
}

// Each phase flown against its requirements (sim/phase_verdicts.hpp).
nlohmann::json verdicts_json(const std::vector<PhaseVerdict>& verdicts) {
  nlohmann::json out = nlohmann::json::array();
  for (const PhaseVerdict& v : verdicts) {
    nlohmann::json requirements = nlohmann::json::array();
    for (const Requirement& q : v.requirements)
      requirements.push_back({{"name", q.name},
                              {"value", finite_or_null(true, q.value)},
                              {"limit", finite_or_null(true, q.limit)},
                              {"met", q.met}});
    out.push_back({{"phase", v.phase}, {"start_s", v.start_s}, {"end_s", v.end_s}, {"met", v.met()},
                   {"requirements", requirements}});
  }
  return out;
}

// The phases' line of the text report: every phase met, or those that are not and why.
std::string verdicts_text(const std::vector<PhaseVerdict>& verdicts) {
  std::string failed;
  for (const PhaseVerdict& v : verdicts) {
    if (v.met()) continue;
    std::string names;
    for (const Requirement& q : v.requirements)
      if (!q.met) names += (names.empty() ? "" : ", ") + q.name;
    failed += fmt::format("{}{} ({})", failed.empty() ? "" : "; ", v.phase, names);
  }
  return failed.empty() ? fmt::format("  phases: every requirement met in the {} phases flown\n", verdicts.size())
                        : fmt::format("  phases: NOT met: {}\n", failed);
}

// The reach against COMRADE Table 2 (sim/reach_result.hpp): null without a capture.
nlohmann::json reach_json(const model::Scenario& scenario, const RunResult& r) {
  if (!scenario.capture) return nullptr;
  const ReachResult& reach = r.reach;
  const MissionFigures& f = r.figures;
  const plant::GripperTruth& g = reach.final_gripper;
  nlohmann::json out{
      {"law", model::to_string(scenario.capture->law)},
      {"flown", reach.flown},
      {"hold_from_s", reach.hold_from_s},
      {"hold_s", reach.hold_periods * scenario.control_period_s},
      {"camera_samples", reach.camera_samples},
      {"gripper", nlohmann::json{
                      {"axes", "the pre-grasp pose's: x the approach"},
                      {"max_error_m", vec_json(reach.max_gripper_error_m)},
                      {"max_velocity_mps", vec_json(reach.max_gripper_velocity_mps)},
                      {"max_attitude_error_deg", vec_json(reach.max_gripper_attitude_rad, kRadToDeg)},
                      {"max_rate_deg_s", vec_json(reach.max_gripper_rate_radps, kRadToDeg)},
                      {"final_error_m", vec_json(g.r_m)},
                      {"final_velocity_mps", vec_json(g.v_mps)},
                      {"final_attitude_error_deg", vec_json(g.attitude_rad, kRadToDeg)},
                      {"final_rate_deg_s", vec_json(g.omega_radps, kRadToDeg)},
                      {"table2_met", gripper_meets_table2(reach)},
                  }},
      {"chaser_table2_met", f.final_position_error_m <= kTable2ChaserPositionM &&
                                f.final_speed_mps <= kTable2ChaserVelocityMps &&
                                f.final_attitude_error_rad * kRadToDeg <= kTable2ChaserAttitudeDeg &&
                                f.final_rate_error_radps * kRadToDeg <= kTable2ChaserRateDegps},
      {"peak_joint_torque_Nm", reach.peak_joint_torque_Nm},
      {"min_tool_clearance_m", finite_or_null(true, reach.min_tool_clearance_m)},
      {"min_tool_clearance_at_s", finite_or_null(true, reach.min_tool_clearance_at_s)},
      {"torque_repeated_peak_Nm", scenario.chaser.arm ? scenario.chaser.arm->torque_repeated_peak_Nm : 0.0},
      {"grasp", grasp_json(reach.grasp)},
      {"berthing", berth_json(reach.berthing)},
      {"rigidisation", rigidise_json(scenario, reach.rigidise)},
      {"stabilisation", stabilise_json(scenario, reach)},
  };
  if (scenario.capture->escape) out["escape"] = escape_json(scenario, r.escape);
  return out;
}

// The berthing's line of the text report.
std::string berth_text(const BerthResult& b) {
  std::string docks = "no soft dock (the latches never closed)";
  if (std::isfinite(b.soft_dock_s))
    docks = fmt::format("soft dock at {:.1f} s (the tip {:.1f}, {:.1f}, {:.1f} mm from the socket, {:.2f} deg off its axes), {}",
                        b.soft_dock_s, 1e3 * b.latch_offset_m.x(), 1e3 * b.latch_offset_m.y(), 1e3 * b.latch_offset_m.z(),
                        b.latch_attitude_deg,
                        std::isfinite(b.hard_dock_s) ? fmt::format("hard dock at {:.1f} s", b.hard_dock_s)
                        : b.pins_jammed              ? std::string("the pins jammed: no hard dock")
                                                     : std::string("no hard dock by the end"));
  return fmt::format("  berthing: {}; peak contact force {:.1f} N (limit {:.0f}), peak latch and pin force {:.1f} N: {}\n",
                     docks, b.peak_contact_N, b.contact_force_limit_N, b.peak_hold_N,
                     berth_meets_requirements(b) ? "met" : "NOT met");
}

// The reach's two lines of the text report.
template <class Mm, class Deg>
std::string reach_lines(const model::Scenario& scenario, const ReachResult& reach, const Mm& mm, const Deg& deg,
                        double peak) {
  return fmt::format(
      "  reach ({} law, {} camera samples): gripper over the hold from {:.0f} s, largest per axis (x the approach): "
      "{} mm, {} mm/s, {} deg, {} deg/s: COMRADE Table 2 {}\n"
      "  reach: peak joint torque {:.1f} N m (limit {:.0f}); the tool point's least clearance from the "
      "keep-out volume {:.3f} m at {:.1f} s\n",
      model::to_string(scenario.capture->law), reach.camera_samples, reach.hold_from_s, mm(reach.max_gripper_error_m),
      mm(reach.max_gripper_velocity_mps), deg(reach.max_gripper_attitude_rad), deg(reach.max_gripper_rate_radps),
      gripper_meets_table2(reach) ? "met" : "NOT met (+-10, 22, 22 mm; 2.74 deg; 5 mm/s; 0.1 deg/s)", peak,
      scenario.chaser.arm ? scenario.chaser.arm->torque_repeated_peak_Nm : 0.0, reach.min_tool_clearance_m,
      reach.min_tool_clearance_at_s);
}

// The reach's and the grasp's lines of the text report.
std::string reach_text(const model::Scenario& scenario, const RunResult& r) {
  if (!scenario.capture) return {};
  const ReachResult& reach = r.reach;
  if (!reach.flown) return "  reach: not flown (the run ended before capture.start_s)\n";
  const auto mm = [](const Vec3& v) { return fmt::format("{:.1f}, {:.1f}, {:.1f}", 1e3 * v.x(), 1e3 * v.y(), 1e3 * v.z()); };
  const auto deg = [](const Vec3& v) {
    return fmt::format("{:.2f}, {:.2f}, {:.2f}", kRadToDeg * v.x(), kRadToDeg * v.y(), kRadToDeg * v.z());
  };
  double peak = 0.0;
  for (const double t : reach.peak_joint_torque_Nm) peak = std::max(peak, t);
  const GraspResult& g = reach.grasp;
  std::string grasp;
  if (const BerthResult& b = reach.berthing; b.flown)
    grasp = berth_text(b);
  else if (g.judged)
    grasp = fmt::format(
        "  grasp: {} (jaws closed at {:.1f} s{}); at the closure the gripper {} mm, {} mm/s, {} deg, {} deg/s from the "
        "fixture, the chaser {:.3f} m, {:.1f} mm/s, {:.2f} deg, {:.3f} deg/s: COMRADE Table 2 {}\n",
        g.outcome, g.closure_s, std::isnan(g.captured_s) ? std::string() : fmt::format(", locked at {:.2f} s", g.captured_s),
        mm(g.at_closure.r_m), mm(g.at_closure.v_mps), deg(g.at_closure.attitude_rad), deg(g.at_closure.omega_radps),
        g.chaser_position_m, 1e3 * g.chaser_velocity_mps, g.chaser_attitude_deg, g.chaser_rate_deg_s,
        grasp_meets_table2(g) ? "met" : "NOT met");
  else if (g.attempted)
    grasp = fmt::format("  grasp: {} (the jaws never closed)\n", g.outcome);
  std::string rigidisation;
  if (const RigidiseResult& rg = reach.rigidise; rg.flown) {
    double peak_rg = 0.0, angle = 0.0, rate = 0.0;
    for (std::size_t j = 0; j < rg.peak_torque_Nm.size(); ++j) {
      peak_rg = std::max(peak_rg, rg.peak_torque_Nm[j]);
      angle = std::max(angle, std::abs(rg.final_angle_error_rad[j]));
      rate = std::max(rate, std::abs(rg.final_rate_radps[j]));
    }
    rigidisation = fmt::format(
        "  rigidisation ({} law): from {:.1f} s, thrusters inhibited; {}; peak joint torque {:.1f} N m; at the end the "
        "joints within {:.3f} deg of where it held them, rates within {:.4f} deg/s\n",
        model::to_string(scenario.capture->rigidise->law), rg.start_s, std::isnan(rg.brakes_s) ? std::string("brakes not engaged") : fmt::format("brakes engaged at {:.1f} s", rg.brakes_s),
        peak_rg, kRadToDeg * angle, kRadToDeg * rate);
  }
  std::string stabilisation;
  if (const StabiliseResult& st = reach.stabilise; st.flown) {
    stabilisation = fmt::format(
        "  stabilisation ({} law): from {:.1f} s at {:.2f} deg/s; {}; at the end {:.3f}, {:.3f}, {:.3f} deg/s (target axes); "
        "peak braked joint load {:.1f} N m (limit {:.0f}); {:.2f} kg of propellant: COMRADE Table 3 {}\n",
        model::to_string(scenario.capture->stabilise->law), st.start_s, st.initial_rate_degps,
        std::isnan(st.below_goal_s) ? fmt::format("not below {} deg/s at the end", model::kStabilisedRateDegps)
                                    : fmt::format("below {} deg/s from {:.1f} s", model::kStabilisedRateDegps, st.below_goal_s),
        st.final_rate_target_degps.x(), st.final_rate_target_degps.y(), st.final_rate_target_degps.z(),
        peak_brake_load_Nm(reach), st.load_limit_Nm, st.propellant_kg, stabilise_meets_table3(reach) ? "met" : "NOT met");
  }
  const std::string escape = scenario.capture->escape ? escape_text(scenario, r.escape) : std::string();
  return reach_lines(scenario, reach, mm, deg, peak) + grasp + rigidisation + stabilisation + escape;
}

}  // namespace

nlohmann::json run_summary(const model::Scenario& scenario, const std::string& scenario_hash, const RunResult& r) {
  const MissionFigures& f = r.figures;
  nlohmann::json out{
      {"chaser_version", kChaserVersion},
      {"scenario", scenario.name},
      {"scenario_hash", scenario_hash},
      {"seed", scenario.seed},
      {"faults", faults_json(scenario)},
      {"duration_s", scenario.duration_s},
      {"control_period_s", scenario.control_period_s},
      {"approach_axis_lvlh", {scenario.guidance.approach_axis_lvlh.x(), scenario.guidance.approach_axis_lvlh.y(),
                              scenario.guidance.approach_axis_lvlh.z()}},
      {"corridor_half_angle_deg", scenario.guidance.corridor_half_angle_rad * kRadToDeg},
      {"capture_distance_m", scenario.guidance.capture_distance_m},
      {"simulated_s", r.simulated_s},
      {"wall_s", r.wall_s},
      {"wall_design_s", r.wall_design_s},
      {"wall_loop_s", r.wall_loop_s},
      {"wall_files_s", r.wall_files_s},
      {"simulated_s_per_wall_s", r.wall_s > 0 ? r.simulated_s / r.wall_s : 0.0},
      {"capture_achieved", f.capture_achieved},
      {"diverged", f.diverged},
      {"diverged_at_s", f.diverged_at_s},
      {"final_position_error_m", f.final_position_error_m},
      {"final_speed_mps", f.final_speed_mps},
      {"final_attitude_error_deg", f.final_attitude_error_rad * kRadToDeg},
      {"final_rate_error_deg_s", f.final_rate_error_radps * kRadToDeg},
      {"corridor_kept", f.corridor_violation_periods == 0},
      {"corridor_violation_s", f.corridor_violation_periods * scenario.control_period_s},
      {"first_corridor_violation_s", f.first_corridor_violation_s},
      {"max_corridor_angle_deg", f.max_corridor_angle_rad * kRadToDeg},
      {"target_out_of_view_s", f.out_of_view_periods * scenario.control_period_s},
      {"max_line_of_sight_angle_deg", f.max_line_of_sight_angle_rad * kRadToDeg},
      {"max_attitude_error_deg", f.max_attitude_error_rad * kRadToDeg},
      {"max_position_error_m", f.max_position_error_m},
      {"min_target_clearance_m", checks_keep_out(scenario) ? nlohmann::json(f.min_target_clearance_m) : nlohmann::json()},
      {"min_target_clearance_at_s", checks_keep_out(scenario) ? nlohmann::json(f.min_target_clearance_at_s) : nlohmann::json()},
      {"min_clearance_unsynchronised_m", finite_or_null(checks_keep_out(scenario), f.min_clearance_unsynchronised_m)},
      {"min_clearance_unsynchronised_at_s", finite_or_null(checks_keep_out(scenario), f.min_clearance_unsynchronised_at_s)},
      {"min_clearance_synchronised_m", finite_or_null(checks_keep_out(scenario), f.min_clearance_synchronised_m)},
      {"min_clearance_synchronised_at_s", finite_or_null(checks_keep_out(scenario), f.min_clearance_synchronised_at_s)},
      {"propellant_used_kg", r.propellant_used_kg},
      {"infeasible_allocation_periods", r.infeasible_allocations},
      {"active_check_pulses", r.active_checks},
      {"max_thruster_on_fraction", r.max_on_fraction},
      {"thruster_saturated_s", static_cast<double>(r.saturated_periods) * scenario.control_period_s},
      {"phases", phases_json(scenario)},
      {"phases_flown", phases_flown_json(r)},
      {"fdir", fdir_json(scenario, r.fdir)},
      {"supervisor", supervisor_json(r.supervisor)},
      {"reach", reach_json(scenario, r)},
  };
  if (scenario.guidance.synchronised) {  // COMRADE's mission, phase by phase
    const std::vector<PhaseVerdict> verdicts = phase_verdicts(scenario, run_phases(scenario), r);
    out["phase_verdicts"] = verdicts_json(verdicts);
    out["mission_met"] = mission_met(verdicts);
  }
  return out;
}

std::string summary_text(const model::Scenario& scenario, const RunResult& r) {
  const MissionFigures& f = r.figures;
  std::string faults = scenario.faults.empty() ? "none" : "";
  for (const auto& fault : scenario.faults)
    faults += fmt::format("{}{} {} at {:.0f} s", faults.empty() ? "" : ", ", model::thruster_name(fault.thruster),
                          model::to_string(fault.kind), fault.onset_s);
  std::string out = fmt::format("{}: seed {}, fault: {}\n", scenario.name, scenario.seed, faults);
  out += fmt::format("  flown {:.1f} s of {:.1f} s in {:.3f} s wall ({:.0f} x real time){}\n", r.simulated_s,
                     scenario.duration_s, r.wall_s, r.wall_s > 0 ? r.simulated_s / r.wall_s : 0.0,
                     f.diverged ? fmt::format(", DIVERGED at {:.1f} s", f.diverged_at_s) : "");
  out += fmt::format("  capture: {}  (final position error {:.3f} m, speed {:.4f} m/s, attitude {:.2f} deg)\n",
                     f.capture_achieved ? "ACHIEVED" : "NOT achieved", f.final_position_error_m, f.final_speed_mps,
                     f.final_attitude_error_rad * kRadToDeg);
  out += f.corridor_violation_periods == 0
             ? fmt::format("  corridor: kept (max {:.2f} deg from the axis)\n", f.max_corridor_angle_rad * kRadToDeg)
             : fmt::format("  corridor: VIOLATED for {:.1f} s from {:.1f} s (max {:.1f} deg)\n",
                           f.corridor_violation_periods * scenario.control_period_s, f.first_corridor_violation_s,
                           f.max_corridor_angle_rad * kRadToDeg);
  out += fmt::format("  target out of view: {:.1f} s; max attitude error {:.2f} deg; max position error {:.3f} m\n",
                     f.out_of_view_periods * scenario.control_period_s, f.max_attitude_error_rad * kRadToDeg,
                     f.max_position_error_m);
  if (checks_keep_out(scenario))
    out += fmt::format("  keep-out: least clearance {:.3f} m at {:.1f} s (target.body.keep_out less chaser.keep_out_radius_m)\n",
                       f.min_target_clearance_m, f.min_target_clearance_at_s);
  out += fmt::format("  thrusters: largest on-time {:.0f} % of a period, {:.1f} s with one saturated (commanded the whole period)\n",
                     100.0 * r.max_on_fraction, static_cast<double>(r.saturated_periods) * scenario.control_period_s);
  if (checks_keep_out(scenario) && scenario.guidance.synchronised && scenario.guidance.synchronised->approach)
    out += fmt::format("  COMRADE Table 4: {:.3f} m before the rotation's synchronisation (>= 3 m), {:.3f} m after (>= 0.5 m); "
                       "final rate error {:.3f} deg/s\n",
                       f.min_clearance_unsynchronised_m, f.min_clearance_synchronised_m,
                       f.final_rate_error_radps * kRadToDeg);
  const double onset = first_onset_s(scenario);
  const int faulty = scenario.faults.empty() ? model::kNoThruster : scenario.faults.front().thruster;
  const std::vector<flight::DiagnosisScheme>& schemes = flight::diagnosis_schemes();
  for (std::size_t i = 0; i < schemes.size(); ++i) out += scheme_text(schemes[i].name, r.fdir.schemes[i], onset, faulty);
  for (std::size_t i = 0; i < r.fdir.episodes.size(); ++i) {
    const FdirResult& e = r.fdir.episodes[i];
    if (i > 0 && e.detection_s >= 0)
      out += fmt::format("  diagnosis {} (after recovery): alarm at {:.1f} s{}\n", i + 1, e.detection_s,
                         e.isolated_thruster != model::kNoThruster
                             ? fmt::format(", {} isolated at {:.1f} s", model::thruster_name(e.isolated_thruster), e.isolation_s)
                                                 : std::string());
    if (e.recovery_s >= 0)
      out += scenario.fdi.recovery == model::RecoveryPolicy::kExclude
                 ? fmt::format("  recovery: {} excluded at {:.1f} s, flying on without it\n",
                               model::thruster_name(e.recovered_thruster), e.recovery_s)
                 : fmt::format("  recovery: {}'s group latch closed at {:.1f} s, flying on the standby group\n",
                               model::thruster_name(e.recovered_thruster), e.recovery_s);
  }
  const bool diagnosis_on = std::any_of(r.fdir.schemes.begin(), r.fdir.schemes.end(),
                                        [](const SchemeResult& s) { return s.enabled; }) || r.supervisor.enabled;
  if (diagnosis_on && r.fdir.stood_down_s >= 0)
    out += fmt::format("  diagnosis: stood down at {:.1f} s, at the capture (its models are the free chaser's)\n",
                       r.fdir.stood_down_s);
  out += reach_text(scenario, r);
  if (scenario.guidance.synchronised) out += verdicts_text(phase_verdicts(scenario, run_phases(scenario), r));
  out += fmt::format("  propellant used: {:.3f} kg\n", r.propellant_used_kg);
  return out;
}

}  // namespace chaser::sim
