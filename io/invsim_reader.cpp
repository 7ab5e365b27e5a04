// The inverse-simulation scenario (io/invsim_loader.hpp): reading of every section with its type
// and static range, then the checks between keys. Schema in docs/invsim.md.
#include <cmath>
#include <set>
#include <sstream>
#include <string_view>

#include <fmt/format.h>

#include "core/constants.hpp"
#include "io/document_limits.hpp"
#include "io/invsim_loader.hpp"
#include "io/invsim_study_reader.hpp"
#include "io/overrides.hpp"
#include "io/text_file.hpp"
#include "io/yaml_reader.hpp"

namespace chaser::io {
namespace {

using model::InvSimParams;
using model::InvSimThruster;
using model::InvSimThrusterRole;

constexpr double kMaxApproachDurationS = 1e6;  // [s] an approach, not a mission

bool read_axis(MapReader& m, std::string_view key, int& out) {
  std::string text;
  if (!m.text(key, text)) return false;
  if (text == "x" || text == "y" || text == "z") {
    out = text[0] - 'x';
    return true;
  }
  m.diagnostics().add(m.path_of(key), fmt::format("must be x, y or z (got '{}')", text));
  return false;
}

void read_sign(MapReader& m, int& out) {
  double value = 0.0;
  if (!m.number("sign", Range::closed(-1.0, 1.0), value)) return;
  if (value != 1.0 && value != -1.0) {
    m.diagnostics().add(m.path_of("sign"), fmt::format("must be 1 or -1 (got {})", format_number(value)));
    return;
  }
  out = static_cast<int>(value);
}

void read_role(MapReader& m, InvSimThrusterRole& out) {
  std::string text;
  if (!m.text("role", text)) return;
  if (text == "engine") out = InvSimThrusterRole::kEngine;
  else if (text == "attitude") out = InvSimThrusterRole::kAttitude;
  else if (text == "translation") out = InvSimThrusterRole::kTranslation;
  else
    m.diagnostics().add(m.path_of("role"),
                        fmt::format("must be engine, attitude or translation (got '{}')", text));
}

void read_thruster(const YAML::Node& node, const std::string& path, InvSimThruster& out,
                   Diagnostics& diag) {
  MapReader m(node, path, diag);
  m.text("name", out.name);
  read_role(m, out.role);
  read_axis(m, "axis", out.axis);
  read_sign(m, out.sign);
  m.number("thrust_N", Range::positive(), out.thrust_N);
  m.vec3("position_body_m", out.position_body_m);
  m.direction("direction_body", out.direction_body);
  m.finish();
}

void read_thrusters(MapReader& r, InvSimParams& p) {
  const auto list = r.child("thrusters", "a list of thrusters");
  const std::string path = r.path_of("thrusters");
  if (!list) return;
  if (!list->IsSequence() || list->size() == 0 || list->size() > model::kMaxInvSimThrusters) {
    r.diagnostics().add(path, fmt::format("must be a list of 1 to {} thrusters (got {})",
                                          model::kMaxInvSimThrusters, describe_node(*list)));
    return;
  }
  p.thrusters.resize(list->size());
  for (std::size_t i = 0; i < list->size(); ++i)
    read_thruster((*list)[i], join_path(path, std::to_string(i)), p.thrusters[i], r.diagnostics());
}

void read_weights(MapReader& r, std::array<double, 6>& out) {
  const auto node = r.child("state_weights", "a list of 6 positive numbers");
  const std::string path = r.path_of("state_weights");
  if (!node || !check_list(*node, path, 6, "a list of 6 positive numbers", r.diagnostics())) return;
  for (std::size_t i = 0; i < 6; ++i)
    read_number((*node)[i], join_path(path, std::to_string(i)), Range::positive(), r.diagnostics(),
                out[i]);
}

// An optional key naming one of two values; absent, `out` keeps its default. The reading's keys:
// pulses.reading (docs/invsim.md, "Readings of App. B"), pulses.paper.inverse_model and .opening.
template <class Choice>
void read_either(MapReader& m, std::string_view key, std::string_view first, Choice first_value,
                 std::string_view second, Choice second_value, Choice& out) {
  if (!m.has(key)) return;
  std::string text;
  if (!m.text(key, text)) return;
  if (text == first) out = first_value;
  else if (text == second) out = second_value;
  else m.diagnostics().add(m.path_of(key), fmt::format("must be {} or {} (got '{}')", first, second, text));
}

// pulses.paper.measurement_noise: optional (no noise); each key optional inside it.
constexpr double kMaxRangeSigmaM = 10.0;     // [m] beyond this the sensor measures nothing useful at 10-100 m
constexpr double kMaxAngleSigmaDeg = 5.0;    // [deg] half the field of view
constexpr std::uint64_t kMaxNoiseDraws = 1000;  // a study of 123 modes x 1000 draws is minutes
constexpr double kMaxLateralBrakeMps2 = 10.0;  // [m/s^2] 1 g: beyond any reaction-control thruster
void read_measurement_noise(MapReader& m, model::InvSimMeasurementNoise& out) {
  if (!m.has("measurement_noise")) return;
  read_section(m, "measurement_noise", [&](MapReader& n) {
    if (n.has("range_sigma_m")) n.number("range_sigma_m", Range::closed(0.0, kMaxRangeSigmaM), out.range_sigma_m);
    if (n.has("angle_sigma_deg"))
      n.angle_deg("angle_sigma_deg", Range::closed(0.0, kMaxAngleSigmaDeg), out.angle_sigma_rad);
    if (n.has("seed")) n.count("seed", out.seed);
    if (n.has("draws") && n.count("draws", out.draws) && (out.draws < 1 || out.draws > kMaxNoiseDraws)) {
      n.diagnostics().add(n.path_of("draws"), fmt::format("must be in [1, {}] (got {})", kMaxNoiseDraws, out.draws));
      out.draws = 1;
    }
  });
}

// pulses.paper: the paper reading's calibrated choices; required when pulses.reading is paper,
// checked whenever present.
void read_paper_reading(MapReader& m, InvSimParams& p) {
  if (!m.has("paper")) {
    if (p.pulses.reading == model::InvSimReading::kPaper)
      m.diagnostics().add(m.path_of("paper"), "is required with pulses.reading: paper (keys pulse_width_s, state_weights)");
    return;
  }
  read_section(m, "paper", [&](MapReader& s) {
    s.number("pulse_width_s", Range::left_open(0.0, 60.0), p.pulses.paper.pulse_width_s);
    read_weights(s, p.pulses.paper.state_weights);
    read_either(s, "inverse_model", "nominal", model::InvSimInverseModel::kNominal, "faulted",
                model::InvSimInverseModel::kFaulted, p.pulses.paper.inverse_model);
    read_either(s, "opening", "capped", model::InvSimOpening::kCapped, "carried", model::InvSimOpening::kCarried,
                p.pulses.paper.opening);
    read_measurement_noise(s, p.pulses.paper.measurement_noise);
    model::InvSimPaperReadingParams& paper = p.pulses.paper;
    if (s.has("lateral_time_constant_s"))
      s.number("lateral_time_constant_s", Range::closed(0.0, kMaxApproachDurationS), paper.lateral_time_constant_s);
    if (s.has("lateral_brake_mps2") &&
        s.number("lateral_brake_mps2", Range::closed(0.0, kMaxLateralBrakeMps2), paper.lateral_brake_mps2) &&
        paper.lateral_brake_mps2 > 0.0 && !(paper.lateral_time_constant_s > 0.0))
      s.diagnostics().add(s.path_of("lateral_brake_mps2"),
                          fmt::format("needs lateral_time_constant_s > 0: the return after the brake (got {} s)",
                                      format_number(paper.lateral_time_constant_s)));
  });
}

void read_sections(MapReader& r, InvSimParams& p) {
  r.text("name", p.name);
  read_section(r, "orbit", [&](MapReader& m) {
    m.number("mu_m3ps2", Range::positive(), p.mu_m3ps2);
    m.number("body_radius_m", Range::positive(), p.body_radius_m);
    m.number("altitude_m", Range::positive(), p.altitude_m);
  });
  read_section(r, "chaser", [&](MapReader& m) {
    m.number("mass_kg", Range::positive(), p.mass_kg);
    m.mat3("inertia_kgm2", p.inertia_kgm2);
    m.number("isp_s", Range::positive(), p.isp_s);
  });
  read_section(r, "initial", [&](MapReader& m) {
    m.vec3("position_hill_m", p.r0_hill_m);
    m.vec3("velocity_hill_mps", p.v0_hill_mps);
    if (m.vec3("attitude_euler_deg", p.euler0_rad)) p.euler0_rad *= kDegToRad;
    if (m.vec3("rate_body_degps", p.omega0_rel_body_radps)) p.omega0_rel_body_radps *= kDegToRad;
  });
  read_section(r, "run", [&](MapReader& m) {
    m.number("step_s", Range::left_open(0.0, 60.0), p.step_s);
    m.number("duration_s", Range::left_open(0.0, kMaxApproachDurationS), p.duration_s);
    m.vec3("envelope_m", p.envelope_m);
  });
  read_section(r, "trajectory", [&](MapReader& m) {
    m.number("dock_x_m", Range::any(), p.trajectory.dock_x_m);
    m.number("damping_start_s", Range::non_negative(), p.trajectory.damping_start_s);
    m.number("damping_time_constant_s", Range::positive(), p.trajectory.damping_time_constant_s);
  });
  read_section(r, "inverse", [&](MapReader& m) {
    std::uint64_t horizon = 0;
    if (m.count("horizon_steps", horizon)) {
      if (horizon < 1 || horizon > 1000)
        m.diagnostics().add(m.path_of("horizon_steps"), fmt::format("must be in [1, 1000] (got {})", horizon));
      else
        p.inverse.horizon_steps = static_cast<int>(horizon);
    }
    read_weights(m, p.inverse.state_weights);
  });
  read_section(r, "pulses", [&](MapReader& m) {
    read_either(m, "reading", "smooth", model::InvSimReading::kSmooth, "paper", model::InvSimReading::kPaper,
                p.pulses.reading);
    m.number("time_sensitivity", Range::right_open(0.0, 1.0), p.pulses.time_sensitivity);
    m.number("acceleration_sensitivity", Range::right_open(0.0, 1.0), p.pulses.acceleration_sensitivity);
    m.number("basic_pulse_amount", Range::positive(), p.pulses.basic_pulse_amount);
    read_paper_reading(m, p);
  });
  read_section(r, "attitude_control", [&](MapReader& m) {
    model::InvSimPhasePlaneParams& a = p.attitude;
    m.number("period_s", Range::positive(), a.period_s);
    m.angle_deg("d_deg", Range::left_open(0.0, 90.0), a.d_rad);
    m.angle_deg("delta_deg", Range::non_negative(), a.delta_rad);
    m.angle_deg("rate_border_s_degps", Range::positive(), a.rate_border_s_radps);
    m.angle_deg("rate_border_t_degps", Range::non_negative(), a.rate_border_t_radps);
    m.number("btc1", Range::closed(0.0, 0.0), a.btc1);
    m.number("btc2", Range::closed(0.0, 1.0), a.btc2);
    m.number("btc3", Range::closed(0.0, 1.0), a.btc3);
  });
  read_section(r, "sensor", [&](MapReader& m) {
    m.vec3("position_body_m", p.sensor.position_body_m);
    m.angle_deg("azimuth_limit_deg", Range::left_open(0.0, 90.0), p.sensor.azimuth_limit_rad);
    m.angle_deg("elevation_limit_deg", Range::left_open(0.0, 90.0), p.sensor.elevation_limit_rad);
    m.angle_deg("attitude_limit_deg", Range::left_open(0.0, 90.0), p.sensor.attitude_limit_rad);
  });
  read_thrusters(r, p);
}

bool integer_ratio(double a, double b) {
  const double ratio = a / b;
  return std::abs(ratio - std::round(ratio)) <= 1e-9 * std::max(1.0, ratio);
}

void validate_timing(const InvSimParams& p, Diagnostics& diag) {
  if (diag.clean("run.step_s") && diag.clean("run.duration_s") && !integer_ratio(p.duration_s, p.step_s))
    diag.add("run.duration_s", fmt::format("must be a whole number of steps of {} s (got {})",
                                           format_number(p.step_s), format_number(p.duration_s)));
  if (diag.clean("run.step_s") && diag.clean("attitude_control.period_s") &&
      (p.attitude.period_s > p.step_s || !integer_ratio(p.step_s, p.attitude.period_s)))
    diag.add("attitude_control.period_s",
             fmt::format("must divide run.step_s = {} s into whole periods (got {})",
                         format_number(p.step_s), format_number(p.attitude.period_s)));
  if (diag.clean("run.envelope_m") && (p.envelope_m.array() <= 0.0).any())
    diag.add("run.envelope_m", "must have three positive sizes");
  if (diag.clean("trajectory") && diag.clean("initial.position_hill_m") &&
      p.trajectory.dock_x_m >= p.r0_hill_m.x())
    diag.add("trajectory.dock_x_m", fmt::format("must be below the initial x = {} m (got {})",
                                                format_number(p.r0_hill_m.x()),
                                                format_number(p.trajectory.dock_x_m)));
  if (diag.clean("chaser.inertia_kgm2") &&
      (!p.inertia_kgm2.isDiagonal(1e-12) || (p.inertia_kgm2.diagonal().array() <= 0.0).any()))
    diag.add("chaser.inertia_kgm2", "must be diagonal and positive (body axes are principal, eq. 10)");
}

}  // namespace

// Every (axis, direction) group must push along its axis, every attitude couple turn about its
// axis, and names must be unique.
void check_invsim_layout(const InvSimParams& p, const std::string& key_path, Diagnostics& diag) {
  std::set<std::string> names;
  for (std::size_t i = 0; i < p.thrusters.size(); ++i)
    if (!names.insert(p.thrusters[i].name).second)
      diag.add(join_path(key_path, fmt::format("{}.name", i)),
               fmt::format("'{}' is used by an earlier thruster", p.thrusters[i].name));
  for (int axis = 0; axis < 3; ++axis) {
    for (int d : {1, -1}) {
      double force = 0.0, torque = 0.0;
      for (const InvSimThruster& t : p.thrusters) {
        if (t.axis != axis) continue;
        if (t.role == InvSimThrusterRole::kTranslation && t.sign == d)
          force += t.thrust_N * t.direction_body(axis);
        if (t.role == InvSimThrusterRole::kAttitude)
          torque += t.sign * d * t.position_body_m.cross(t.thrust_N * t.direction_body)(axis);
      }
      if (!(force * d > 0.0))
        diag.add(key_path, fmt::format("the translation group {}{} must push along {}{}",
                                          d > 0 ? '+' : '-', char('x' + axis), d > 0 ? '+' : '-',
                                          char('x' + axis)));
      if (!(torque * d > 0.0))
        diag.add(key_path, fmt::format("the attitude thrusters of axis {} must turn about {}{}",
                                          char('x' + axis), d > 0 ? '+' : '-', char('x' + axis)));
    }
  }
}

namespace {

std::optional<YAML::Node> parse_invsim_document(const std::string& text, const std::string& source,
                                         Diagnostics& diag) {
  std::vector<YAML::Node> documents;
  try {
    documents = YAML::LoadAll(text);
  } catch (const YAML::Exception& e) {
    diag.add(source, fmt::format("invalid YAML at line {}, column {}: {}", e.mark.line + 1,
                                 e.mark.column + 1, e.msg));
    return std::nullopt;
  }
  if (documents.size() != 1 || !documents.front().IsMap()) {
    diag.add(source, "must hold exactly one YAML document, a mapping of scenario keys");
    return std::nullopt;
  }
  return documents.front();
}

std::vector<std::string> read_fault_names(MapReader& r) {
  std::vector<std::string> names;
  const auto node = r.child("faults", "a list of thruster names");
  if (!node) return names;
  if (!node->IsSequence() || node->size() > model::kMaxInvSimThrusters) {
    r.diagnostics().add(r.path_of("faults"), fmt::format("must be a list of at most {} thruster names (got {})",
                                                         model::kMaxInvSimThrusters, describe_node(*node)));
    return names;
  }
  for (std::size_t i = 0; i < node->size(); ++i) {
    const YAML::Node& item = (*node)[i];
    if (item.IsScalar() && !item.Scalar().empty()) names.push_back(item.Scalar());
    else r.diagnostics().add(join_path(r.path_of("faults"), std::to_string(i)),
                             fmt::format("must be a thruster name (got {})", describe_node(item)));
  }
  return names;
}

InvSimLoadResult load_document(const std::string& text, const std::string& source,
                               const std::vector<std::string>& overrides) {
  InvSimLoadResult result;
  Diagnostics diag;
  std::optional<YAML::Node> root;
  if (check_yaml_text(text, source, "", diag)) root = parse_invsim_document(text, source, diag);
  if (root) {
    for (const std::string& o : overrides) apply_override(*root, o, diag);
  }
  if (root && check_document_tree(*root, source, diag)) {
    InvSimParams p;
    MapReader r(*root, "", diag);
    read_sections(r, p);
    const std::vector<std::string> fault_names = read_fault_names(r);
    validate_timing(p, diag);
    if (diag.clean("thrusters")) check_invsim_layout(p, "thrusters", diag);
    if (diag.clean("thrusters")) read_invsim_study(r, p, result.study);
    r.accept("configurations");
    r.accept("optimize");
    r.finish();
    std::vector<ScenarioError> fault_errors;
    if (diag.clean("thrusters")) {
      if (auto faults = invsim_fault_set(p, fault_names, "faults", fault_errors)) result.faults = *faults;
      for (ScenarioError& e : fault_errors) diag.add(e.key_path, e.message);
    }
    if (diag.errors().empty()) result.params = p;
  }
  result.errors = diag.errors();
  return result;
}

}  // namespace

InvSimLoadResult load_invsim_text(const std::string& yaml_text, const std::vector<std::string>& overrides) {
  return load_document(yaml_text, "<text>", overrides);
}

InvSimLoadResult load_invsim_file(const std::string& path, const std::vector<std::string>& overrides) {
  const std::optional<std::string> text = read_text_file(path, kMaxDocumentBytes);
  if (!text) {
    InvSimLoadResult result;
    result.errors.push_back({path, kUnreadableScenario});
    return result;
  }
  return load_document(*text, path, overrides);
}

std::optional<model::InvSimFaultSet> invsim_fault_set(const InvSimParams& p,
                                                      const std::vector<std::string>& names,
                                                      const std::string& key_path,
                                                      std::vector<ScenarioError>& errors) {
  model::InvSimFaultSet set;
  bool ok = true;
  for (std::size_t k = 0; k < names.size(); ++k) {
    std::size_t i = 0;
    while (i < p.thrusters.size() && p.thrusters[i].name != names[k]) ++i;
    const std::string path = join_path(key_path, std::to_string(k));
    if (i == p.thrusters.size()) {
      errors.push_back({path, fmt::format("'{}' is not a thruster of the scenario", names[k])});
      ok = false;
    } else if (set.failed(i)) {
      errors.push_back({path, fmt::format("'{}' is listed twice", names[k])});
      ok = false;
    } else {
      set.failed_mask |= std::uint64_t{1} << i;
    }
  }
  if (!ok) return std::nullopt;
  return set;
}

}  // namespace chaser::io
