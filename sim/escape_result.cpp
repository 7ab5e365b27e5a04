#include "sim/escape_result.hpp"

#include <cmath>
#include <limits>

#include "model/capture.hpp"

namespace chaser::sim {

namespace {

// A smaller (larger) value than the figure, or the first: taken with its time. NaN values are not figures.
void keep_least(double value, double t_s, double& least, double& at_s) {
  if (std::isnan(value) || value >= least) return;
  least = value;
  at_s = t_s;
}
void keep_most(double value, double t_s, double& most, double& at_s) {
  if (std::isnan(value) || value <= most) return;
  most = value;
  at_s = t_s;
}

}  // namespace

void add_escape_period(EscapeResult& r, const flight::EscapeLawParams& params, const flight::EscapeState& state,
                       const EscapeSample& s) {
  if (state.refused_s >= 0.0) r.refused_s = state.refused_s;
  if (!state.started()) return;
  r.flown = true;
  r.trigger = flight::to_string(state.trigger);
  r.start_s = state.start_s;
  r.desynchronise_s = flight::escape_desynchronise_s(params, state);
  r.hold_s = flight::escape_hold_s(params, state);
  constexpr double kTimeTolS = 1e-9;
  if (s.t_s + kTimeTolS < r.desynchronise_s)
    keep_least(s.chaser_clearance_m, s.t_s, r.min_clearance_synchronised_m, r.min_clearance_synchronised_at_s);
  else
    keep_least(s.chaser_clearance_m, s.t_s, r.min_clearance_unsynchronised_m, r.min_clearance_unsynchronised_at_s);
  // The tool from its retraction's end on: it starts at the fixture, on the keep-out volume's face.
  if (s.t_s + kTimeTolS >= state.start_s + params.escape.retract_duration_s)
    keep_least(s.tool_clearance_m, s.t_s, r.min_tool_clearance_m, r.min_tool_clearance_at_s);
  keep_most(s.camera_angle_rad, s.t_s, r.max_camera_angle_rad, r.max_camera_angle_at_s);
  r.final_distance_m = s.distance_m;
  if (state.braked()) r.brakes_s = state.brakes_s;
  r.final_t_s = s.t_s;
}

double camera_angle_rad(const Vec3& tool_target_m, const Quat& q_target_from_tool, double setback_m) {
  const Vec3 axis = q_target_from_tool * Vec3::UnitX();
  const Vec3 eye_m = tool_target_m - setback_m * axis;
  return std::atan2(axis.cross(-eye_m).norm(), axis.dot(-eye_m));
}

bool escape_meets_requirements(const EscapeResult& r, double safe_distance_m, double camera_fov_rad,
                               double load_limit_Nm) {
  constexpr double kTimeTolS = 1e-9;
  const bool camera_met = std::isnan(camera_fov_rad) || r.max_camera_angle_rad <= camera_fov_rad;
  const bool loads_met = std::isnan(r.brakes_s) || r.peak_brake_load_Nm <= load_limit_Nm;
  return r.flown && loads_met && r.final_t_s + kTimeTolS >= r.hold_s &&
         r.min_clearance_synchronised_m >= model::kEscapeSynchronisedClearanceM &&
         r.min_clearance_unsynchronised_m >= model::kEscapeUnsynchronisedClearanceM && r.min_tool_clearance_m > 0.0 &&
         camera_met && std::abs(r.final_distance_m - safe_distance_m) <= model::kEscapeDistanceTolM;
}

double arm_camera_fov_rad(const model::Scenario& scenario) {
  return scenario.sensors.arm_camera ? scenario.sensors.arm_camera->fov_half_angle_rad
                                     : std::numeric_limits<double>::quiet_NaN();
}

bool escape_meets_requirements(const EscapeResult& r, const model::Scenario& scenario) {
  return escape_meets_requirements(r, scenario.capture->escape->safe_distance_m, arm_camera_fov_rad(scenario),
                                   scenario.chaser.arm->torque_repeated_peak_Nm);
}

}  // namespace chaser::sim
