#include "sim/reach_result.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace chaser::sim {

void add_reach_period(ReachResult& r, const plant::GripperTruth& gripper, double t_s, double clearance_m) {
  constexpr double kTimeTolS = 1e-9;  // the hold's start is a sum of seconds, the period's start a count of ns
  r.flown = true;
  if (t_s + kTimeTolS >= r.hold_to_s) return;
  if (t_s + kTimeTolS >= r.hold_from_s) {
    r.max_gripper_error_m = r.max_gripper_error_m.cwiseMax(gripper.r_m.cwiseAbs());
    r.max_gripper_velocity_mps = r.max_gripper_velocity_mps.cwiseMax(gripper.v_mps.cwiseAbs());
    r.max_gripper_attitude_rad = r.max_gripper_attitude_rad.cwiseMax(gripper.attitude_rad.cwiseAbs());
    r.max_gripper_rate_radps = r.max_gripper_rate_radps.cwiseMax(gripper.omega_radps.cwiseAbs());
    ++r.hold_periods;
  }
  r.final_gripper = gripper;
  if (!(clearance_m >= r.min_tool_clearance_m)) {  // the first, NaN before it, or a smaller one
    if (std::isnan(clearance_m)) return;
    r.min_tool_clearance_m = clearance_m;
    r.min_tool_clearance_at_s = t_s;
  }
}

bool gripper_meets_table2(const ReachResult& r) {
  constexpr double kDeg = std::numbers::pi / 180.0;
  if (!r.flown || r.hold_periods == 0) return false;
  const std::array<Vec3, 4> figures = {r.max_gripper_error_m, r.max_gripper_velocity_mps,
                                       r.max_gripper_attitude_rad / kDeg, r.max_gripper_rate_radps / kDeg};
  for (int f = 0; f < 4; ++f)
    for (int k = 0; k < 3; ++k)
      if (figures[static_cast<std::size_t>(f)](k) > table2_gripper_limit(f, k)) return false;
  return true;
}

bool grasp_meets_table2(const GraspResult& g) {
  constexpr double kDeg = std::numbers::pi / 180.0;
  if (!g.judged) return false;
  const plant::GripperTruth& a = g.at_closure;
  const std::array<Vec3, 4> figures = {a.r_m, a.v_mps, a.attitude_rad / kDeg, a.omega_radps / kDeg};
  for (int f = 0; f < 4; ++f)
    for (int k = 0; k < 3; ++k)
      if (!(std::abs(figures[static_cast<std::size_t>(f)](k)) <= table2_gripper_limit(f, k))) return false;
  return g.chaser_position_m <= kTable2ChaserPositionM && g.chaser_velocity_mps <= kTable2ChaserVelocityMps &&
         g.chaser_attitude_deg <= kTable2ChaserAttitudeDeg && g.chaser_rate_deg_s <= kTable2ChaserRateDegps;
}

void add_grasp_period(GraspResult& g, const flight::GraspState& state, const plant::GripperTruth& gripper_at_fixture,
                      const MonitorSample& sample) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const auto time = [&](double t_s) { return t_s >= 0.0 ? t_s : kNaN; };
  g.attempted = g.attempted || state.step != flight::GraspStep::kReach;
  g.outcome = flight::to_string(state.step);
  g.closure_s = time(state.closure_s);
  g.lock_s = time(state.lock_s);
  g.captured_s = time(state.captured_s);
  if (g.judged || state.closure_s < 0.0) return;
  g.judged = true;
  g.at_closure = gripper_at_fixture;
  const Quat q_body_from_ref = (sample.q_inertial_from_body.conjugate() * sample.q_ref_inertial_from_body).normalized();
  g.chaser_position_m = (sample.r_lvlh_m - sample.r_ref_lvlh_m).norm();
  g.chaser_velocity_mps = (sample.v_lvlh_mps - sample.v_ref_lvlh_mps).norm();
  g.chaser_attitude_deg = 2.0 * std::atan2(q_body_from_ref.vec().norm(), std::abs(q_body_from_ref.w())) * 180.0 / std::numbers::pi;
  g.chaser_rate_deg_s = (sample.omega_body_radps - sample.omega_ref_body_radps).norm() * 180.0 / std::numbers::pi;
}

void add_rigidise_period(RigidiseResult& r, const flight::RigidiseState& state, const model::ArmMeasurements& joints) {
  if (!state.started()) return;
  r.flown = true;
  r.start_s = state.started_s;
  if (state.brakes_s >= 0.0) r.brakes_s = state.brakes_s;
  for (int j = 0; j < model::kArmJoints; ++j) {
    const auto i = static_cast<std::size_t>(j);
    r.final_angle_error_rad[i] = joints.q_rad[i] - state.q_hold_rad(j);
    r.final_rate_radps[i] = joints.q_dot_radps[i];
  }
}

double peak_brake_load_Nm(const ReachResult& r) {
  return *std::max_element(r.rigidise.peak_brake_load_Nm.begin(), r.rigidise.peak_brake_load_Nm.end());
}

bool stabilise_meets_table3(const ReachResult& r) {
  return r.stabilise.flown && !std::isnan(r.stabilise.below_goal_s) && peak_brake_load_Nm(r) <= r.stabilise.load_limit_Nm;
}

void add_stabilise_period(StabiliseResult& r, const flight::StabiliseState& state, const Vec3& omega_target_radps,
                          double chaser_mass_kg, double load_limit_Nm, double t_s) {
  if (!state.started()) return;
  const Vec3 rate_degps = omega_target_radps * (180.0 / std::numbers::pi);
  if (!r.flown) {
    r.flown = true;
    r.start_s = state.started_s;
    r.initial_rate_degps = rate_degps.norm();
    r.start_mass_kg = chaser_mass_kg;
    r.load_limit_Nm = load_limit_Nm;
  }
  if (rate_degps.norm() >= model::kStabilisedRateDegps)
    r.below_goal_s = std::numeric_limits<double>::quiet_NaN();
  else if (std::isnan(r.below_goal_s))
    r.below_goal_s = t_s;
  r.final_rate_target_degps = rate_degps;
  r.propellant_kg = r.start_mass_kg - chaser_mass_kg;
}

}  // namespace chaser::sim
