// capture: the arm's reach and its combined controller (model/capture.hpp). The keys' ranges here;
// their checks against the rest of the scenario (the arm, the run, the synchronisation, the
// multibody plant's needs) in validate_capture below.
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "io/scenario_sections.hpp"

namespace chaser::io {

void read_optional_capture(MapReader& r, std::optional<model::CaptureParams>& out) {
  if (!r.has("capture")) return;
  out.emplace();
  read_section(r, "capture", [&](MapReader& m) {
    model::CaptureParams& c = *out;
    m.number("start_s", Range::closed(0.0, kMaxDurationS), c.start_s);
    if (m.has("law"))
      m.choice("law", {{"compliance", model::CaptureLaw::kCompliance}, {"hinf", model::CaptureLaw::kHinf}}, c.law);
    m.number("path_duration_s", Range::left_open(0.0, 1e4), c.path_duration_s);
    m.number("standoff_m", Range::closed(0.0, 2.0), c.standoff_m);
    m.number("joint_rate_hz", Range::closed(1.0, 1e4), c.joint_rate_hz);
    m.number("platform_rate_hz", Range::left_open(0.0, 1e4), c.platform_rate_hz);
    m.number("hub_bandwidth_radps", Range::left_open(0.0, 100.0), c.hub_bandwidth_radps);
    m.number("tool_bandwidth_radps", Range::left_open(0.0, 100.0), c.tool_bandwidth_radps);
    m.number("joint_bandwidth_radps", Range::left_open(0.0, 100.0), c.joint_bandwidth_radps);
    m.number("damping_ratio", Range::closed(0.1, 10.0), c.damping_ratio);
    // The grasp's keys are optional (model/capture.hpp's defaults).
    if (m.has("pre_grasp_hold_s")) m.number("pre_grasp_hold_s", Range::closed(0.0, 1e4), c.pre_grasp_hold_s);
    if (m.has("approach_duration_s")) m.number("approach_duration_s", Range::left_open(0.0, 1e4), c.approach_duration_s);
    if (std::uint64_t samples = 0; m.has("closure_samples") && m.count("closure_samples", samples)) {
      if (samples < 1 || samples > 100)
        m.diagnostics().add(m.path_of("closure_samples"), fmt::format("must be in [1, 100] (got {})", samples));
      else
        c.closure_samples = static_cast<int>(samples);
    }
    if (m.has("lock_dwell_s")) m.number("lock_dwell_s", Range::closed(0.0, 10.0), c.lock_dwell_s);
    if (m.has("grasp_timeout_s")) m.number("grasp_timeout_s", Range::left_open(0.0, 1e4), c.grasp_timeout_s);
    if (m.has("rigidise")) {
      c.rigidise.emplace();
      read_section(m, "rigidise", [&](MapReader& g) {  // every key optional: model/capture.hpp's defaults
        model::RigidiseParams& r = *c.rigidise;
        if (g.has("law"))
          g.choice("law", {{"compliance", model::RigidiseLaw::kCompliance}, {"hinf", model::RigidiseLaw::kHinf}}, r.law);
        if (g.has("stiffness_Nm_per_rad")) g.number("stiffness_Nm_per_rad", Range::closed(0.0, 1e6), r.stiffness_Nm_per_rad);
        if (g.has("damping_Nms_per_rad")) g.number("damping_Nms_per_rad", Range::left_open(0.0, 1e7), r.damping_Nms_per_rad);
        if (g.has("saturation"))
          g.choice("saturation",
                   {{"linear", model::RigidiseSaturation::kLinear}, {"clip", model::RigidiseSaturation::kClip}}, r.saturation);
        if (g.has("linear_limit_Nm")) g.number("linear_limit_Nm", Range::left_open(0.0, 1e5), r.linear_limit_Nm);
        if (g.has("brake_rate_degps")) g.number("brake_rate_degps", Range::left_open(0.0, 10.0), r.brake_rate_degps);
        if (g.has("brake_dwell_s")) g.number("brake_dwell_s", Range::closed(0.0, 1e3), r.brake_dwell_s);
        if (g.has("hinf")) read_section(g, "hinf", [&](MapReader& h) { read_hinf_loop(h, "error_scale_rad", r.hinf); });
      });
    }
    if (m.has("stabilise")) {
      c.stabilise.emplace();
      read_section(m, "stabilise", [&](MapReader& g) {  // every key optional: model/capture.hpp's defaults
        model::StabiliseParams& st = *c.stabilise;
        if (g.has("duration_s")) g.number("duration_s", Range::closed(1.0, 1e5), st.duration_s);
        if (g.has("law"))
          g.choice("law", {{"momentum", model::StabiliseLaw::kMomentum}, {"hinf", model::StabiliseLaw::kHinf}}, st.law);
        if (g.has("bandwidth_radps")) g.number("bandwidth_radps", Range::closed(1e-3, 10.0), st.bandwidth_radps);
        if (g.has("hinf")) read_section(g, "hinf", [&](MapReader& h) { read_hinf_loop(h, "error_scale_Nms2", st.hinf); });
        if (g.has("inertia_uncertainty")) g.number("inertia_uncertainty", Range::closed(0.0, 0.9), st.inertia_uncertainty);
      });
    }
    if (m.has("escape")) {
      c.escape.emplace();
      read_section(m, "escape", [&](MapReader& g) {  // every key optional: model/capture.hpp's defaults
        model::EscapeParams& e = *c.escape;
        if (double command_s = 0.0; g.has("command_s") && g.number("command_s", Range::closed(0.0, kMaxDurationS), command_s))
          e.command_s = command_s;
        if (g.has("on_failed_grasp")) g.boolean("on_failed_grasp", e.on_failed_grasp);
        if (g.has("retract_duration_s")) g.number("retract_duration_s", Range::closed(1.0, 1e4), e.retract_duration_s);
        if (g.has("withdraw_duration_s")) g.number("withdraw_duration_s", Range::closed(1.0, 1e4), e.withdraw_duration_s);
        if (g.has("withdraw_backoff_m")) g.number("withdraw_backoff_m", Range::closed(0.0, 100.0), e.withdraw_backoff_m);
        if (g.has("desynchronise_duration_s"))
          g.number("desynchronise_duration_s", Range::closed(1.0, 1e4), e.desynchronise_duration_s);
        if (g.has("retreat_duration_s")) g.number("retreat_duration_s", Range::closed(1.0, 1e4), e.retreat_duration_s);
        if (g.has("safe_distance_m")) g.number("safe_distance_m", Range::closed(1.0, 1e3), e.safe_distance_m);
        if (g.has("brake_when_stowed")) g.boolean("brake_when_stowed", e.brake_when_stowed);
        if (g.has("brake_rate_degps")) g.number("brake_rate_degps", Range::left_open(0.0, 10.0), e.brake_rate_degps);
        if (g.has("braked_step_s")) g.number("braked_step_s", Range::left_open(0.0, 1.0), e.braked_step_s);
      });
    }
    if (m.has("berthing")) {
      c.berthing.emplace();
      read_section(m, "berthing", [&](MapReader& g) {  // every key optional: model/capture.hpp's defaults
        model::BerthingParams& b = *c.berthing;
        const auto optional = [&g](const char* key, Range range, double& value) {
          if (g.has(key)) g.number(key, range, value);
        };
        optional("probe_tip_radius_m", Range::left_open(0.0, 0.2), b.probe_tip_radius_m);
        optional("drogue_mouth_radius_m", Range::left_open(0.0, 1.0), b.drogue_mouth_radius_m);
        optional("drogue_depth_m", Range::left_open(0.0, 1.0), b.drogue_depth_m);
        optional("socket_clearance_m", Range::closed(0.0, 0.05), b.socket_clearance_m);
        optional("friction", Range::closed(0.0, 2.0), b.friction);
        optional("latch_radius_m", Range::left_open(0.0, 0.05), b.latch_radius_m);
        optional("soft_dock_timeconst_s", Range::closed(0.01, 10.0), b.soft_dock_timeconst_s);
        optional("insertion_overtravel_m", Range::closed(0.0, 0.5), b.insertion_overtravel_m);
        optional("retraction_m", Range::closed(0.0, 1.0), b.retraction_m);
        optional("retraction_duration_s", Range::closed(1.0, 1e4), b.retraction_duration_s);
        optional("pin_position_tol_m", Range::left_open(0.0, 0.1), b.pin_position_tol_m);
        optional("pin_attitude_tol_deg", Range::left_open(0.0, 10.0), b.pin_attitude_tol_deg);
        optional("contact_force_limit_N", Range::left_open(0.0, 1e4), b.contact_force_limit_N);
      });
    }
  });
}

namespace {

// A count of one or more that a ratio of periods must be, to 1e-9 of itself (the periods are decimals
// written in seconds or hertz, their ratios not exact in binary).
bool whole_count(double x) { return std::round(x) >= 1.0 && std::abs(x - std::round(x)) <= 1e-9 * x; }

// The escape's command while the arm is awake; its retreat outwards, from the point the
// synchronised transfer started from (on the momentum axis) to beyond it.
void validate_escape(const model::Scenario& s, Diagnostics& d) {
  const model::CaptureParams& c = *s.capture;
  const model::EscapeParams& e = *c.escape;
  if (e.command_s && d.clean("capture.start_s") && !(*e.command_s >= c.start_s))
    d.add("capture.escape.command_s", fmt::format("must be at or after capture.start_s {} (the arm awake; got {})",
                                                  format_number(c.start_s), format_number(*e.command_s)));
  // The braked step a whole number of joint periods, and the control period a whole number of it.
  if (d.clean("capture.escape.braked_step_s") && d.clean("capture.joint_rate_hz") && d.clean("control_period_s")) {
    const double joints = e.braked_step_s * c.joint_rate_hz, per_period = s.control_period_s / e.braked_step_s;
    if (!whole_count(joints) || !whole_count(per_period))
      d.add("capture.escape.braked_step_s",
            fmt::format("must be a whole number of joint periods (1 / capture.joint_rate_hz = {} s) and divide "
                        "control_period_s {} s into whole steps (got {})",
                        format_number(1.0 / c.joint_rate_hz), format_number(s.control_period_s),
                        format_number(e.braked_step_s)));
  }
  const auto& sync = s.guidance.synchronised;
  if (!sync || !d.clean("guidance.synchronised")) return;
  const double withdraw_m = sync->approach ? sync->approach->axis_distance_m : sync->start_target_m.norm();
  if (!(e.safe_distance_m > withdraw_m))
    d.add("capture.escape.safe_distance_m",
          fmt::format("must be beyond the point the escape withdraws to, {} m from the target's centre ({}; got {})",
                      format_number(withdraw_m),
                      sync->approach ? "guidance.synchronised.approach.axis_distance_m"
                                     : "guidance.synchronised.start_target_m",
                      format_number(e.safe_distance_m)));
}

// The berthing's drogue: a cone that narrows to its throat, the probe's pre-contact pose outside its
// mouth; no escape (built for the gripper's jaws).
void validate_berthing(const model::CaptureParams& c, Diagnostics& d) {
  const model::BerthingParams& b = *c.berthing;
  const double throat_m = b.probe_tip_radius_m + b.socket_clearance_m;
  if (!(b.drogue_mouth_radius_m > throat_m))
    d.add("capture.berthing.drogue_mouth_radius_m",
          fmt::format("must be wider than the throat, probe_tip_radius_m + socket_clearance_m = {:.4g} m (got {})",
                      throat_m, format_number(b.drogue_mouth_radius_m)));
  const double outside_m = b.drogue_depth_m + b.probe_tip_radius_m;
  if (d.clean("capture.standoff_m") && !(c.standoff_m > outside_m))
    d.add("capture.standoff_m",
          fmt::format("with capture.berthing must put the probe's tip outside the drogue's mouth: beyond "
                      "capture.berthing.drogue_depth_m + probe_tip_radius_m = {:.4g} m (got {})",
                      outside_m, format_number(c.standoff_m)));
  if (c.escape) d.add("capture.escape", "is built for the gripper's grasp, not for capture.berthing: remove one of them");
}

}  // namespace

void validate_capture(const model::Scenario& s, Diagnostics& d) {
  if (!s.capture || !d.clean("capture")) return;
  const model::CaptureParams& c = *s.capture;
  if (!s.chaser.arm) d.add("capture", "needs chaser.arm (the arm that reaches)");
  if (!s.orbit.earth) d.add("capture", "needs orbit.earth (the multibody plant takes over from the Earth-orbit one)");
  if (s.chaser.slosh)
    d.add("capture", "the multibody plant has no slosh yet: remove chaser.slosh from a scenario with a capture");
  if (d.clean("duration_s") && !(c.start_s < s.duration_s))
    d.add("capture.start_s", fmt::format("must be before duration_s {} (got {})", format_number(s.duration_s),
                                         format_number(c.start_s)));
  if (s.guidance.synchronised && d.clean("guidance.synchronised")) {
    const double at_capture_point_s = s.guidance.synchronised->transfer_start_s + s.guidance.synchronised->transfer_duration_s;
    if (c.start_s < at_capture_point_s)
      d.add("capture.start_s", fmt::format("must be at or after the end of the transfer to the capture point, {} s "
                                           "(guidance.synchronised.transfer_start_s + transfer_duration_s; got {})",
                                           format_number(at_capture_point_s), format_number(c.start_s)));
  } else if (!s.guidance.synchronised) {
    d.add("capture", "needs guidance.synchronised (the capture point the chaser holds while the arm reaches)");
  }
  // The joints' period a whole number of nanoseconds, and the control period a whole number of them.
  const double joint_period_ns = 1e9 / c.joint_rate_hz;
  if (d.clean("capture.joint_rate_hz") && std::abs(joint_period_ns - std::round(joint_period_ns)) > 1e-6)
    d.add("capture.joint_rate_hz", fmt::format("must divide 1e9 ns into whole nanoseconds (got {})",
                                               format_number(c.joint_rate_hz)));
  else if (d.clean("capture.joint_rate_hz") && d.clean("control_period_s")) {
    const double per_period = s.control_period_s * c.joint_rate_hz;
    if (!whole_count(per_period))
      d.add("capture.joint_rate_hz", fmt::format("must run a whole number of times per control period {} s (got {} Hz)",
                                                 format_number(s.control_period_s), format_number(c.joint_rate_hz)));
  }
  if (d.clean("capture.platform_rate_hz") && d.clean("control_period_s") &&
      c.platform_rate_hz * s.control_period_s > 1.0 + 1e-9)
    d.add("capture.platform_rate_hz", fmt::format("must be at most the control rate, 1 / control_period_s = {} Hz (got {})",
                                                  format_number(1.0 / s.control_period_s), format_number(c.platform_rate_hz)));
  // The linear saturation's L inside its limit M, the drives' repeated peak.
  if (c.rigidise && s.chaser.arm && d.clean("capture.rigidise.linear_limit_Nm") &&
      !(c.rigidise->linear_limit_Nm < s.chaser.arm->torque_repeated_peak_Nm))
    d.add("capture.rigidise.linear_limit_Nm",
          fmt::format("must be below chaser.arm.torque_repeated_peak_Nm {} (got {})",
                      format_number(s.chaser.arm->torque_repeated_peak_Nm), format_number(c.rigidise->linear_limit_Nm)));
  // The rigidisation's H-infinity loops: omega_B a decade below the drives' torque loop, whose lag
  // the design takes as a delay (control/joint_design.hpp).
  if (c.rigidise && c.rigidise->law == model::RigidiseLaw::kHinf && s.chaser.arm && d.clean("capture.rigidise.hinf") &&
      !(c.rigidise->hinf.bandwidth_radps <= 0.1 * s.chaser.arm->torque_loop_bandwidth_radps))
    d.add("capture.rigidise.hinf.bandwidth_radps",
          fmt::format("must be at most a tenth of chaser.arm.torque_loop_bandwidth_radps, {} rad/s (got {})",
                      format_number(0.1 * s.chaser.arm->torque_loop_bandwidth_radps),
                      format_number(c.rigidise->hinf.bandwidth_radps)));
  // The stabilisation's H-infinity loops: omega_B below the Nyquist frequency of the control period.
  if (c.stabilise && c.stabilise->law == model::StabiliseLaw::kHinf && d.clean("capture.stabilise.hinf") &&
      d.clean("control_period_s") && !(c.stabilise->hinf.bandwidth_radps < 0.5 * std::numbers::pi / s.control_period_s))
    d.add("capture.stabilise.hinf.bandwidth_radps",
          fmt::format("must be below half the Nyquist frequency, pi / (2 control_period_s) = {} rad/s (got {})",
                      format_number(0.5 * std::numbers::pi / s.control_period_s),
                      format_number(c.stabilise->hinf.bandwidth_radps)));
  if (c.stabilise && !c.rigidise)
    d.add("capture.stabilise", "needs capture.rigidise (the stabilisation begins once its brakes hold)");
  if (c.escape && d.clean("capture.escape")) validate_escape(s, d);
  if (c.berthing && d.clean("capture.berthing")) validate_berthing(c, d);
  if (c.law == model::CaptureLaw::kHinf && !s.control.hinf)
    d.add("capture.law", "hinf needs a control.hinf section (the platform's authority and loop delay come from its design)");
}

}  // namespace chaser::io
