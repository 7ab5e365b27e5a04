// chaser.arm: the servicer's arm reads into model::ArmParams exactly, and each rule reports one
// error at its key path: the list's length, a link's inertia, its limits, the torque limits, the
// drives' friction, the fixture on the target's surface, the reach from the capture point, and the
// capture the arm needs.
#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "io/scenario_loader.hpp"
#include "model/arm.hpp"
#include "scenario_test_util.hpp"

namespace chaser::io {
namespace {

using testing::has_error;
constexpr const char* kSync = "scenarios/comrade_sync.yaml";
constexpr double kRadToDeg = 180.0 / std::numbers::pi;

std::string vec(const Vec3& v) { return fmt::format("[{}, {}, {}]", v.x(), v.y(), v.z()); }

// The arm as a flow mapping for --set chaser.arm=...; `links` replaces the list when given.
std::string arm_yaml(const model::ArmParams& arm, const std::string& links = "") {
  std::string list;
  for (const model::ArmLinkParams& l : arm.links)
    list += fmt::format("{}{{joint_position_m: {}, joint_axis: {}, mass_kg: {}, com_m: {}, inertia_kgm2: {}, "
                        "lower_deg: {}, upper_deg: {}, friction_Nm: {}, damping_Nms: {}, armature_kgm2: {}}}",
                        list.empty() ? "" : ", ", vec(l.joint_position_parent_m), vec(l.joint_axis), l.mass_kg,
                        vec(l.com_link_m), vec(l.inertia_kgm2), l.lower_rad * kRadToDeg, l.upper_rad * kRadToDeg,
                        l.friction_Nm, l.damping_Nms, l.armature_kgm2);
  const model::GripperParams& g = arm.gripper;
  return fmt::format("chaser.arm={{mount_body_m: {}, torque_repeated_peak_Nm: {}, torque_momentary_Nm: {}, "
                     "torque_loop_bandwidth_radps: {}, "
                     "links: [{}], gripper: {{tool_position_m: {}, mass_kg: {}, com_m: {}, inertia_kgm2: {}}}}}",
                     vec(arm.mount_body_m), arm.torque_repeated_peak_Nm, arm.torque_momentary_Nm,
                     arm.torque_loop_bandwidth_radps,
                     links.empty() ? list : links, vec(g.position_link7_m), g.mass_kg, vec(g.com_link7_m),
                     vec(g.inertia_kgm2));
}

TEST(ArmSection, TheDefaultArmReadsBackExactly) {
  const model::ArmParams arm = model::default_arm();
  const LoadResult r = load_scenario_file(kSync, {arm_yaml(arm)});
  ASSERT_TRUE(r.errors.empty()) << format_errors(r.errors);
  ASSERT_TRUE(r.scenario->chaser.arm.has_value());
  const model::ArmParams& read = *r.scenario->chaser.arm;
  EXPECT_EQ(read.mount_body_m, arm.mount_body_m);
  EXPECT_EQ(read.torque_momentary_Nm, 314.0);
  EXPECT_EQ(read.torque_loop_bandwidth_radps, 300.0);
  for (std::size_t i = 0; i < arm.links.size(); ++i) {
    EXPECT_EQ(read.links[i].joint_position_parent_m, arm.links[i].joint_position_parent_m) << i;
    EXPECT_EQ(read.links[i].joint_axis, arm.links[i].joint_axis) << i;
    EXPECT_EQ(read.links[i].inertia_kgm2, arm.links[i].inertia_kgm2) << i;
    EXPECT_NEAR(read.links[i].lower_rad, arm.links[i].lower_rad, 1e-15) << i;  // through degrees
    EXPECT_EQ(read.links[i].armature_kgm2, arm.links[i].armature_kgm2) << i;
  }
  EXPECT_EQ(read.gripper.position_link7_m, arm.gripper.position_link7_m);
  EXPECT_FALSE(load_scenario_file(kSync, {}).scenario->chaser.arm.has_value());  // optional
}

struct BadArm {
  const char* label;
  std::vector<std::string> overrides;
  const char* key_path;
  const char* fragment;
};

model::ArmParams with(void (*edit)(model::ArmParams&)) {
  model::ArmParams arm = model::default_arm();
  edit(arm);
  return arm;
}

std::vector<BadArm> bad_arms() {
  const model::ArmParams arm = model::default_arm();
  return {
      {"six_links", {arm_yaml(arm, "{joint_position_m: [0,0,0], joint_axis: [1,0,0], mass_kg: 1, com_m: [0,0,0], "
                                   "inertia_kgm2: [1,1,1], lower_deg: -10, upper_deg: 10, friction_Nm: 0, "
                                   "damping_Nms: 0, armature_kgm2: 0}")},
       "chaser.arm.links", "must be a list of 7 links, base to tip"},
      {"link_inertia", {arm_yaml(with([](model::ArmParams& a) { a.links[2].inertia_kgm2 = Vec3(1, 1, 3); }))},
       "chaser.arm.links.2.inertia_kgm2", "violate the triangle inequality"},
      {"limits_unordered", {arm_yaml(with([](model::ArmParams& a) { a.links[3].upper_rad = a.links[3].lower_rad; }))},
       "chaser.arm.links.3.upper_deg", "must be greater than lower_deg"},
      {"massless_link", {arm_yaml(with([](model::ArmParams& a) { a.links[1].mass_kg = 0.0; }))},
       "chaser.arm.links.1.mass_kg", "must be in (0, 10000] (got 0)"},
      {"friction", {arm_yaml(with([](model::ArmParams& a) { a.links[5].friction_Nm = 200.0; }))},
       "chaser.arm.links.5.friction_Nm", "must be less than torque_repeated_peak_Nm 176"},
      {"torques", {arm_yaml(with([](model::ArmParams& a) { a.torque_repeated_peak_Nm = 400.0; }))},
       "chaser.arm.torque_repeated_peak_Nm", "must be at most torque_momentary_Nm 314 (got 400)"},
      {"torque_loop", {arm_yaml(with([](model::ArmParams& a) { a.torque_loop_bandwidth_radps = 5000.0; }))},
       "chaser.arm.torque_loop_bandwidth_radps", "must be in [1, 1000] (got 5000)"},
      {"gripper_inertia", {arm_yaml(with([](model::ArmParams& a) { a.gripper.inertia_kgm2 = Vec3(0.1, 0.1, 1.0); }))},
       "chaser.arm.gripper.inertia_kgm2", "violate the triangle inequality"},
      {"out_of_reach", {arm_yaml(with([](model::ArmParams& a) { a.mount_body_m = Vec3(-1.05, 0.0, 0.0); }))},
       "chaser.arm", "cannot reach the fixture from the capture point: joint 1 is 4.55 m"},
      {"fixture_inside", {arm_yaml(arm), "target.body.grasp_point_target_m=[3.0, 0.0, 0.6]"},
       "target.body.grasp_point_target_m", "must lie on the target's surface (target.body.keep_out) to within 0.05 m"},
  };
}

class BadArmCase : public ::testing::TestWithParam<BadArm> {};

TEST_P(BadArmCase, ReportsOneErrorAtItsKeyPath) {
  const BadArm& c = GetParam();
  const LoadResult r = load_scenario_file(kSync, c.overrides);
  EXPECT_FALSE(r.scenario.has_value());
  EXPECT_TRUE(has_error(r, c.key_path, c.fragment));
  EXPECT_EQ(r.errors.size(), 1u) << format_errors(r.errors);
}

INSTANTIATE_TEST_SUITE_P(Rules, BadArmCase, ::testing::ValuesIn(bad_arms()),
                         [](const auto& info) { return std::string(info.param.label); });

// An arm serves a capture: on MSR's line (no target body, no synchronised guidance) it is told so.
TEST(ArmSection, AnArmWithoutACaptureIsRefused) {
  const LoadResult r = testing::load_msr({arm_yaml(model::default_arm())});
  EXPECT_TRUE(has_error(r, "chaser.arm", "needs target.body")) << format_errors(r.errors);
  EXPECT_EQ(r.errors.size(), 1u) << format_errors(r.errors);
}

}  // namespace
}  // namespace chaser::io
