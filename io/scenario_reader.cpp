// Top level of the scenario document and its physical sections: orbit, chaser, target,
// environment, sensors.
#include <fmt/format.h>

#include "core/plain_name.hpp"
#include "io/scenario_sections.hpp"

namespace chaser::io {

model::Scenario read_scenario(const YAML::Node& root, const std::string& source, Diagnostics& diag) {
  model::Scenario s;
  if (!root.IsMap()) {
    diag.add(source, fmt::format("must be a mapping of scenario keys (got {})", describe_node(root)));
    return s;
  }
  MapReader r(root, "", diag);
  if (r.text("name", s.name) && !is_plain_name(s.name))  // it names a campaign case's folder (--preset comrade-table5)
    diag.add("name", fmt::format("must be a plain name: {} (got '{}')", kPlainNameRule, s.name));
  r.count("seed", s.seed);
  r.number("duration_s", Range::left_open(0.0, kMaxDurationS), s.duration_s);
  r.number("control_period_s", Range::closed(kMinControlPeriodS, kMaxControlPeriodS), s.control_period_s);
  read_section(r, "orbit", [&](MapReader& m) { read_orbit(m, s.orbit); });
  read_section(r, "chaser", [&](MapReader& m) { read_chaser(m, s.chaser); });
  read_section(r, "target", [&](MapReader& m) { read_target(m, s.target); });
  read_section(r, "thrusters", [&](MapReader& m) { read_thrusters(m, s.thrusters); });
  read_section(r, "environment", [&](MapReader& m) { read_environment(m, s.environment); });
  read_section(r, "sensors", [&](MapReader& m) { read_sensors(m, s.sensors); });
  read_section(r, "navigation", [&](MapReader& m) { read_navigation(m, s.navigation); });
  read_section(r, "guidance", [&](MapReader& m) { read_guidance(m, s.guidance); });
  read_section(r, "control", [&](MapReader& m) { read_control(m, s.control); });
  read_section(r, "fdi", [&](MapReader& m) { read_fdi(m, s.fdi); });
  read_section(r, "initial", [&](MapReader& m) { read_initial(m, s.initial); });
  read_section(r, "campaign", [&](MapReader& m) { read_campaign(m, s.campaign); });
  read_optional_capture(r, s.capture);
  read_faults(r, s.faults);
  r.finish();
  return s;
}

void read_orbit(MapReader& r, model::OrbitParams& out) {
  r.number("mu_m3ps2", Range::positive(), out.mu_m3ps2);
  r.number("body_radius_m", Range::positive(), out.body_radius_m);
  r.number("altitude_m", Range::positive(), out.altitude_m);
  read_optional_earth_orbit(r, out.earth);
}

void read_chaser(MapReader& r, model::SpacecraftParams& out) {
  r.number("mass_kg", Range::positive(), out.mass_kg);
  r.mat3("inertia_kgm2", out.inertia_kgm2);
  r.vec3("com_body_m", Range::closed(-kMaxLayoutExtentM, kMaxLayoutExtentM), out.com_body_m);
  r.number("isp_s", Range::positive(), out.isp_s);
  if (r.has("keep_out_radius_m"))
    r.number("keep_out_radius_m", Range::closed(0.0, kMaxLayoutExtentM), out.keep_out_radius_m);
  read_optional_slosh(r, out.slosh);
  read_optional_arm(r, out.arm);
}

void read_target(MapReader& r, model::TargetParams& out) {
  r.quaternion("q_inertial_from_target", out.q_inertial_from_target);
  r.vec3("omega_inertial_radps", out.omega_inertial_radps);
  read_optional_target_body(r, out.body);
}

void read_environment(MapReader& r, model::EnvironmentParams& out) {
  r.vec3("force_bias_lvlh_N", out.force_bias_lvlh_N);
  r.number("force_noise_sigma_N", Range::non_negative(), out.force_noise_sigma_N);
  r.vec3("torque_bias_body_Nm", out.torque_bias_body_Nm);
  r.number("torque_noise_sigma_Nm", Range::non_negative(), out.torque_noise_sigma_Nm);
  r.boolean("gravity_gradient", out.gravity_gradient);
}

// Delays are checked against the control period in validate_scenario.
void read_sensors(MapReader& r, model::SensorParams& out) {
  read_section(r, "lidar", [&](MapReader& m) {
    m.number("noise_sigma_m", Range::non_negative(), out.lidar.noise_sigma_m);
    m.vec3("bias_m", out.lidar.bias_m);
    m.number("delay_s", Range::non_negative(), out.lidar.delay_s);
    m.angle_deg("fov_half_angle_deg", Range::left_open(0.0, 90.0), out.lidar.fov_half_angle_rad);
    if (m.has("range_max_m")) m.number("range_max_m", Range::left_open(0.0, 1e6), out.lidar.range_max_m);
  });
  read_section(r, "star_tracker", [&](MapReader& m) {
    m.number("noise_sigma_rad", Range::non_negative(), out.star_tracker.noise_sigma_rad);
    m.vec3("bias_rad", out.star_tracker.bias_rad);
    m.number("delay_s", Range::non_negative(), out.star_tracker.delay_s);
  });
  read_section(r, "gyro", [&](MapReader& m) {
    m.number("noise_sigma_radps", Range::non_negative(), out.gyro.noise_sigma_radps);
    m.vec3("bias_radps", out.gyro.bias_radps);
    m.number("delay_s", Range::non_negative(), out.gyro.delay_s);
  });
  read_section(r, "propellant", [&](MapReader& m) {
    m.number("noise_sigma_kg", Range::non_negative(), out.propellant.noise_sigma_kg);
  });
  if (r.has("target_pose")) {  // optional; its period and latency against the control period in validate_scenario
    out.target_pose.emplace();
    read_section(r, "target_pose", [&](MapReader& m) {
      m.number("period_s", Range::left_open(0.0, 10.0), out.target_pose->period_s);
      m.angle_deg("attitude_noise_deg", Range::closed(0.0, 30.0), out.target_pose->attitude_noise_rad);
      m.number("latency_s", Range::non_negative(), out.target_pose->latency_s);
      if (m.has("range_max_m")) m.number("range_max_m", Range::left_open(0.0, 1e6), out.target_pose->range_max_m);
    });
  }
  if (r.has("arm_camera")) {  // optional; its period and latency against the control period in validate_scenario
    out.arm_camera.emplace();
    read_section(r, "arm_camera", [&](MapReader& m) {
      model::ArmCameraParams& c = *out.arm_camera;
      m.number("period_s", Range::left_open(0.0, 10.0), c.period_s);
      m.number("position_noise_m", Range::closed(0.0, 1.0), c.position_noise_m);
      m.angle_deg("attitude_noise_deg", Range::closed(0.0, 30.0), c.attitude_noise_rad);
      m.number("latency_s", Range::non_negative(), c.latency_s);
      m.angle_deg("fov_half_angle_deg", Range::left_open(0.0, 90.0), c.fov_half_angle_rad);
      m.number("range_max_m", Range::left_open(0.0, 100.0), c.range_max_m);
      m.number("setback_m", Range::closed(0.0, 2.0), c.setback_m);
      if (m.has("position_bias_m")) m.vec3("position_bias_m", Range::closed(-0.5, 0.5), c.position_bias_m);
    });
  }
}

}  // namespace chaser::io
