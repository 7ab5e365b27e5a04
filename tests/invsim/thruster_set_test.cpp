#include "invsim/thruster_set.hpp"

#include <gtest/gtest.h>

#include "io/invsim_loader.hpp"

namespace chaser::invsim {
namespace {

model::InvSimParams scenario() {
  const io::InvSimLoadResult loaded = io::load_invsim_file("scenarios/manual_rvd.yaml");
  EXPECT_TRUE(loaded.errors.empty()) << io::format_errors(loaded.errors);
  return *loaded.params;
}

std::size_t index_of(const model::InvSimParams& p, const char* name) {
  const auto i = find_thruster(p, name);
  EXPECT_TRUE(i.has_value()) << name;
  return i.value_or(0);
}

// Zhou 2018, Table 1, row by row: the switching signal of every thruster for commands 0, +1, -1 on
// its own axis (translation thrusters for the pilot's command, attitude thrusters for the
// attitude controller's).
TEST(ThrusterSet, SwitchingLogicReproducesTable1) {
  const model::InvSimParams p = scenario();
  struct Row { const char* name; int axis; bool attitude; int on_plus; int on_minus; };
  const Row table1[] = {
      {"a", 0, true, 1, -1},   {"a~", 0, true, -1, 1},  {"b", 1, true, -1, 1},
      {"b~", 1, true, 1, -1},  {"c", 2, true, 1, -1},   {"c~", 2, true, -1, 1},
      {"d1", 0, false, 1, 0},  {"d2", 0, false, 1, 0},  {"d1~", 0, false, 0, 1},
      {"d2~", 0, false, 0, 1}, {"e1", 1, false, 0, 1},  {"e2", 1, false, 0, 1},
      {"e1~", 1, false, 1, 0}, {"e2~", 1, false, 1, 0}, {"f1", 2, false, 1, 0},
      {"f2", 2, false, 1, 0},  {"f1~", 2, false, 0, 1}, {"f2~", 2, false, 0, 1},
  };
  for (const Row& row : table1) {
    const model::InvSimThruster& t = p.thrusters[index_of(p, row.name)];
    for (int cmd : {0, 1, -1}) {
      std::array<int, 3> translation{0, 0, 0}, attitude{0, 0, 0};
      (row.attitude ? attitude : translation)[row.axis] = cmd;
      const int expected = cmd == 0 ? 0 : (cmd == 1 ? row.on_plus : row.on_minus);
      EXPECT_EQ(switching_signal(t, translation, attitude), expected) << row.name << " cmd " << cmd;
      // No thruster answers another axis' command.
      std::array<int, 3> other{0, 0, 0};
      other[(row.axis + 1) % 3] = cmd;
      EXPECT_EQ(switching_signal(t, other, other), 0) << row.name;
    }
  }
  EXPECT_EQ(switching_signal(p.thrusters[index_of(p, "engine")], {1, 1, 1}, {1, 1, 1}), 0);
}

// A healthy group gives a pure force along its axis (the pairs' moments cancel) and a healthy
// attitude couple a pure torque about its axis: nominal flight is undisturbed. 1e-12: sums of
// a few products of exact decimal inputs.
TEST(ThrusterSet, HealthyGroupsArePureForcesAndCouples) {
  const model::InvSimParams p = scenario();
  for (int axis = 0; axis < 3; ++axis) {
    for (int d : {1, -1}) {
      const Wrench t = translation_wrench(p, {}, axis, d);
      EXPECT_NEAR(t.force_body_N(axis), d * 120.0, 1e-12);
      EXPECT_LT((t.force_body_N - t.force_body_N(axis) * Vec3::Unit(axis)).norm(), 1e-12);
      EXPECT_LT(t.torque_body_Nm.norm(), 1e-12);
      const Wrench a = attitude_wrench(p, {}, axis, d);
      EXPECT_LT(a.force_body_N.norm(), 1e-12);
      EXPECT_GT(d * a.torque_body_Nm(axis), 0.0);
      EXPECT_LT((a.torque_body_Nm - a.torque_body_Nm(axis) * Vec3::Unit(axis)).norm(), 1e-12);
    }
    EXPECT_NEAR(nominal_translation_accel(p, axis, 1), 120.0 / p.mass_kg, 1e-15);
  }
}

// Zhou 2018, Table 6 header: the disturbing yaw moment each lost x or y thruster leaves
// (d1: Mz+, d1~: Mz-, d2: Mz-, d2~: Mz+, e1: Mz-, e1~: Mz+, e2: Mz+, e2~: Mz-), and it is what the
// faulty group actually produces when it fires.
TEST(ThrusterSet, LostThrustersLeaveTable6Moments) {
  const model::InvSimParams p = scenario();
  const std::pair<const char*, int> table6[] = {{"d1", 1}, {"d1~", -1}, {"d2", -1}, {"d2~", 1},
                                                {"e1", -1}, {"e1~", 1}, {"e2", 1}, {"e2~", -1}};
  for (const auto& [name, sign] : table6) {
    const std::size_t i = index_of(p, name);
    const Vec3 m = fault_disturbing_moment(p, i);
    EXPECT_GT(sign * m.z(), 0.0) << name;
    EXPECT_NEAR(m.x(), 0.0, 1e-12) << name;
    EXPECT_NEAR(m.y(), 0.0, 1e-12) << name;
    model::InvSimFaultSet faults;
    faults.failed_mask = std::uint64_t{1} << i;
    const model::InvSimThruster& t = p.thrusters[i];
    const Wrench w = translation_wrench(p, faults, t.axis, t.sign);
    EXPECT_LT((w.torque_body_Nm - m).norm(), 1e-12) << name;
    EXPECT_NEAR(std::abs(w.force_body_N(t.axis)), 60.0, 1e-12) << name;  // half the group
  }
}

// A z thruster lost disturbs roll and pitch (section 3.3), not yaw.
TEST(ThrusterSet, LostZThrusterDisturbsRollAndPitch) {
  const model::InvSimParams p = scenario();
  for (const char* name : {"f1", "f2", "f1~", "f2~"}) {
    const Vec3 m = fault_disturbing_moment(p, index_of(p, name));
    EXPECT_GT(std::abs(m.x()), 1.0) << name;
    EXPECT_GT(std::abs(m.y()), 1.0) << name;
    EXPECT_NEAR(m.z(), 0.0, 1e-12) << name;
  }
}

}  // namespace
}  // namespace chaser::invsim
