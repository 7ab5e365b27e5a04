// The view's data: the track's decimation keeps every event's rows and draws every dropped row
// within its stated tolerance; the events are found where the telemetry puts them.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "view/replay_events.hpp"
#include "view/replay_track.hpp"
#include "view/run_files.hpp"

namespace {

using chaser::Quat;
using chaser::Vec3;
using namespace chaser::view;

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

// A track at 10 Hz: an approach along -y with a sinusoidal weave and a slow tumble, and a jolt at
// t = 40 s (an attitude kick a decimation must not smooth over).
ReplayTrack synthetic_track(int rows) {
  ReplayTrack k;
  for (int i = 0; i < rows; ++i) {
    const double t = 0.1 * i;
    k.t_s.push_back(t);
    k.r_lvlh_m.push_back(Vec3(0.3 * std::sin(0.05 * t), -30.0 + 0.2 * t, 0.1 * std::cos(0.11 * t)));
    const double kick = t >= 40.0 ? 5.0 * kDegToRad : 0.0;
    k.q_lvlh_from_body.push_back(Quat(Eigen::AngleAxisd(0.02 * t + kick, Vec3(0.0, 0.6, 0.8))));
    k.q_lvlh_from_target.push_back(Quat(Eigen::AngleAxisd(0.0436 * t, Vec3::UnitY())));
    k.r_ref_lvlh_m.push_back(Vec3(0.0, -30.0 + 0.2 * t, 0.0));
    k.attitude_error_rad.push_back(0.0);
  }
  return k;
}

double angle(const Quat& a, const Quat& b) { return 2.0 * std::acos(std::min(1.0, std::abs(a.dot(b)))); }

TEST(ViewDecimation, DroppedRowsAreDrawnWithinTheToleranceAndForcedRowsAreKept) {
  const ReplayTrack k = synthetic_track(1200);
  const DecimationTolerance tol;
  const std::vector<std::size_t> forced{37, 399, 400, 777};
  const std::vector<std::size_t> kept = decimate(k, tol, forced);
  ASSERT_GE(kept.size(), 2U);
  EXPECT_EQ(kept.front(), 0U);
  EXPECT_EQ(kept.back(), 1199U);
  for (std::size_t f : forced) EXPECT_TRUE(std::binary_search(kept.begin(), kept.end(), f)) << "row " << f;
  EXPECT_TRUE(std::is_sorted(kept.begin(), kept.end()));
  // Every row, dropped or not, drawn from its kept neighbours as the page draws it.
  double worst_position = 0.0, worst_attitude = 0.0;
  for (std::size_t s = 0; s + 1 < kept.size(); ++s) {
    EXPECT_LE(k.t_s[kept[s + 1]] - k.t_s[kept[s]], tol.max_gap_s + 1e-9);
    for (std::size_t r = kept[s]; r <= kept[s + 1]; ++r) {
      const double t = k.t_s[r];
      worst_position = std::max(worst_position, (lerp_position(k.r_lvlh_m, kept[s], kept[s + 1], t, k.t_s) - k.r_lvlh_m[r]).norm());
      worst_attitude = std::max(worst_attitude, angle(slerp_attitude(k.q_lvlh_from_body, kept[s], kept[s + 1], t, k.t_s), k.q_lvlh_from_body[r]));
      worst_attitude = std::max(worst_attitude, angle(slerp_attitude(k.q_lvlh_from_target, kept[s], kept[s + 1], t, k.t_s), k.q_lvlh_from_target[r]));
    }
  }
  EXPECT_LE(worst_position, tol.position_m);
  EXPECT_LE(worst_attitude, tol.attitude_rad);
  // Smooth motion needs far fewer rows than the telemetry has; the kick at 40 s is kept on both sides.
  EXPECT_LT(kept.size(), 1200U / 4) << kept.size() << " rows kept";
  EXPECT_TRUE(std::binary_search(kept.begin(), kept.end(), 399U) && std::binary_search(kept.begin(), kept.end(), 400U));
}

TEST(ViewDecimation, ATighterToleranceKeepsMoreRows) {
  const ReplayTrack k = synthetic_track(1200);
  DecimationTolerance loose, tight;
  tight.position_m = 0.0005;
  tight.attitude_rad = 0.0002;
  EXPECT_GT(decimate(k, tight, {}).size(), decimate(k, loose, {}).size());
}

TEST(ViewDecimation, TheArmsWakingIsKeptAndItsPointsAreWithinTolerance) {
  ReplayTrack k = synthetic_track(600);
  for (int i = 0; i < 600; ++i) {
    if (i < 250) {
      k.arm.emplace_back(std::nullopt);
      continue;
    }
    ArmFigure f;
    for (int p = 0; p < kArmPoints; ++p) f[static_cast<std::size_t>(p)] = Vec3(0.3 * p, std::sin(0.01 * i * (p + 1)), 0.0);
    k.arm.emplace_back(f);
  }
  const DecimationTolerance tol;
  const std::vector<std::size_t> kept = decimate(k, tol, {});
  EXPECT_TRUE(std::binary_search(kept.begin(), kept.end(), 249U));
  EXPECT_TRUE(std::binary_search(kept.begin(), kept.end(), 250U));
  for (std::size_t s = 0; s + 1 < kept.size(); ++s) {
    const std::size_t a = kept[s], b = kept[s + 1];
    if (!k.arm[a]) continue;
    for (std::size_t r = a; r <= b; ++r) {
      const double f = (k.t_s[r] - k.t_s[a]) / (k.t_s[b] - k.t_s[a]);
      for (std::size_t p = 0; p < kArmPoints; ++p)
        EXPECT_LE(((*k.arm[a])[p] + f * ((*k.arm[b])[p] - (*k.arm[a])[p]) - (*k.arm[r])[p]).norm(), tol.position_m);
    }
  }
}

// LVLH turns about z at n: a body fixed in LVLH turns at n in the inertial frame, and reads still.
TEST(ViewTrack, AttitudesAreTurnedIntoLvlh) {
  chaser::sim::TelemetryRows rows;
  rows.channels = {"t_s", "r_lvlh_x_m", "r_lvlh_y_m", "r_lvlh_z_m", "q_inertial_from_body_w", "q_inertial_from_body_x",
                   "q_inertial_from_body_y", "q_inertial_from_body_z", "q_inertial_from_target_w", "q_inertial_from_target_x",
                   "q_inertial_from_target_y", "q_inertial_from_target_z"};
  const double n = 1.1e-4;  // [rad/s] LVLH turns 0.54 rad over the 4,900 s
  const Quat q_lvlh_from_body(Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, 3.0).normalized()));
  for (int i = 0; i < 50; ++i) {
    const double t = 100.0 * i;
    const Quat q = q_inertial_from_lvlh(n, t) * q_lvlh_from_body;
    auto row = rows.new_row();
    const double values[] = {t, 1.0, 2.0, 3.0, q.w(), q.x(), q.y(), q.z(), 1.0, 0.0, 0.0, 0.0};
    std::copy(std::begin(values), std::end(values), row.begin());
  }
  const ReplayTrack k = replay_track(rows, n, "telemetry.csv");
  for (const Quat& q : k.q_lvlh_from_body) EXPECT_LT(angle(q, q_lvlh_from_body), 1e-9);
  EXPECT_NEAR(angle(k.q_lvlh_from_target.back(), Quat::Identity()), n * 4900.0, 1e-9);
  EXPECT_TRUE(std::isnan(k.r_ref_lvlh_m[0].x()));  // no reference channels
  EXPECT_TRUE(k.arm.empty());
}

