#pragma once
// A complete, validated scenario: every parameter of one run. Loaded by io/, never mutated during a
// run (docs/architecture.md: parameters, state and algorithm are three things).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "model/campaign.hpp"
#include "model/capture.hpp"
#include "model/environment.hpp"
#include "model/faults.hpp"
#include "model/fdi.hpp"
#include "model/gnc.hpp"
#include "model/orbit.hpp"
#include "model/sensors.hpp"
#include "model/spacecraft.hpp"
#include "model/thrusters.hpp"

namespace chaser::model {

// Chaser state at t = 0 relative to the target, MSR LVLH, and its attitude.
struct InitialState {
  Vec3 r_lvlh_m = Vec3(0.0, -20.0, 0.0);         // [m] if use_guidance_start: taken from guidance
  Vec3 v_lvlh_mps = Vec3::Zero();                // [m/s]
  bool use_guidance_start = true;                // start on the approach axis, target-pointing, at rest
  Quat q_lvlh_from_body = Quat::Identity();      // used when use_guidance_start is false
  Vec3 omega_body_radps = Vec3::Zero();          // [rad/s] inertial rate, body axes
  // Added to the start's position and velocity (not scenario keys: a campaign's dispersion of the
  // start, campaign/dispersion.hpp).
  Vec3 offset_r_lvlh_m = Vec3::Zero();           // [m]
  Vec3 offset_v_lvlh_mps = Vec3::Zero();         // [m/s]
};

struct Scenario {
  std::string name = "unnamed";
  std::uint64_t seed = 1;
  double duration_s = 1200.0;       // [s]
  double control_period_s = 0.1;    // [s] T
  OrbitParams orbit;
  SpacecraftParams chaser;
  TargetParams target;
  ThrusterSetParams thrusters;
  EnvironmentParams environment;
  SensorParams sensors;
  NavigationParams navigation;
  GuidanceParams guidance;
  ControlParams control;
  FdiParams fdi;
  InitialState initial;
  std::vector<FaultParams> faults;
  CampaignParams campaign;
  std::optional<CaptureParams> capture;  // the arm's reach (needs chaser.arm)
};

}  // namespace chaser::model
