// The thruster management function (flight/thruster_management.hpp) with an active check's test
// pulse: the pulse rides on the allocation without changing the commanded wrench.
#include "flight/thruster_management.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "core/random.hpp"
#include "flight/norm_allocation.hpp"
#include "model/thruster_geometry.hpp"
#include "tests/support/msr_branch_a.hpp"

namespace chaser::flight {
namespace {

constexpr model::ThrusterMask kBranchA = 0x00FFU;

// MSR's branch A with no valve minimum (min_on_fraction 0), so that the allocation's answer is the
// command: the pulse's cancellation is then exact up to rounding.
ThrusterManagementParams msr_management() {
  ThrusterManagementParams p;
  p.thrusters = testing::msr_branch_a_thrusters();
  p.min_on_fraction = 0.0;
  return p;
}

// Attainable demands: M t for on-times t in [0, 0.4], so that a 0.05 floor leaves room.
Vec6 attainable_demand(RandomStream& rng, const ThrusterManagementState& s) {
  AllocationTon t = AllocationTon::Zero();
  for (int i = 0; i < 8; ++i) t[i] = rng.uniform(0.0, 0.4);
  return s.allocation.config.leftCols<8>() * t.head<8>();
}

// For every thruster as the one checked and 100 random attainable demands (the zero demand among
// them): the command carries the pulse (on-time >= its floor), its wrench M ton equals the unchecked
// command's to rounding (1e-12 of the largest column entry, ~5e-11 N), and it costs at least as much.
TEST(ThrusterManagement, TestPulseLeavesTheCommandedWrenchUnchanged) {
  const ThrusterManagementParams p = msr_management();
  ThrusterManagementState checked, unchecked;
  set_active_thrusters(p, checked, kBranchA);
  set_active_thrusters(p, unchecked, kBranchA);
  const double scale = checked.allocation.config.cwiseAbs().maxCoeff();
  RandomStream rng(20, "test/management/test-pulse");
  for (int k = 0; k < 100; ++k) {
    const Vec6 demand = k == 0 ? Vec6::Zero() : attainable_demand(rng, checked);
    for (int thruster = 0; thruster < 8; ++thruster) {
      model::ThrusterOnTimes ton_checked{}, ton_unchecked{};
      const ThrusterManagementOutput a =
          manage_thrusters(p, checked, demand, ton_checked, {.thruster = thruster, .on_fraction = 0.05});
      const ThrusterManagementOutput b = manage_thrusters(p, unchecked, demand, ton_unchecked);
      ASSERT_EQ(a.pulsed, thruster) << k;
      EXPECT_EQ(b.pulsed, model::kNoThruster);
      EXPECT_GE(ton_checked[static_cast<std::size_t>(thruster)], 0.05) << k;
      EXPECT_LE((a.commanded_wrench - b.commanded_wrench).cwiseAbs().maxCoeff(), 1e-12 * scale) << k << " T" << thruster + 1;
      double sum_checked = 0, sum_unchecked = 0;
      for (int i = 0; i < 8; ++i) sum_checked += ton_checked[static_cast<std::size_t>(i)], sum_unchecked += ton_unchecked[static_cast<std::size_t>(i)];
      EXPECT_GE(sum_checked, sum_unchecked - 1e-12) << k;
    }
  }
}

// A pulse on a thruster outside the active set, or one that would make the demand unattainable, is
// not fired: the command is then the unchecked one, bit for bit.
TEST(ThrusterManagement, TestPulseIsSkippedOutsideTheSetAndWhenTheDemandIsAtTheLimit) {
  const ThrusterManagementParams p = msr_management();
  ThrusterManagementState s, t;  // two states, so that both calls solve cold
  set_active_thrusters(p, s, kBranchA & ~model::thruster_bit(3));  // T4 removed by a recovery
  set_active_thrusters(p, t, kBranchA & ~model::thruster_bit(3));
  const Vec6 demand = s.allocation.config.col(0) * 0.3;
  model::ThrusterOnTimes with{}, without{};
  EXPECT_EQ(manage_thrusters(p, s, demand, with, {.thruster = 3, .on_fraction = 0.05}).pulsed, model::kNoThruster);
  manage_thrusters(p, t, demand, without);
  EXPECT_EQ(with[3], 0.0);
  EXPECT_EQ(std::memcmp(with.data(), without.data(), sizeof(double) * 8), 0);

  // Beyond what the set can do, the allocation is a best effort (not the demand): no pulse then.
  ThrusterManagementState a, b;
  set_active_thrusters(p, a, kBranchA);
  set_active_thrusters(p, b, kBranchA);
  const Vec6 beyond = a.allocation.config.col(0) * 1000.0;
  model::ThrusterOnTimes checked{}, unchecked{};
  const ThrusterManagementOutput out = manage_thrusters(p, a, beyond, checked, {.thruster = 4, .on_fraction = 0.05});
  manage_thrusters(p, b, beyond, unchecked);
  EXPECT_FALSE(out.feasible);
  EXPECT_EQ(out.pulsed, model::kNoThruster);
  EXPECT_EQ(std::memcmp(checked.data(), unchecked.data(), sizeof(double) * 8), 0);
}

}  // namespace
}  // namespace chaser::flight

