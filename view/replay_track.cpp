#include "view/replay_track.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <fmt/format.h>

#include "view/run_files.hpp"

namespace chaser::view {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Column indices by name; -1 if absent.
struct Columns {
  const sim::TelemetryRows& rows;
  int find(const std::string& name) const {
    const auto it = std::find(rows.channels.begin(), rows.channels.end(), name);
    return it == rows.channels.end() ? -1 : static_cast<int>(it - rows.channels.begin());
  }
  double at(std::size_t row, int col) const { return col < 0 ? kNaN : rows.values[row * rows.channels.size() + static_cast<std::size_t>(col)]; }
};

std::array<int, 3> vec_columns(const Columns& c, const std::string& base, const char* unit) {
  std::array<int, 3> cols{};
  for (int i = 0; i < 3; ++i) cols[static_cast<std::size_t>(i)] = c.find(fmt::format("{}_{}{}", base, "xyz"[i], unit));
  return cols;
}

std::array<int, 4> quat_columns(const Columns& c, const std::string& base) {
  std::array<int, 4> cols{};
  for (int i = 0; i < 4; ++i) cols[static_cast<std::size_t>(i)] = c.find(fmt::format("{}_{}", base, "wxyz"[i]));
  return cols;
}

template <std::size_t N>
void require(const std::array<int, N>& cols, const std::string& what, const std::string& file) {
  for (int c : cols)
    if (c < 0) throw ViewInputError(fmt::format("{}: no {} channels: a view needs them (a run flown with --channels?)", file, what));
}

Vec3 vec_at(const Columns& c, std::size_t r, const std::array<int, 3>& cols) { return {c.at(r, cols[0]), c.at(r, cols[1]), c.at(r, cols[2])}; }
Quat quat_at(const Columns& c, std::size_t r, const std::array<int, 4>& cols) {
  return Quat(c.at(r, cols[0]), c.at(r, cols[1]), c.at(r, cols[2]), c.at(r, cols[3])).normalized();
}

std::vector<std::array<int, 3>> arm_columns(const Columns& c) {
  std::vector<std::array<int, 3>> cols{vec_columns(c, "hub_target", "_m")};
  for (int j = 1; j <= 7; ++j) cols.push_back(vec_columns(c, fmt::format("joint{}_target", j), "_m"));
  cols.push_back(vec_columns(c, "tool_target", "_m"));
  for (const auto& p : cols)
    if (std::any_of(p.begin(), p.end(), [](int k) { return k < 0; })) return {};
  return cols;
}

double fraction(double t, double ta, double tb) { return tb > ta ? (t - ta) / (tb - ta) : 0.0; }

double angle_between(const Quat& a, const Quat& b) { return 2.0 * std::acos(std::min(1.0, std::abs(a.dot(b)))); }

}  // namespace

Quat q_inertial_from_lvlh(double mean_motion_radps, double t_s) {
  return Quat(Eigen::AngleAxisd(mean_motion_radps * t_s, Vec3::UnitZ()));
}

ReplayTrack replay_track(const sim::TelemetryRows& telemetry, double mean_motion_radps, const std::string& file) {
  const Columns c{telemetry};
  const auto r = vec_columns(c, "r_lvlh", "_m"), r_ref = vec_columns(c, "r_ref_lvlh", "_m"), att = vec_columns(c, "att_err_body", "_rad");
  const auto qb = quat_columns(c, "q_inertial_from_body"), qt = quat_columns(c, "q_inertial_from_target");
  require(r, "r_lvlh_*_m", file);
  require(qb, "q_inertial_from_body_*", file);
  require(qt, "q_inertial_from_target_*", file);
  const auto arm = arm_columns(c);
  ReplayTrack track;
  const std::size_t n = telemetry.rows();
  for (std::size_t i = 0; i < n; ++i) {
    const double t = c.at(i, 0);
    const Quat q_lvlh_from_inertial = q_inertial_from_lvlh(mean_motion_radps, t).conjugate();
    track.t_s.push_back(t);
    track.r_lvlh_m.push_back(vec_at(c, i, r));
    track.q_lvlh_from_body.push_back((q_lvlh_from_inertial * quat_at(c, i, qb)).normalized());
    track.q_lvlh_from_target.push_back((q_lvlh_from_inertial * quat_at(c, i, qt)).normalized());
    track.r_ref_lvlh_m.push_back(vec_at(c, i, r_ref));
    track.attitude_error_rad.push_back(vec_at(c, i, att).norm());
    if (arm.empty()) continue;
    ArmFigure figure;
    bool finite = true;
    for (std::size_t p = 0; p < arm.size(); ++p) {
      figure[p] = vec_at(c, i, arm[p]);
      finite = finite && figure[p].allFinite();
    }
    track.arm.push_back(finite ? std::optional<ArmFigure>(figure) : std::nullopt);
  }
  return track;
}

