#pragma once
// Navigation unit (Fonod 2015, section II.B): estimates of relative position and velocity (LIDAR +
// HCW Kalman filter, flight/translation_filter.hpp) and of attitude and rate (star tracker + gyro
// complementary filter, flight/attitude_filter.hpp).
//
// Call order: init_nav with the first measurement, then step_nav once per control period with the
// next measurement and the force flight software commanded over the period that just ended.
#include "core/time.hpp"
#include "core/types.hpp"
#include "flight/attitude_filter.hpp"
#include "flight/translation_filter.hpp"
#include "model/messages.hpp"
#include "model/scenario.hpp"

namespace chaser::flight {

struct NavEstimate {
  Vec3 r_lvlh_m = Vec3::Zero();                  // [m] chaser position from the target, LVLH
  Vec3 v_lvlh_mps = Vec3::Zero();                // [m/s] its LVLH-frame derivative
  Quat q_inertial_from_body = Quat::Identity();  // attitude
  Vec3 omega_body_radps = Vec3::Zero();          // [rad/s] bias-corrected inertial rate, body axes
};

struct NavParams {
  TranslationFilterParams translation;
  AttitudeFilterParams attitude;
};

NavParams make_nav_params(const model::Scenario& scenario);

struct NavState {
  TranslationFilterState translation;
  AttitudeFilterState attitude;
  TimeNs t_last = 0;  // [ns] time of the last measurement used
};

// Position from the LIDAR, velocity zero, attitude from the star tracker, bias zero. Throws
// std::runtime_error when the LIDAR does not see the target in the first sample: without a
// position the flight software cannot start (the scenario's initial state points it elsewhere).
NavState init_nav(const NavParams& params, const model::SensorMeasurements& first);

// One period: predict with the force commanded last period (LVLH, N), then correct with `meas`
// (the translation only with a LIDAR sample: in a gap it propagates on the commands alone).
// A measurement with the same time stamp as the last one used is not applied twice: the current
// estimate is returned unchanged (so the first period may pass the measurement init_nav consumed).
NavEstimate step_nav(const NavParams& params, NavState& state, const model::SensorMeasurements& meas,
                     const Vec3& force_cmd_lvlh_N_prev);

// The estimate held in a state, with the rate from the last gyro sample.
NavEstimate nav_estimate(const NavState& state);

}  // namespace chaser::flight
