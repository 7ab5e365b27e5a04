// Flight-software sections: navigation, guidance, control (model/gnc.hpp) and the initial state.
#include <fmt/format.h>

#include "io/scenario_sections.hpp"

namespace chaser::io {

void read_navigation(MapReader& r, model::NavigationParams& out) {
  r.number("position_process_noise_mps2", Range::non_negative(), out.position_process_noise_mps2);
  r.number("attitude_gain", Range::left_open(0.0, 1.0), out.attitude_gain);
  r.number("gyro_bias_gain", Range::non_negative(), out.gyro_bias_gain);
  if (r.has("target_torque_noise_Nm"))
    r.number("target_torque_noise_Nm", Range::left_open(0.0, 1e6), out.target_torque_noise_Nm);
}

// Distances and durations against each other are checked in validate_scenario.
void read_guidance(MapReader& r, model::GuidanceParams& out) {
  r.direction("approach_axis_lvlh", out.approach_axis_lvlh);
  r.number("start_distance_m", Range::positive(), out.start_distance_m);
  r.number("capture_distance_m", Range::positive(), out.capture_distance_m);
  r.number("approach_duration_s", Range::positive(), out.approach_duration_s);
  r.number("blend_time_s", Range::non_negative(), out.blend_time_s);
  r.angle_deg("corridor_half_angle_deg", Range::open(0.0, 90.0), out.corridor_half_angle_rad);
  r.number("corridor_min_distance_m", Range::non_negative(), out.corridor_min_distance_m);
  r.number("capture_position_tol_m", Range::positive(), out.capture_position_tol_m);
  r.number("capture_speed_tol_mps", Range::positive(), out.capture_speed_tol_mps);
  r.angle_deg("capture_attitude_tol_deg", Range::left_open(0.0, 180.0), out.capture_attitude_tol_rad);
  if (r.has("synchronised")) {  // its needs (target.body, sensors.target_pose) are checked in validate_scenario
    out.synchronised.emplace();
    read_section(r, "synchronised", [&](MapReader& m) {
      if (m.has("approach")) {  // the start point is then the axis point (flight/sync_approach.hpp)
        out.synchronised->approach.emplace();
        read_section(m, "approach", [&](MapReader& a) {
          model::SyncApproachParams& p = *out.synchronised->approach;
          a.number("fly_around_start_s", Range::non_negative(), p.fly_around_start_s);
          a.number("fly_around_duration_s", Range::positive(), p.fly_around_duration_s);
          a.number("axis_distance_m", Range::left_open(0.0, 1e3), p.axis_distance_m);
          a.number("axis_approach_duration_s", Range::positive(), p.axis_approach_duration_s);
          a.number("rotation_sync_duration_s", Range::positive(), p.rotation_sync_duration_s);
        });
      } else {
        m.vec3("start_target_m", Range::closed(-1e3, 1e3), out.synchronised->start_target_m);
      }
      m.number("transfer_start_s", Range::non_negative(), out.synchronised->transfer_start_s);
      m.number("transfer_duration_s", Range::positive(), out.synchronised->transfer_duration_s);
      m.quaternion("q_target_from_body", out.synchronised->q_target_from_body);
    });
  }
}

// One loop family of control.hinf (model::HinfLoopWeights). The bandwidth is bounded by the period
// in validate_scenario (it must lie below the Nyquist frequency pi / T).
void read_hinf_loop(MapReader& r, const char* error_scale_key, model::HinfLoopWeights& out) {
  r.number("bandwidth_radps", Range::positive(), out.bandwidth_radps);
  r.number("peak_sensitivity", Range::left_open(1.0, 10.0), out.peak_sensitivity);
  r.number("low_frequency_gain", Range::open(0.0, 1.0), out.low_frequency_gain);
  r.number(error_scale_key, Range::positive(), out.error_scale);
  if (r.has("input_disturbance")) r.number("input_disturbance", Range::closed(0.0, 10.0), out.input_disturbance);
}

// LQR weights (model/gnc.hpp): input weights r > 0 so that the input cost is positive definite;
// position and angle weights > 0 too, for without them the Riccati equation has no stabilising
// solution; rate weights >= 0. Modulation thresholds and the anti-windup clamp > 0.
namespace {

constexpr int kMaxModesPerFamily = 4;
constexpr int kMaxGridPoints = 20;

void read_mode(const YAML::Node& node, const std::string& path, model::UncertainModeSpec& out, Diagnostics& diag) {
  MapReader m(node, path, diag);
  m.text("name", out.name);
  m.number("frequency_lo_radps", Range::positive(), out.frequency_lo_radps);
  m.number("frequency_hi_radps", Range::positive(), out.frequency_hi_radps);
  m.number("modal_fraction", Range::right_open(0.0, 1.0), out.modal_fraction);
  m.number("damping", Range::right_open(0.0, 1.0), out.damping);
  m.finish();
  if (m.valid() && diag.clean(join_path(path, "frequency_lo_radps")) && diag.clean(join_path(path, "frequency_hi_radps")) &&
      !(out.frequency_lo_radps <= out.frequency_hi_radps))
    diag.add(join_path(path, "frequency_hi_radps"),
             fmt::format("must be >= frequency_lo_radps = {} (got {})", format_number(out.frequency_lo_radps),
                         format_number(out.frequency_hi_radps)));
}

void read_modes(MapReader& r, const char* key, std::vector<model::UncertainModeSpec>& out) {
  const auto list = r.child(key, fmt::format("a list of 0 to {} modes", kMaxModesPerFamily));
  if (!list) return;
  if (!(list->IsSequence() && list->size() <= static_cast<std::size_t>(kMaxModesPerFamily))) {
    r.diagnostics().add(r.path_of(key), fmt::format("must be a list of 0 to {} modes (got {})", kMaxModesPerFamily,
                                                    describe_node(*list)));
    return;
  }
  out.assign(list->size(), model::UncertainModeSpec{});
  for (std::size_t i = 0; i < list->size(); ++i)
    read_mode((*list)[i], join_path(r.path_of(key), std::to_string(i)), out[i], r.diagnostics());
}

void read_robustness(MapReader& r, model::HinfRobustnessParams& out) {
  r.number("mass_uncertainty", Range::right_open(0.0, 0.5), out.mass_uncertainty);
  r.number("thrust_uncertainty", Range::right_open(0.0, 0.5), out.thrust_uncertainty);
  std::uint64_t points = 0;
  if (r.count("points_per_range", points)) {
    if (points < 2 || points > static_cast<std::uint64_t>(kMaxGridPoints))
      r.diagnostics().add(r.path_of("points_per_range"),
                          fmt::format("must be in [2, {}] (got {})", kMaxGridPoints, points));
    else
      out.points_per_range = static_cast<int>(points);
  }
  read_modes(r, "translation_modes", out.translation_modes);
  read_modes(r, "rotation_modes", out.rotation_modes);
}

void read_optional_hinf(MapReader& r, std::optional<model::HinfDesignParams>& out) {
  if (!r.has("hinf")) return;
  out.emplace();
  read_section(r, "hinf", [&](MapReader& h) {
    read_section(h, "translation", [&](MapReader& t) { read_hinf_loop(t, "error_scale_m", out->translation); });
    read_section(h, "rotation", [&](MapReader& t) { read_hinf_loop(t, "error_scale_rad", out->rotation); });
    if (h.has("robustness")) {
      out->robustness.emplace();
      read_section(h, "robustness", [&](MapReader& b) { read_robustness(b, *out->robustness); });
    }
  });
}

// control.allocation_norm (optional): 1, 2 or inf (flight/norm_allocation.hpp).
void read_allocation_norm(MapReader& r, model::AllocationNorm& out) {
  if (!r.has("allocation_norm")) return;
  r.choice("allocation_norm",
           {{"1", model::AllocationNorm::kOne}, {"2", model::AllocationNorm::kTwo}, {"inf", model::AllocationNorm::kInfinity}},
           out);
}

// control.law (optional): lqr or hinf; hinf flies control.hinf's design, which must be there.
void read_control_law(MapReader& r, model::ControlParams& out) {
  if (!r.has("law") || !r.choice("law", {{"lqr", model::ControlLaw::kLqr}, {"hinf", model::ControlLaw::kHinf}}, out.law))
    return;
  if (out.law == model::ControlLaw::kHinf && !out.hinf)
    r.diagnostics().add(r.path_of("law"), "hinf needs a control.hinf section (the loops' weights)");
}

}  // namespace

void read_control(MapReader& r, model::ControlParams& out) {
  r.number("position_q_pos", Range::positive(), out.position_q_pos);
  r.number("position_q_vel", Range::non_negative(), out.position_q_vel);
  r.number("position_r_force", Range::positive(), out.position_r_force);
  r.number("attitude_q_angle", Range::positive(), out.attitude_q_angle);
  r.number("attitude_q_rate", Range::non_negative(), out.attitude_q_rate);
  r.number("attitude_r_torque", Range::positive(), out.attitude_r_torque);
  r.number("tmu_force_threshold_Ns", Range::positive(), out.tmu_force_threshold_Ns);
  r.number("tmu_torque_threshold_Nms", Range::positive(), out.tmu_torque_threshold_Nms);
  r.number("tmu_windup_periods", Range::positive(), out.tmu_windup_periods);
  read_allocation_norm(r, out.allocation_norm);
  if (r.has("mass_from_gauge")) r.boolean("mass_from_gauge", out.mass_from_gauge);
  read_optional_hinf(r, out.hinf);
  read_control_law(r, out);
}

void read_initial(MapReader& r, model::InitialState& out) {
  r.vec3("r_lvlh_m", out.r_lvlh_m);
  r.vec3("v_lvlh_mps", out.v_lvlh_mps);
  r.boolean("use_guidance_start", out.use_guidance_start);
  r.quaternion("q_lvlh_from_body", out.q_lvlh_from_body);
  r.vec3("omega_body_radps", out.omega_body_radps);
}

}  // namespace chaser::io