Vec3 lerp_position(const std::vector<Vec3>& v, std::size_t a, std::size_t b, double t, const std::vector<double>& t_s) {
  const double f = fraction(t, t_s[a], t_s[b]);
  return v[a] + f * (v[b] - v[a]);
}

Quat slerp_attitude(const std::vector<Quat>& q, std::size_t a, std::size_t b, double t, const std::vector<double>& t_s) {
  return q[a].slerp(fraction(t, t_s[a], t_s[b]), q[b]);  // Eigen's slerp takes the shorter arc, as three.js's
}

namespace {

// Whether rows a..b may be drawn from rows a and b alone.
bool within(const ReplayTrack& k, const DecimationTolerance& tol, std::size_t a, std::size_t b) {
  const bool has_arm = !k.arm.empty();
  if (has_arm && k.arm[a].has_value() != k.arm[b].has_value()) return false;
  for (std::size_t i = a + 1; i < b; ++i) {
    const double t = k.t_s[i];
    if ((lerp_position(k.r_lvlh_m, a, b, t, k.t_s) - k.r_lvlh_m[i]).norm() > tol.position_m) return false;
    if (angle_between(slerp_attitude(k.q_lvlh_from_body, a, b, t, k.t_s), k.q_lvlh_from_body[i]) > tol.attitude_rad) return false;
    if (angle_between(slerp_attitude(k.q_lvlh_from_target, a, b, t, k.t_s), k.q_lvlh_from_target[i]) > tol.attitude_rad) return false;
    const Vec3 ref = lerp_position(k.r_ref_lvlh_m, a, b, t, k.t_s);
    if (ref.allFinite() && (ref - k.r_ref_lvlh_m[i]).norm() > tol.position_m) return false;
    if (!has_arm) continue;
    if (k.arm[i].has_value() != k.arm[a].has_value()) return false;
    if (!k.arm[i]) continue;
    const double f = fraction(t, k.t_s[a], k.t_s[b]);
    for (std::size_t p = 0; p < kArmPoints; ++p) {
      const Vec3 drawn = (*k.arm[a])[p] + f * ((*k.arm[b])[p] - (*k.arm[a])[p]);
      if ((drawn - (*k.arm[i])[p]).norm() > tol.position_m) return false;
    }
  }
  return true;
}

}  // namespace

std::vector<std::size_t> decimate(const ReplayTrack& track, const DecimationTolerance& tol,
                                  const std::vector<std::size_t>& forced) {
  const std::size_t n = track.t_s.size();
  std::vector<std::size_t> kept;
  if (n == 0) return kept;
  std::vector<char> must(n, 0);
  must.front() = must.back() = 1;
  for (std::size_t f : forced)
    if (f < n) must[f] = 1;
  kept.push_back(0);
  std::size_t a = 0;
  // Grow the segment from `a` while the rows inside it are drawn within tolerance; keep its last good end.
  for (std::size_t b = 1; b < n; ++b) {
    const bool fits = track.t_s[b] - track.t_s[a] <= tol.max_gap_s && within(track, tol, a, b);
    if (!fits && b - 1 > a) {
      kept.push_back(b - 1);
      a = b - 1;
      --b;  // the same b from the new start
      continue;
    }
    if (!fits || must[b]) {  // b - 1 == a: b must be kept anyway
      kept.push_back(b);
      a = b;
    }
  }
  if (kept.back() != n - 1) kept.push_back(n - 1);
  return kept;
}

}  // namespace chaser::view
