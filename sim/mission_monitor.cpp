#include "sim/mission_monitor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/rotation.hpp"
#include "model/keep_out.hpp"
#include "model/target_orbit.hpp"

namespace chaser::sim {

namespace {

double angle_between(const Vec3& a, const Vec3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

bool finite(const MonitorSample& s) {
  return s.r_lvlh_m.allFinite() && s.v_lvlh_mps.allFinite() && s.q_inertial_from_body.coeffs().allFinite();
}

}  // namespace

bool checks_keep_out(const model::Scenario& scenario) {
  return scenario.target.body && !scenario.target.body->keep_out.empty();
}

double synchronised_from_s(const model::Scenario& scenario) {
  const auto& sync = scenario.guidance.synchronised;
  if (sync) return sync->approach ? sync->approach->rotation_sync_end_s() : 0.0;
  // On the line the chaser's attitude is fixed in LVLH: synchronised with a target that turns with
  // LVLH (ASSIST's "null relative angular velocity"), never with a tumbling one.
  const auto& body = scenario.target.body;
  if (body && body->spin_case == model::SpinCase::given) {
    const Vec3 omega_lvlh_radps = model::TargetOrbit(scenario.orbit).mean_motion_radps() * Vec3::UnitZ();
    if ((scenario.target.omega_inertial_radps - omega_lvlh_radps).norm() <= kSynchronisedRate_radps) return 0.0;
  }
  return std::numeric_limits<double>::infinity();
}

double keep_out_clearance_m(const model::Scenario& scenario, const MonitorSample& s) {
  // The chaser's CoM in the target's axes, from its CoM.
  const Vec3 p_target_m = s.q_inertial_from_target.conjugate() * (s.q_inertial_from_lvlh * s.r_lvlh_m);
  return model::keep_out_distance_m(scenario.target.body->keep_out, p_target_m) - scenario.chaser.keep_out_radius_m;
}

bool monitor_period(const model::Scenario& scenario, const MonitorSample& s, MissionFigures& f) {
  if (!finite(s) || s.r_lvlh_m.norm() > kDivergedDistance_m) {
    f.diverged = true;
    f.diverged_at_s = s.t_s;
    return false;
  }
  const auto& g = scenario.guidance;
  const double range_m = s.r_lvlh_m.norm();
  if (range_m > g.corridor_min_distance_m && !g.synchronised) {  // the line's cone; the synchronised
                                                                  // approach turns with the target
    const double corridor_angle = angle_between(s.r_lvlh_m, g.approach_axis_lvlh);
    f.max_corridor_angle_rad = std::max(f.max_corridor_angle_rad, corridor_angle);
    if (corridor_angle > g.corridor_half_angle_rad) {
      if (f.corridor_violation_periods == 0) f.first_corridor_violation_s = s.t_s;
      ++f.corridor_violation_periods;
    }
  }
  // Line of sight from the chaser to the target, in body axes, against the boresight +x.
  const Vec3 los_body = s.q_inertial_from_body.conjugate() * (s.q_inertial_from_lvlh * (-s.r_lvlh_m));
  const double los_angle = angle_between(los_body, Vec3::UnitX());
  f.max_line_of_sight_angle_rad = std::max(f.max_line_of_sight_angle_rad, los_angle);
  if (los_angle > scenario.sensors.lidar.fov_half_angle_rad) ++f.out_of_view_periods;

  const double attitude_error = attitude_error_body(s.q_ref_inertial_from_body, s.q_inertial_from_body).norm();
  f.max_attitude_error_rad = std::max(f.max_attitude_error_rad, attitude_error);
  f.max_position_error_m = std::max(f.max_position_error_m, (s.r_lvlh_m - s.r_ref_lvlh_m).norm());
  if (checks_keep_out(scenario)) {
    const double clearance_m = keep_out_clearance_m(scenario, s);
    if (clearance_m < f.min_target_clearance_m) {
      f.min_target_clearance_m = clearance_m;
      f.min_target_clearance_at_s = s.t_s;
    }
    double& least = s.synchronised ? f.min_clearance_synchronised_m : f.min_clearance_unsynchronised_m;
    if (clearance_m < least) {
      least = clearance_m;
      (s.synchronised ? f.min_clearance_synchronised_at_s : f.min_clearance_unsynchronised_at_s) = s.t_s;
    }
  }
  return true;
}

void monitor_final(const model::Scenario& scenario, const MonitorSample& s, MissionFigures& f) {
  const auto& g = scenario.guidance;
  if (g.synchronised) {  // the capture point turns with the target: judged against the reference,
                         // which the sample carries from the truth at the end (sim::Simulation)
    f.final_position_error_m = (s.r_lvlh_m - s.r_ref_lvlh_m).norm();
    f.final_speed_mps = (s.v_lvlh_mps - s.v_ref_lvlh_mps).norm();
  } else {
    const Vec3 capture_point_lvlh_m = g.capture_distance_m * g.approach_axis_lvlh;
    f.final_position_error_m = (s.r_lvlh_m - capture_point_lvlh_m).norm();
    f.final_speed_mps = s.v_lvlh_mps.norm();
  }
  f.final_attitude_error_rad = attitude_error_body(s.q_ref_inertial_from_body, s.q_inertial_from_body).norm();
  // Both rates in the body's own axes: the reference's turned through the attitude error.
  const Vec3 omega_ref_in_body =
      s.q_inertial_from_body.conjugate() * (s.q_ref_inertial_from_body * s.omega_ref_body_radps);
  f.final_rate_error_radps = (s.omega_body_radps - omega_ref_in_body).norm();
  f.capture_achieved = !f.diverged && f.final_position_error_m <= g.capture_position_tol_m &&
                       f.final_speed_mps <= g.capture_speed_tol_mps &&
                       f.final_attitude_error_rad <= g.capture_attitude_tol_rad;
}

}  // namespace chaser::sim
