#include "sim/telemetry_channels.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <variant>

#include <fmt/format.h>

#include "core/rotation.hpp"
#include "sim/run_phases.hpp"

namespace chaser::sim {

namespace {

using Value = double (*)(const PeriodRecord&, int);
using Channels = std::vector<TelemetryChannel>;

// "base_unit", or "base" for a dimensionless quantity.
std::string with_unit(const std::string& base, const char* unit) {
  return *unit ? fmt::format("{}_{}", base, unit) : base;
}

void scalar(Channels& t, const char* base, const char* unit, Value v) { t.push_back({with_unit(base, unit), unit, v, 0}); }

void vec3(Channels& t, const char* base, const char* unit, Value v) {
  for (int i = 0; i < 3; ++i) t.push_back({with_unit(fmt::format("{}_{}", base, "xyz"[i]), unit), unit, v, i});
}

void quat(Channels& t, const char* base, Value v) {
  for (int i = 0; i < 4; ++i) t.push_back({fmt::format("{}_{}", base, "wxyz"[i]), "", v, i});
}

// Quaternion component i of (w, x, y, z).
double component(const Quat& q, int i) { return i == 0 ? q.w() : q.vec()[i - 1]; }

// A lane of the watched set as a thruster number 1..N in telemetry, 0 for none.
double thruster_number(const PeriodRecord& r, int lane) {
  return model::thruster_number(lane >= 0 ? r.watched->index[static_cast<std::size_t>(lane)] : model::kNoThruster);
}

// A diagnosis scheme's outputs, by its slot (flight/diagnosis_schemes.hpp).
const flight::fdi::FdiSchemeOutput& scheme(const PeriodRecord& r, int s) {
  return r.flight->fdir.schemes[static_cast<std::size_t>(s)];
}

// The residual channels of a scheme (up to three components) pack the scheme in the index: 3 s + i.
void fdi_scheme(Channels& t, const flight::DiagnosisScheme& d, int s) {
  const std::string& name = d.name;
  for (int i = 0; i < d.residual_channels; ++i)
    t.push_back({fmt::format("residual_{}_{}", name, i + 1), "",
                 [](const PeriodRecord& r, int k) { return scheme(r, k / 3).residual[k % 3]; }, 3 * s + i});
  t.push_back({fmt::format("glr_{}", name), "", [](const PeriodRecord& r, int k) { return scheme(r, k).glr.value(); }, s});
  t.push_back({fmt::format("alarm_{}", name), "",
               [](const PeriodRecord& r, int k) { return scheme(r, k).alarm ? 1.0 : 0.0; }, s});
  t.push_back({fmt::format("candidate_{}", name), "",
               [](const PeriodRecord& r, int k) { return thruster_number(r, scheme(r, k).candidate); }, s});
  t.push_back({fmt::format("confirmed_{}", name), "",
               [](const PeriodRecord& r, int k) { return thruster_number(r, scheme(r, k).confirmed); }, s});
}

}  // namespace

namespace {

// Joint j's angle at the period start (NaN without an arm measurement).
double arm_angle(const PeriodRecord& r, int j) {
  return r.arm != nullptr && r.arm->joints > j ? r.arm->q_rad[static_cast<std::size_t>(j)]
                                               : std::numeric_limits<double>::quiet_NaN();
}

// Joint j's brake load [N m] over the period's last MuJoCo step (0 unbraked, or without the arm awake).
double brake_load(const PeriodRecord& r, int j) {
  const auto* multibody = std::get_if<plant::MultibodyMotionState>(&r.plant->motion);
  return multibody != nullptr ? multibody->brake_load_Nm[static_cast<std::size_t>(j)] : 0.0;
}

// The gripper's 12 values in channel order: error, velocity, attitude error, rate (3 each).
double gripper_value(const PeriodRecord& r, int k) {
  if (r.gripper == nullptr) return std::numeric_limits<double>::quiet_NaN();
  const plant::GripperTruth& g = *r.gripper;
  const Vec3& v = k < 3 ? g.r_m : k < 6 ? g.v_mps : k < 9 ? g.attitude_rad : g.omega_radps;
  return v(k % 3);
}

// The arm's figure's values in channel order: the hub (3), its attitude (w, x, y, z), the joints'
// anchors (3 each), the tool point (3).
constexpr int kFigureValues = 3 + 4 + 3 * model::kArmJoints + 3;
double figure_value(const PeriodRecord& r, int k) {
  if (r.figure == nullptr) return std::numeric_limits<double>::quiet_NaN();
  const plant::ArmFigure& f = *r.figure;
  if (k < 3) return f.hub_m(k);
  if (k < 7) return component(f.q_target_from_hub, k - 3);
  if (k < 7 + 3 * model::kArmJoints) return f.joint_m[static_cast<std::size_t>((k - 7) / 3)]((k - 7) % 3);
  return f.tool_m(k - 7 - 3 * model::kArmJoints);
}

}  // namespace

TelemetryShape telemetry_shape(const model::Scenario& scenario) {
  const auto& slosh = scenario.chaser.slosh;
  return {.thrusters = scenario.thrusters.count,
          .slosh_tanks = slosh ? static_cast<int>(slosh->tanks.size()) : 0,
          .target_estimator = scenario.sensors.target_pose.has_value() && scenario.target.body.has_value(),
          .phases = static_cast<int>(planned_phases(scenario).size()),
          .arm = scenario.capture.has_value() && scenario.chaser.arm.has_value(),
          .supervisor = scenario.fdi.supervisor.enabled};
}

namespace {

// The target estimator against the truth (flight/target_estimator.hpp): the attitude error's angle,
// the rate error's norm (target axes) and the largest attitude sigma; NaN before the first pose.
std::array<double, 3> target_estimate_errors(const PeriodRecord& r) {
  const auto& est = r.flight->target;
  if (!est) return {std::nan(""), std::nan(""), std::nan("")};
  return {rotation_vector_from_quat(r.q_inertial_from_target.conjugate() * est->q_inertial_from_target).norm(),
          (est->omega_target_radps - r.omega_target_body_radps).norm(), est->attitude_sigma_rad.maxCoeff()};
}

}  // namespace

std::vector<TelemetryChannel> telemetry_channels(const TelemetryShape& shape) {
  const int thrusters = shape.thrusters;
  Channels t;
  scalar(t, "t", "s", [](const PeriodRecord& r, int) { return r.t_s; });
  vec3(t, "r_lvlh", "m", [](const PeriodRecord& r, int i) { return r.truth->r_lvlh_m[i]; });
  vec3(t, "v_lvlh", "mps", [](const PeriodRecord& r, int i) { return r.truth->v_lvlh_mps[i]; });
  quat(t, "q_inertial_from_body", [](const PeriodRecord& r, int i) { return component(r.truth->q_inertial_from_body, i); });
  vec3(t, "omega_body", "radps", [](const PeriodRecord& r, int i) { return r.truth->omega_body_radps[i]; });
  quat(t, "q_inertial_from_target", [](const PeriodRecord& r, int i) { return component(r.q_inertial_from_target, i); });
  vec3(t, "omega_target_body", "radps", [](const PeriodRecord& r, int i) { return r.omega_target_body_radps[i]; });
  vec3(t, "r_est_lvlh", "m", [](const PeriodRecord& r, int i) { return r.flight->estimate.r_lvlh_m[i]; });
  vec3(t, "v_est_lvlh", "mps", [](const PeriodRecord& r, int i) { return r.flight->estimate.v_lvlh_mps[i]; });
  quat(t, "q_est_inertial_from_body",
       [](const PeriodRecord& r, int i) { return component(r.flight->estimate.q_inertial_from_body, i); });
  vec3(t, "omega_est_body", "radps", [](const PeriodRecord& r, int i) { return r.flight->estimate.omega_body_radps[i]; });
  vec3(t, "r_ref_lvlh", "m", [](const PeriodRecord& r, int i) { return r.flight->reference.r_lvlh_m[i]; });
  vec3(t, "att_err_body", "rad", [](const PeriodRecord& r, int i) { return r.attitude_error_body_rad[i]; });
  vec3(t, "force_demand_lvlh", "N", [](const PeriodRecord& r, int i) { return r.flight->force_demand_lvlh_N[i]; });
  vec3(t, "torque_demand_body", "Nm", [](const PeriodRecord& r, int i) { return r.flight->torque_demand_body_Nm[i]; });
  vec3(t, "force_cmd_body", "N", [](const PeriodRecord& r, int i) { return r.flight->commanded_wrench[i]; });
  vec3(t, "torque_cmd_body", "Nm", [](const PeriodRecord& r, int i) { return r.flight->commanded_wrench[3 + i]; });
  for (int i = 0; i < thrusters; ++i)
    t.push_back({fmt::format("ton_cmd_{}", i + 1), "",
                 [](const PeriodRecord& r, int k) { return r.flight->command.ton[static_cast<std::size_t>(k)]; }, i});
  for (int i = 0; i < thrusters; ++i)
    t.push_back({fmt::format("ton_real_{}", i + 1), "",
                 [](const PeriodRecord& r, int k) { return r.plant->last_profile.ton_realised[static_cast<std::size_t>(k)]; },
                 i});
  const std::vector<flight::DiagnosisScheme>& schemes = flight::diagnosis_schemes();
  for (std::size_t s = 0; s < schemes.size(); ++s) fdi_scheme(t, schemes[s], static_cast<int>(s));
  scalar(t, "over_consumption", "", [](const PeriodRecord& r, int) { return r.flight->fdir.over_consumption ? 1.0 : 0.0; });
  // Exact: a 32-bit mask is an integer below 2^53, which a double holds and the writer round-trips.
  scalar(t, "active_thrusters", "",
         [](const PeriodRecord& r, int) { return static_cast<double>(r.flight_state->thrusters.active); });
  scalar(t, "delay", "s", [](const PeriodRecord& r, int) { return to_seconds(r.plant->last_delay_ns); });
  scalar(t, "mass", "kg", [](const PeriodRecord& r, int) { return r.truth->mass_kg; });
  scalar(t, "propellant_used", "kg", [](const PeriodRecord& r, int) { return r.plant->propellant_used_kg; });
  // Per tank: the index packs the tank and the axis, 3 tank + axis.
  for (int tank = 0; tank < shape.slosh_tanks; ++tank) {
    for (int i = 0; i < 3; ++i)
      t.push_back({fmt::format("slosh{}_s_body_{}_m", tank + 1, "xyz"[i]), "m",
                   [](const PeriodRecord& r, int k) { return r.slosh[static_cast<std::size_t>(k / 3)].s_body_m[k % 3]; },
                   3 * tank + i});
    for (int i = 0; i < 3; ++i)
      t.push_back({fmt::format("slosh{}_s_dot_body_{}_mps", tank + 1, "xyz"[i]), "mps",
                   [](const PeriodRecord& r, int k) {
                     return r.slosh[static_cast<std::size_t>(k / 3)].s_dot_body_mps[k % 3];
                   },
                   3 * tank + i});
  }
  if (shape.target_estimator) {
    t.push_back({"target_est_att_err_rad", "rad", [](const PeriodRecord& r, int) { return target_estimate_errors(r)[0]; }, 0});
    t.push_back({"target_est_rate_err_radps", "radps", [](const PeriodRecord& r, int) { return target_estimate_errors(r)[1]; }, 0});
    t.push_back({"target_est_att_sigma_rad", "rad", [](const PeriodRecord& r, int) { return target_estimate_errors(r)[2]; }, 0});
  }
  if (shape.arm) {
    for (int j = 0; j < model::kArmJoints; ++j)
      t.push_back({fmt::format("q_arm_{}_rad", j + 1), "rad", [](const PeriodRecord& r, int k) { return arm_angle(r, k); }, j});
    for (int j = 0; j < model::kArmJoints; ++j)
      t.push_back({fmt::format("tau_arm_{}_Nm", j + 1), "Nm",
                   [](const PeriodRecord& r, int k) { return r.flight_state->reach.joint_torque_Nm(k); }, j});
    for (int j = 0; j < model::kArmJoints; ++j)
      t.push_back({fmt::format("load_arm_{}_Nm", j + 1), "Nm", [](const PeriodRecord& r, int k) { return brake_load(r, k); }, j});
    const std::array<std::pair<const char*, const char*>, 4> gripper = {
        {{"gripper_err_{}_m", "m"}, {"gripper_v_{}_mps", "mps"}, {"gripper_att_err_{}_rad", "rad"}, {"gripper_rate_{}_radps", "radps"}}};
    for (std::size_t g = 0; g < gripper.size(); ++g)
      for (int i = 0; i < 3; ++i)
        t.push_back({fmt::vformat(gripper[g].first, fmt::make_format_args("xyz"[i])), gripper[g].second,
                     [](const PeriodRecord& r, int k) { return gripper_value(r, k); }, 3 * static_cast<int>(g) + i});
    const auto figure = [&t](std::string name, const char* unit, int k) {
      t.push_back({std::move(name), unit, [](const PeriodRecord& r, int i) { return figure_value(r, i); }, k});
    };
    for (int i = 0; i < 3; ++i) figure(fmt::format("hub_target_{}_m", "xyz"[i]), "m", i);
    for (int i = 0; i < 4; ++i) figure(fmt::format("q_target_from_hub_{}", "wxyz"[i]), "", 3 + i);
    for (int j = 0; j < model::kArmJoints; ++j)
      for (int i = 0; i < 3; ++i) figure(fmt::format("joint{}_target_{}_m", j + 1, "xyz"[i]), "m", 7 + 3 * j + i);
    for (int i = 0; i < 3; ++i) figure(fmt::format("tool_target_{}_m", "xyz"[i]), "m", kFigureValues - 3 + i);
  }
  if (shape.phases > 1) t.push_back({"phase", "", [](const PeriodRecord& r, int) { return static_cast<double>(r.phase); }, 0});
  if (shape.supervisor)
    t.push_back({"supervisor_mode", "", [](const PeriodRecord& r, int) { return static_cast<double>(r.flight->supervisor_mode); }, 0});
  return t;
}

std::vector<std::string> channel_names(const std::vector<TelemetryChannel>& channels) {
  std::vector<std::string> names;
  names.reserve(channels.size());
  for (const TelemetryChannel& c : channels) names.push_back(c.name);
  return names;
}

std::vector<TelemetryChannel> select_channels(std::vector<TelemetryChannel> channels,
                                              const std::vector<std::string>& patterns) {
  if (patterns.empty()) return channels;
  std::vector<TelemetryChannel> kept;
  for (TelemetryChannel& c : channels)
    if (c.name == "t_s" || std::any_of(patterns.begin(), patterns.end(),
                                       [&](const std::string& p) { return name_matches(p, c.name); }))
      kept.push_back(std::move(c));
  return kept;
}

std::vector<std::string> unmatched_patterns(const std::vector<TelemetryChannel>& channels,
                                            const std::vector<std::string>& patterns) {
  std::vector<std::string> unmatched;
  for (const std::string& p : patterns)
    if (std::none_of(channels.begin(), channels.end(), [&](const TelemetryChannel& c) { return name_matches(p, c.name); }))
      unmatched.push_back(p);
  return unmatched;
}

bool name_matches(std::string_view pattern, std::string_view name) {
  // '*' any run of characters, '?' one character; iterative with one backtrack point (linear in practice).
  std::size_t p = 0, n = 0, star = std::string_view::npos, resume = 0;
  while (n < name.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == name[n])) {
      ++p, ++n;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++, resume = n;
    } else if (star != std::string_view::npos) {
      p = star + 1, n = ++resume;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

void record_period(const std::vector<TelemetryChannel>& channels, const PeriodRecord& r, double* row) {
  for (std::size_t i = 0; i < channels.size(); ++i) row[i] = channels[i].value(r, channels[i].index);
}

void record_every_channel(const PeriodRecord& r, const TelemetryShape& shape, double* row) {
  const int thrusters = shape.thrusters;
  const auto put3 = [&row](const Vec3& v) { row[0] = v.x(), row[1] = v.y(), row[2] = v.z(), row += 3; };
  const auto put4 = [&row](const Quat& q) { row[0] = q.w(), row[1] = q.x(), row[2] = q.y(), row[3] = q.z(), row += 4; };
  const flight::FlightOutput& f = *r.flight;
  *row++ = r.t_s;
  put3(r.truth->r_lvlh_m);
  put3(r.truth->v_lvlh_mps);
  put4(r.truth->q_inertial_from_body);
  put3(r.truth->omega_body_radps);
  put4(r.q_inertial_from_target);
  put3(r.omega_target_body_radps);
  put3(f.estimate.r_lvlh_m);
  put3(f.estimate.v_lvlh_mps);
  put4(f.estimate.q_inertial_from_body);
  put3(f.estimate.omega_body_radps);
  put3(f.reference.r_lvlh_m);
  put3(r.attitude_error_body_rad);
  put3(f.force_demand_lvlh_N);
  put3(f.torque_demand_body_Nm);
  put3(f.commanded_wrench.head<3>());
  put3(f.commanded_wrench.tail<3>());
  for (int i = 0; i < thrusters; ++i) *row++ = f.command.ton[static_cast<std::size_t>(i)];
  for (int i = 0; i < thrusters; ++i) *row++ = r.plant->last_profile.ton_realised[static_cast<std::size_t>(i)];
  // The three built in with their residuals' fixed sizes (3, 3, 0: the table's, which the channel
  // table reads; the two are tested equal), then any registered scheme.
  const auto put_scheme = [&](const flight::fdi::FdiSchemeOutput& o) {
    *row++ = o.glr.value();
    *row++ = o.alarm ? 1.0 : 0.0;
    *row++ = thruster_number(r, o.candidate);
    *row++ = thruster_number(r, o.confirmed);
  };
  put3(scheme(r, flight::kPositionScheme).residual);
  put_scheme(scheme(r, flight::kPositionScheme));
  put3(scheme(r, flight::kAttitudeScheme).residual);
  put_scheme(scheme(r, flight::kAttitudeScheme));
  put_scheme(scheme(r, flight::kDeficitScheme));
  const std::vector<flight::DiagnosisScheme>& schemes = flight::diagnosis_schemes();
  for (std::size_t s = flight::kDeficitScheme + 1; s < schemes.size(); ++s) {
    const flight::fdi::FdiSchemeOutput& o = scheme(r, static_cast<int>(s));
    for (int i = 0; i < schemes[s].residual_channels; ++i) *row++ = o.residual[i];
    put_scheme(o);
  }
  *row++ = f.fdir.over_consumption ? 1.0 : 0.0;
  *row++ = static_cast<double>(r.flight_state->thrusters.active);
  *row++ = to_seconds(r.plant->last_delay_ns);
  *row++ = r.truth->mass_kg;
  *row++ = r.plant->propellant_used_kg;
  for (int tank = 0; tank < shape.slosh_tanks; ++tank) {
    put3(r.slosh[static_cast<std::size_t>(tank)].s_body_m);
    put3(r.slosh[static_cast<std::size_t>(tank)].s_dot_body_mps);
  }
  if (shape.target_estimator) {
    const std::array<double, 3> e = target_estimate_errors(r);
    *row++ = e[0], *row++ = e[1], *row++ = e[2];
  }
  if (shape.arm) {
    for (int j = 0; j < model::kArmJoints; ++j) *row++ = arm_angle(r, j);
    for (int j = 0; j < model::kArmJoints; ++j) *row++ = r.flight_state->reach.joint_torque_Nm(j);
    for (int j = 0; j < model::kArmJoints; ++j) *row++ = brake_load(r, j);
    for (int k = 0; k < 12; ++k) *row++ = gripper_value(r, k);
    for (int k = 0; k < kFigureValues; ++k) *row++ = figure_value(r, k);
  }
  if (shape.phases > 1) *row++ = static_cast<double>(r.phase);
  if (shape.supervisor) *row++ = static_cast<double>(r.flight->supervisor_mode);
}

}  // namespace chaser::sim