TEST(ViewTrack, AMissingChannelIsNamed) {
  chaser::sim::TelemetryRows rows;
  rows.channels = {"t_s", "r_lvlh_x_m", "r_lvlh_y_m", "r_lvlh_z_m"};
  rows.new_row()[0] = 0.0;
  try {
    replay_track(rows, 0.0, "run/telemetry.csv");
    FAIL() << "no error";
  } catch (const ViewInputError& e) {
    EXPECT_NE(std::string(e.what()).find("run/telemetry.csv"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("q_inertial_from_body"), std::string::npos) << e.what();
  }
}

TEST(ViewEvents, AlarmsIsolationsRecoveriesFaultsAndPhasesAtTheirTimes) {
  chaser::sim::TelemetryRows rows;
  rows.channels = {"t_s", "alarm_attitude", "confirmed_attitude", "active_thrusters"};
  for (int i = 0; i < 100; ++i) {
    const double t = 0.1 * i;
    auto row = rows.new_row();
    row[0] = t;
    row[1] = (i >= 30 && i < 40) || i >= 70 ? 1.0 : 0.0;  // two alarms: 3.0 s and 7.0 s
    row[2] = i >= 45 ? 8.0 : 0.0;                          // T8 isolated at 4.5 s
    row[3] = i >= 46 ? static_cast<double>(0xFF00U) : static_cast<double>(0x00FFU);  // recovery at 4.6 s
  }
  const nlohmann::json summary = {
      {"faults", {{{"thruster", "T8"}, {"kind", "stuck_open"}, {"onset_s", 2.5}}}},
      {"phases_flown", {{{"name", "line"}, {"start_s", 0.0}}, {{"name", "hold"}, {"start_s", 5.0}}}}};
  const std::vector<ReplayEvent> events = replay_events(rows, summary);
  std::vector<std::pair<double, std::string>> seen;
  for (const ReplayEvent& e : events) seen.emplace_back(e.t_s, e.kind);
  const std::vector<std::pair<double, std::string>> expected{{0.0, "phase"},     {2.5, "fault"},    {3.0, "alarm"},
                                                             {4.5, "isolation"}, {4.6, "recovery"}, {5.0, "phase"},
                                                             {7.0, "alarm"}};
  ASSERT_EQ(seen.size(), expected.size());
  for (std::size_t i = 0; i < seen.size(); ++i) {
    EXPECT_NEAR(seen[i].first, expected[i].first, 1e-9) << i;
    EXPECT_EQ(seen[i].second, expected[i].second) << i;
  }
  EXPECT_EQ(events[1].thruster, 7);  // T8's index
  EXPECT_EQ(events[3].thruster, 7);
  EXPECT_EQ(events[4].label, "recovery: T9, T10, T11, T12, T13, T14, T15, T16 in; T1, T2, T3, T4, T5, T6, T7, T8 out");
}

// A capture's and a berthing's steps, from summary.json's reach; a step not reached (null) is none.
TEST(ViewEvents, TheCapturesStepsFromTheSummary) {
  chaser::sim::TelemetryRows rows;
  rows.channels = {"t_s"};
  rows.new_row()[0] = 0.0;
  const nlohmann::json summary = {{"reach",
                                   {{"hold_from_s", 10.0},
                                    {"grasp", {{"closure_s", 12.0}, {"lock_s", 12.5}}},
                                    {"rigidisation", {{"brakes_s", 20.0}}},
                                    {"stabilisation", {{"below_goal_s", nullptr}}},
                                    {"berthing", {{"soft_dock_s", 13.0}, {"hard_dock_s", 30.0}}}}}};
  std::vector<std::pair<double, std::string>> seen;
  for (const ReplayEvent& e : replay_events(rows, summary)) seen.emplace_back(e.t_s, e.label);
  const std::vector<std::pair<double, std::string>> expected{
      {10.0, "reach: gripper over the hold"}, {12.0, "capture: jaws closed"},
      {12.5, "capture: gripper locked"},      {13.0, "berthing: soft dock (latches)"},
      {20.0, "rigidisation: brakes engaged"}, {30.0, "berthing: hard dock (pins)"}};
  EXPECT_EQ(seen, expected);
}

}  // namespace