namespace chaser::flight {
namespace {

// The TMF flies the scenario's norm (flight/norm_allocation.hpp): its command is that norm's
// allocation, written by thruster index, and realises the same wrench whatever the norm.
TEST(ThrusterManagement, FliesTheChosenNorm) {
  RandomStream rng(18, "test/management/norm");
  for (const model::AllocationNorm norm :
       {model::AllocationNorm::kOne, model::AllocationNorm::kTwo, model::AllocationNorm::kInfinity}) {
    ThrusterManagementParams p = msr_management();
    p.norm = norm;
    ThrusterManagementState s;
    set_active_thrusters(p, s, kBranchA);
    AllocationWarmStart warm;  // evolves like the TMF's own: the same calls in the same order
    for (int k = 0; k < 50; ++k) {
      const Vec6 demand = attainable_demand(rng, s);
      model::ThrusterOnTimes ton{};
      const ThrusterManagementOutput out = manage_thrusters(p, s, demand, ton);
      const AllocationResult expected = allocate_thrusters(s.allocation, demand, norm, warm);
      for (int i = 0; i < 8; ++i) EXPECT_EQ(ton[static_cast<std::size_t>(i)], expected.ton[i]) << k;
      EXPECT_TRUE(out.feasible);
      EXPECT_LE((out.commanded_wrench - demand).cwiseAbs().maxCoeff(), 1e-10) << k;
    }
  }
}

// Two 22 N thrusters on each face of a 2 m bus, pushing inwards (tests/sim/exclude_recovery_test.cpp's
// layout): every set without one of them still pushes and turns everywhere.
model::ThrusterSetParams twelve_on_six_faces() {
  const Vec3 positions_m[12] = {{1, 0.5, 0},  {1, -0.5, 0},  {-1, 0, 0.5},  {-1, 0, -0.5}, {0, 0.8, 0.5},  {0, 0.8, -0.5},
                                {0.5, -0.8, 0}, {-0.5, -0.8, 0}, {0.5, 0, 0.8}, {-0.5, 0, 0.8}, {0, 0.5, -0.8}, {0, -0.5, -0.8}};
  const Vec3 directions[6] = {-Vec3::UnitX(), Vec3::UnitX(), -Vec3::UnitY(), Vec3::UnitY(), -Vec3::UnitZ(), Vec3::UnitZ()};
  model::ThrusterSetParams set;
  set.count = 12;
  for (int i = 0; i < 12; ++i) set.thrusters[static_cast<std::size_t>(i)] = {positions_m[i], directions[i / 2], 22.0};
  return set;
}

// T3 excluded and stuck open (on-time 1): for 100 random attainable demands the eleven others give the
// demand less T3's wrench, so that with it the vehicle gets the demand (to 1e-9 of a thruster's
// column, the LP's tolerance), and T3 is commanded nothing; with the default (least-propellant) norm
// the cancellation is spread (least peak): no thruster commanded the whole period. A thruster
// recorded with on-time 0 cancels nothing.
TEST(ThrusterManagement, AnExcludedStuckOpenThrusterIsCancelled) {
  ThrusterManagementParams p;
  p.thrusters = twelve_on_six_faces();
  ThrusterManagementState s;
  set_active_thrusters(p, s, 0x0FFFu & ~model::thruster_bit(2));
  set_uncommanded_thrust(p, s, 2, 1.0);
  const Vec6 t3 = model::configuration_matrix(p.thrusters, model::thruster_bit(2), p.com_body_m).col(0);
  EXPECT_LE((s.uncommanded_wrench - t3).norm(), 1e-15);
  RandomStream rng(21, "test/management/exclude");
  for (int k = 0; k < 100; ++k) {
    Vec6 demand = Vec6::Zero();
    if (k > 0)
      for (int i = 0; i < 6; ++i) demand[i] = rng.uniform(-5.0, 5.0);  // [N; N m], well inside the authority
    model::ThrusterOnTimes ton{};
    const ThrusterManagementOutput out = manage_thrusters(p, s, demand, ton);
    ASSERT_TRUE(out.feasible) << k;
    EXPECT_LE((out.commanded_wrench - demand).cwiseAbs().maxCoeff(), 1e-9 * 22.0) << k;
    Vec6 active_part = Vec6::Zero();
    for (int i = 0; i < 12; ++i)
      active_part += ton[static_cast<std::size_t>(i)] *
                     model::configuration_matrix(p.thrusters, model::thruster_bit(i), p.com_body_m).col(0);
    EXPECT_LE((active_part + t3 - demand).cwiseAbs().maxCoeff(), 1e-9 * 22.0) << k;
    EXPECT_EQ(ton[2], 0.0);
    EXPECT_LT(*std::max_element(ton.begin(), ton.begin() + 12), 1.0) << k;
  }
  set_uncommanded_thrust(p, s, 2, 0.0);
  EXPECT_EQ(s.uncommanded_thruster, model::kNoThruster);
  model::ThrusterOnTimes ton{};
  EXPECT_LE(manage_thrusters(p, s, Vec6::Zero(), ton).commanded_wrench.norm(), 1e-12);
}

}  // namespace
}  // namespace chaser::flight
