// The arm in the plant (plant/arm_joints.hpp) against references of the test's own: the gripper's
// truth at the arm's waking against the stowed arm's forward kinematics written out here from the
// scenario (a chain of rotations and offsets) on the rigid chaser's state; its velocity and angular
// velocity against central differences of its positions and attitudes over 2 ms while the arm is
// driven; the arm camera's fixture pose against the same kinematics, and its cone and range.
//
// Tolerances: positions 1e-9 m (the hand-over places the bodies to 1e-12 m; MuJoCo's compiled chain
// is the scenario's numbers); velocities 1e-7 m/s and 1e-7 rad/s: central differences at h = 0.25
// ms, whose truncation h^2 |x'''| / 6 falls 4x per halving of h (measured on the rate: 4.1e-7 rad/s
// at 1 ms, 1.0e-7 at 0.5 ms, 2.0e-8 at 0.25 ms), rounding 1e-16 x 4 m / 2.5e-4 s ~ 2e-12.
#include "plant/arm_joints.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/rotation.hpp"
#include "plant/plant.hpp"
#include "tests/plant/earth_orbit_scenario.hpp"

namespace chaser::plant {
namespace {

model::Scenario arm_scenario() {
  model::Scenario s = testing::tumbling_target_scenario();
  testing::add_stowed_arm(s);
  s.faults.clear();
  return s;
}

RigidState start(const model::Scenario& s) {
  return testing::chaser_start(s.chaser.mass_kg, Vec3(3.0, -6.0, 2.0));
}

// The stowed tool point and its attitude in the chaser's body frame, from the scenario's arm: link i
// turns about its axis at its joint, which sits at joint_position_m in the parent's frame (link 1's
// parent is the body frame, from mount_body_m); the tool is at gripper.position_link7_m in link 7's.
struct BodyPose {
  Vec3 r_m;
  Mat3 body_from_tool;
};
BodyPose stowed_tool(const model::ArmParams& arm) {
  Vec3 origin = arm.mount_body_m;
  Mat3 rotation = Mat3::Identity();
  for (int i = 0; i < model::kArmJoints; ++i) {
    const model::ArmLinkParams& link = arm.links[static_cast<std::size_t>(i)];
    origin += rotation * link.joint_position_parent_m;
    rotation = rotation * Eigen::AngleAxisd(arm.stowed_rad[static_cast<std::size_t>(i)], link.joint_axis).toRotationMatrix();
  }
  return {origin + rotation * arm.gripper.position_link7_m, rotation};
}

struct Awake {
  model::Scenario s = arm_scenario();
  model::TargetOrbit circle{[this] {
    model::OrbitParams o = s.orbit;
    o.earth.reset();
    return o;
  }()};
  Plant plant = make_plant(s, start(s), 7);
  const Vec3 fixture_target_m = Vec3(0.4, -0.3, 1.1);
  const Quat q_target_from_fixture = Quat(Eigen::AngleAxisd(0.7, Vec3(0.2, -1.0, 0.4).normalized()));
  Awake() {
    if (auto problem = wake_arm(plant, s)) ADD_FAILURE() << *problem;
  }
};

TEST(ArmJoints, TheGrippersTruthAtWakingIsTheStowedArmsKinematics) {
  Awake a;
  ASSERT_TRUE(arm_awake(a.plant));
  const BodyPose tool = stowed_tool(*a.s.chaser.arm);
  const RigidState& x = chaser_state(a.plant);
  const Mat3 inertial_from_body = x.q_inertial_from_body.toRotationMatrix();
  const Mat3 inertial_from_target = target_rotation(a.plant, 0.0).q_inertial_from_target.toRotationMatrix();
  // The tool from the target's CoM: the chaser's CoM point from LVLH, then the stowed arm.
  const Vec3 tool_m = q_inertial_from_lvlh(a.plant, a.circle, 0.0) * x.r_lvlh_m +
                      inertial_from_body * (tool.r_m - a.s.chaser.com_body_m);
  const Mat3 inertial_from_pose = inertial_from_target * a.q_target_from_fixture.toRotationMatrix();
  const Vec3 expected = inertial_from_pose.transpose() * (tool_m - inertial_from_target * a.fixture_target_m);
  const GripperTruth g = gripper_truth(a.plant, a.fixture_target_m, a.q_target_from_fixture);
  EXPECT_LT((g.r_m - expected).norm(), 1e-9);
  const Quat q_pose_from_tool(inertial_from_pose.transpose() * inertial_from_body * tool.body_from_tool);
  EXPECT_LT(quat_from_rotation_vector(g.attitude_rad).angularDistance(q_pose_from_tool), 1e-9);
}

// The figure python/plot_reach.py draws: at waking, the hub and every joint where the stowed chain
// puts them (1e-9 m, as the tool above); with the arm driven, the links keep their lengths (1e-9 m:
// a hinge's anchor is on its axis, so joint i+1's distance from joint i is fixed) and the tool point
// is the gripper's truth against the pose (the same point by two computations, 1e-12 m).
TEST(ArmJoints, TheArmsFigureIsTheArmsKinematicsInTargetAxes) {
  Awake a;
  const model::ArmParams& arm = *a.s.chaser.arm;
  const RigidState& x = chaser_state(a.plant);
  const Mat3 inertial_from_body = x.q_inertial_from_body.toRotationMatrix();
  const Quat q_inertial_from_target = target_rotation(a.plant, 0.0).q_inertial_from_target;
  const Mat3 target_from_inertial = q_inertial_from_target.toRotationMatrix().transpose();
  const Vec3 body_origin_inertial =
      q_inertial_from_lvlh(a.plant, a.circle, 0.0) * x.r_lvlh_m - inertial_from_body * a.s.chaser.com_body_m;
  const auto expected_in_target = [&](const Vec3& body_m) {
    return Vec3(target_from_inertial * (body_origin_inertial + inertial_from_body * body_m));
  };
  const ArmFigure f = arm_figure(a.plant);
  EXPECT_LT((f.hub_m - expected_in_target(Vec3::Zero())).norm(), 1e-9);
  EXPECT_LT(f.q_target_from_hub.angularDistance(q_inertial_from_target.conjugate() * x.q_inertial_from_body), 1e-9);
  Vec3 origin = arm.mount_body_m;
  Mat3 rotation = Mat3::Identity();
  for (int i = 0; i < model::kArmJoints; ++i) {
    const model::ArmLinkParams& link = arm.links[static_cast<std::size_t>(i)];
    origin += rotation * link.joint_position_parent_m;
    EXPECT_LT((f.joint_m[static_cast<std::size_t>(i)] - expected_in_target(origin)).norm(), 1e-9) << "joint " << i + 1;
    rotation = rotation * Eigen::AngleAxisd(arm.stowed_rad[static_cast<std::size_t>(i)], link.joint_axis).toRotationMatrix();
  }
  EXPECT_LT((f.tool_m - expected_in_target(stowed_tool(arm).r_m)).norm(), 1e-9);

  model::ArmCommand command;
  for (std::size_t j = 0; j < command.torque_Nm.size(); ++j) command.torque_Nm[j] = 5.0 * std::cos(0.5 + j);
  command_arm(a.plant, command);
  begin_plant_period(a.plant.params, a.plant.state, model::ThrusterCommand{}, 0);
  advance_plant(a.plant.params, a.plant.state, 0, 100'000'000);  // 0.1 s of 1 ms joint steps
  const ArmFigure moved = arm_figure(a.plant);
  EXPECT_GT((moved.tool_m - f.tool_m).norm(), 1e-4);  // the arm moved
  for (int i = 0; i + 1 < model::kArmJoints; ++i) {
    const auto k = static_cast<std::size_t>(i);
    EXPECT_NEAR((moved.joint_m[k + 1] - moved.joint_m[k]).norm(), (f.joint_m[k + 1] - f.joint_m[k]).norm(), 1e-9);
  }
  const GripperTruth g = gripper_truth(a.plant, a.fixture_target_m, a.q_target_from_fixture);
  EXPECT_LT((moved.tool_m - (a.fixture_target_m + a.q_target_from_fixture * g.r_m)).norm(), 1e-12);
}

TEST(ArmJoints, TheGrippersVelocityAndRateAreItsMotionsDerivatives) {
  Awake a;
  model::ArmCommand command;
  for (std::size_t j = 0; j < command.torque_Nm.size(); ++j) command.torque_Nm[j] = 3.0 * std::sin(1.0 + j);
  command_arm(a.plant, command);
  begin_plant_period(a.plant.params, a.plant.state, model::ThrusterCommand{}, 0);
  // The pose's frame in inertial axes at t, and the gripper's world difference from its point.
  struct Sample {
    Vec3 d_m;
    Quat q_tool;
    Mat3 inertial_from_pose;
    Vec3 omega_target_inertial;
    GripperTruth g;
  };
  TimeNs at = 0;
  const auto sample = [&](TimeNs t) {
    advance_plant(a.plant.params, a.plant.state, at, t);
    at = t;
    const TargetRotation target = target_rotation(a.plant, to_seconds(t));
    const Mat3 inertial_from_pose = (target.q_inertial_from_target * a.q_target_from_fixture).toRotationMatrix();
    const GripperTruth g = gripper_truth(a.plant, a.fixture_target_m, a.q_target_from_fixture);
    return Sample{inertial_from_pose * g.r_m,
                  Quat(inertial_from_pose) * quat_from_rotation_vector(g.attitude_rad),
                  inertial_from_pose, target.q_inertial_from_target * target.omega_body_radps, g};
  };
  for (TimeNs t = 1'000'000; t < 30'000'000; t += 1'000'000) sample(t);  // the arm gets going (1 ms joint steps)
  const TimeNs h_ns = 250'000;  // 0.25 ms: the differences' error falls 4x per halving (1 ms: 4.1e-7 rad/s; here 2e-8)
  const Sample before = sample(30'000'000), now = sample(30'000'000 + h_ns), after = sample(30'000'000 + 2 * h_ns);
  const double h = to_seconds(h_ns);
  const Vec3 v_expected = now.inertial_from_pose.transpose() * (after.d_m - before.d_m) / (2.0 * h);
  EXPECT_LT((now.g.v_mps - v_expected).norm(), 1e-7);
  EXPECT_GT(now.g.v_mps.norm(), 1e-4);  // the arm moves
  const Quat q_rate((after.q_tool.coeffs() - before.q_tool.coeffs()) / (2.0 * h));
  const Vec3 omega_tool_inertial = 2.0 * (q_rate * now.q_tool.conjugate()).vec();
  const Vec3 omega_expected = now.inertial_from_pose.transpose() * (omega_tool_inertial - now.omega_target_inertial);
  EXPECT_LT((now.g.omega_radps - omega_expected).norm(), 1e-7);
}

// The brakes (plant::engage_brakes through command_arm) hold a joint by friction up to their
// holding torque. Joint 4 (the elbow) driven at 0.8 of it barely creeps: MuJoCo's friction is a
// soft constraint, whose stick lets a loaded joint creep at (1 - d) / (d b) of its free
// acceleration (d = 0.999, b = 2 / (d T) = 1000 / s: ~2e-6 rad/s here; measured 7e-6, bound 2e-5
// rad/s, 1e-3 deg/s; with MuJoCo's default friction constraint it crept at 7e-3 rad/s). At 1.2 of
// it the joint slips against the holding torque, and at 2.2 of it too: the brake takes its holding
// torque off either drive's, so over the first 0.1 s (the other joints braked in both: the same
// effective inertia) their rates are as (110 - 50) / (60 - 50) = 6, within 5 % (the
// configuration moves by 0.02 rad in that time).
// The brake's load (brake_loads_Nm, its friction row's force) is the drive's torque while it holds
// (the joint static: nothing else acts about it, to the creep's ~1e-5 N m of inertia), and the
// holding torque itself while it slips (the row at its bound), within 0.1 %; nothing unbraked.
TEST(ArmJoints, TheBrakesHoldAJointBelowTheirTorqueAndSlipAbove) {
  constexpr double kHoldingNm = 50.0;
  constexpr std::size_t kElbow = 3;
  struct Elbow {
    double rate_at_0p1s_radps = 0.0, rate_at_1s_radps = 0.0, turned_rad = 0.0;
    std::array<double, model::kArmJoints> load_at_1s_Nm{};
  };
  const auto drive_elbow = [&](double torque_Nm, bool braked) {
    model::Scenario s = arm_scenario();
    s.chaser.arm->brake_holding_torque_Nm = kHoldingNm;
    Plant plant = make_plant(s, start(s), 7);
    if (auto problem = wake_arm(plant, s)) ADD_FAILURE() << *problem;
    model::ArmCommand command;
    command.engage_brakes = braked;
    command.torque_Nm[kElbow] = torque_Nm;
    command_arm(plant, command);
    EXPECT_EQ(sense_arm(plant).brakes_engaged, braked);
    const double q0 = sense_arm(plant).q_rad[kElbow];
    Elbow e;
    for (TimeNs t = 0; t < 1'000'000'000; t += 100'000'000) {  // ten 0.1 s periods, thrusters off
      begin_plant_period(plant.params, plant.state, model::ThrusterCommand{}, t);
      advance_plant(plant.params, plant.state, t, t + 100'000'000);
      if (t == 0) e.rate_at_0p1s_radps = sense_arm(plant).q_dot_radps[kElbow];
    }
    e.rate_at_1s_radps = sense_arm(plant).q_dot_radps[kElbow];
    e.turned_rad = sense_arm(plant).q_rad[kElbow] - q0;
    e.load_at_1s_Nm = brake_loads_Nm(plant);
    return e;
  };
  const Elbow held = drive_elbow(0.8 * kHoldingNm, true);
  const Elbow slipped = drive_elbow(1.2 * kHoldingNm, true);
  const Elbow slipped_harder = drive_elbow(2.2 * kHoldingNm, true);
  const Elbow free = drive_elbow(1.2 * kHoldingNm, false);
  EXPECT_LT(std::abs(held.rate_at_1s_radps), 2e-5);
  EXPECT_LT(std::abs(held.turned_rad), 2e-5);
  EXPECT_GT(std::abs(free.turned_rad), 0.5);  // the drive turns the free elbow
  EXPECT_GT(slipped.rate_at_1s_radps, 5.0 * slipped.rate_at_0p1s_radps);  // it keeps slipping
  EXPECT_NEAR(slipped_harder.rate_at_0p1s_radps / slipped.rate_at_0p1s_radps, 6.0, 0.3);
  EXPECT_NEAR(held.load_at_1s_Nm[kElbow], -0.8 * kHoldingNm, 1e-3 * kHoldingNm);
  EXPECT_NEAR(slipped.load_at_1s_Nm[kElbow], -kHoldingNm, 1e-3 * kHoldingNm);
  for (const double load : free.load_at_1s_Nm) EXPECT_EQ(load, 0.0);
}

// The arm braked at rest, then 10 s under the same thrusters (a torque on the hub that the brakes
// carry to the links), MuJoCo's braked integrator and step as given (step_s 0: the scene's 1 ms).
struct BrakedUnderThrust {
  Vec3 omega_body_radps = Vec3::Zero();
  Vec3 r_lvlh_m = Vec3::Zero();
  std::array<double, model::kArmJoints> peak_load_Nm{};
};
BrakedUnderThrust braked_under_thrust(const model::Scenario& s, int integrator, double step_s) {
  Plant plant = make_plant(s, start(s), 7);
  if (auto problem = wake_arm(plant, s)) ADD_FAILURE() << *problem;
  std::get<MultibodyMotionParams>(plant.params.motion).braked_integrator = integrator;
  model::ArmCommand command;
  command.engage_brakes = true;
  command_arm(plant, command);
  if (step_s > 0.0) set_braked_step(plant, step_s);
  model::ThrusterCommand thrust;
  thrust.ton[0] = 0.6;
  thrust.ton[2] = 0.3;
  BrakedUnderThrust out;
  for (TimeNs t = 0; t < 10'000'000'000; t += 100'000'000) {
    begin_plant_period(plant.params, plant.state, thrust, t);
    advance_plant(plant.params, plant.state, t, t + 100'000'000);
    const auto load = brake_loads_Nm(plant);
    for (std::size_t j = 0; j < load.size(); ++j) out.peak_load_Nm[j] = std::max(out.peak_load_Nm[j], std::abs(load[j]));
  }
  out.omega_body_radps = plant.state.chaser.omega_body_radps;
  out.r_lvlh_m = plant.state.chaser.r_lvlh_m;
  return out;
}

// Braked, the scene is integrated by MuJoCo's semi-implicit Euler (MultibodyMotionParams'
// braked_integrator), not RK4: the same braked arm under the same thrusters for 10 s, each way from
// the same state. The hub's rate and the brakes' loads agree to 3e-5 of their size (Euler's
// first-order error over a smooth 10 s motion at 1 ms steps: measured 8e-6 of the rate and 7e-6 of
// the largest load), far below what the capture's figures are judged to (Table 3's 0.5 deg/s, the
// drives' 176 N m).
TEST(ArmJoints, TheBrakedArmMovesAlikeUnderEulerAndRk4) {
  const model::Scenario s = arm_scenario();
  const BrakedUnderThrust euler = braked_under_thrust(s, mjINT_EULER, 0.0);
  const BrakedUnderThrust rk4 = braked_under_thrust(s, mjINT_RK4, 0.0);
  ASSERT_GT(rk4.omega_body_radps.norm(), 1e-4);  // the thrusters turn it
  EXPECT_LT((euler.omega_body_radps - rk4.omega_body_radps).norm(), 3e-5 * rk4.omega_body_radps.norm());
  const double largest = *std::max_element(rk4.peak_load_Nm.begin(), rk4.peak_load_Nm.end());
  ASSERT_GT(largest, 1e-3);  // the brakes carry the links' share
  for (std::size_t j = 0; j < rk4.peak_load_Nm.size(); ++j)
    EXPECT_NEAR(euler.peak_load_Nm[j], rk4.peak_load_Nm[j], 3e-5 * largest) << j;
}

// The escape's braked arm steps at capture.escape.braked_step_s (10 ms) instead of the scene's 1 ms
// (set_braked_step): the same braked arm under the same thrusters for 10 s, each way from the same
// state. Semi-implicit Euler's error is first order in the step: the hub's rate agrees to 3e-4 of
// itself (measured 7e-5; at 1 ms against RK4, 8e-6 above), the brakes' peak loads to 3e-3 of the
// largest (measured 1.4e-3), and the position to 1 mm over the 0.34 m the thrusters move it
// (measured 0.46 mm: Euler's position lags by about h/2 of the velocity gained, 4.5 ms x 0.07 m/s).
// All far below what the escape is judged to: clearances of 0.5 m and more, the drives' 176 N m.
TEST(ArmJoints, TheBrakedArmMovesAlikeAtTheBrakedStep) {
  const model::Scenario s = arm_scenario();
  const Vec3 r_start_m = make_plant(s, start(s), 7).state.chaser.r_lvlh_m;
  const BrakedUnderThrust fine = braked_under_thrust(s, mjINT_EULER, 0.0);
  const BrakedUnderThrust coarse = braked_under_thrust(s, mjINT_EULER, 0.01);
  ASSERT_GT(fine.omega_body_radps.norm(), 1e-4);     // the thrusters turn it
  ASSERT_GT((fine.r_lvlh_m - r_start_m).norm(), 0.3);  // and move it
  EXPECT_LT((coarse.omega_body_radps - fine.omega_body_radps).norm(), 3e-4 * fine.omega_body_radps.norm());
  EXPECT_LT((coarse.r_lvlh_m - fine.r_lvlh_m).norm(), 1e-3);
  const double largest = *std::max_element(fine.peak_load_Nm.begin(), fine.peak_load_Nm.end());
  ASSERT_GT(largest, 0.1);  // the brakes carry the links' share
  for (std::size_t j = 0; j < fine.peak_load_Nm.size(); ++j)
    EXPECT_NEAR(coarse.peak_load_Nm[j], fine.peak_load_Nm[j], 3e-3 * largest) << j;
}

TEST(ArmJoints, TheBrakedStepIsRefusedUnbraked) {
  model::Scenario s = arm_scenario();
  Plant plant = make_plant(s, start(s), 7);
  EXPECT_THROW(set_braked_step(plant, 0.01), std::logic_error);  // asleep
  if (auto problem = wake_arm(plant, s)) ADD_FAILURE() << *problem;
  EXPECT_THROW(set_braked_step(plant, 0.01), std::logic_error);  // awake, not braked
  model::ArmCommand command;
  command.engage_brakes = true;
  command_arm(plant, command);
  EXPECT_THROW(set_braked_step(plant, 0.0), std::invalid_argument);
  EXPECT_NO_THROW(set_braked_step(plant, 0.01));
}

TEST(ArmJoints, TheArmCameraSeesTheFixtureInItsConeAndRangeOnly) {
  Awake a;
  a.plant.params.fixture_target_m = a.fixture_target_m;
  a.plant.params.q_target_from_fixture = a.q_target_from_fixture;
  model::ArmCameraParams camera;
  camera.position_noise_m = 0.0;
  camera.attitude_noise_rad = 0.0;
  camera.latency_s = 0.0;
  camera.fov_half_angle_rad = 3.14;  // everything in front and behind but straight back
  camera.range_max_m = 100.0;
  a.plant.params.sensors.arm_camera = camera;
  // The expected view from the stowed kinematics: the fixture in the tool's axes.
  const BodyPose tool = stowed_tool(*a.s.chaser.arm);
  const RigidState& x = chaser_state(a.plant);
  const Mat3 inertial_from_tool = x.q_inertial_from_body.toRotationMatrix() * tool.body_from_tool;
  const Mat3 inertial_from_target = target_rotation(a.plant, 0.0).q_inertial_from_target.toRotationMatrix();
  const Vec3 tool_m = q_inertial_from_lvlh(a.plant, a.circle, 0.0) * x.r_lvlh_m +
                      x.q_inertial_from_body * (tool.r_m - a.s.chaser.com_body_m);
  const Vec3 fixture_in_camera = inertial_from_tool.transpose() * (inertial_from_target * a.fixture_target_m - tool_m);
  const Quat q_camera_from_fixture(inertial_from_tool.transpose() * inertial_from_target *
                                   a.q_target_from_fixture.toRotationMatrix());

  const auto seen = sense_arm_with_camera(a.plant.params, a.plant.state, 0.0);
  ASSERT_TRUE(seen && seen->fixture.valid);
  EXPECT_EQ(seen->joints, model::kArmJoints);
  EXPECT_LT((seen->fixture.r_camera_m - fixture_in_camera).norm(), 1e-9);
  EXPECT_LT(seen->fixture.q_camera_from_fixture.angularDistance(q_camera_from_fixture), 1e-9);
  // A cone that misses the fixture, or a range short of it: nothing.
  const double angle = std::acos(fixture_in_camera.x() / fixture_in_camera.norm());
  a.plant.params.sensors.arm_camera->fov_half_angle_rad = 0.9 * angle;
  EXPECT_FALSE(sense_arm_with_camera(a.plant.params, a.plant.state, 0.1)->fixture.valid);
  a.plant.params.sensors.arm_camera->fov_half_angle_rad = 1.1 * angle;
  a.plant.params.sensors.arm_camera->range_max_m = 0.9 * fixture_in_camera.norm();
  EXPECT_FALSE(sense_arm_with_camera(a.plant.params, a.plant.state, 0.2)->fixture.valid);
  a.plant.params.sensors.arm_camera->range_max_m = 1.1 * fixture_in_camera.norm();
  EXPECT_TRUE(sense_arm_with_camera(a.plant.params, a.plant.state, 0.3)->fixture.valid);
}

}  // namespace
}  // namespace chaser::plant
