// The thrusters section: timing and dispersion parameters, and the 16 thrusters T1..T16, branch A
// (T1..T8, indices 0..7) then branch B (T9..T16, indices 8..15), listed in that order.
#include <fmt/format.h>

#include "io/scenario_sections.hpp"

namespace chaser::io {
namespace {

// The plant draws the per-run dispersion truncated at 3 sigma (plant/thruster_hardware.hpp): up to
// 0.25 every dispersed thrust stays >= 25 % of nominal, and up to 10 deg every direction stays
// within 30 deg of nominal about each axis, so a thruster keeps its role in the layout.
constexpr double kMaxThrustSigma = 0.25;
constexpr double kMaxMisalignmentSigmaDeg = 10.0;

std::string expected_name(int index) { return fmt::format("T{}", index + 1); }
char expected_branch(int index) { return index < model::kThrustersPerBranch ? 'A' : 'B'; }

void read_thruster(const YAML::Node& node, const std::string& path, int index,
                   model::ThrusterParams& out, Diagnostics& diag) {
  MapReader m(node, path, diag);
  std::string name, branch;
  if (m.text("name", name) && name != expected_name(index))
    diag.add(m.path_of("name"), fmt::format("must be {} (entries are listed in order T1..T16; got '{}')",
                                            expected_name(index), name));
  if (m.text("branch", branch) && index < model::kThrustersTotal &&
      branch != std::string(1, expected_branch(index)))
    diag.add(m.path_of("branch"), fmt::format("must be {} (branch A is T1..T8, B is T9..T16; got '{}')",
                                              expected_branch(index), branch));
  m.vec3("position_body_m", out.position_body_m);
  m.direction("direction_body", out.direction_body);
  m.number("max_thrust_N", Range::positive(), out.max_thrust_N);
  m.finish();
}

void read_thruster_list(MapReader& r, model::ThrusterSetParams& out) {
  constexpr std::string_view expected = "a list of the 16 thrusters T1..T16";
  const auto list = r.child("list", expected);
  const std::string path = r.path_of("list");
  if (!list || !check_list(*list, path, model::kThrustersTotal, expected, r.diagnostics())) return;
  for (int i = 0; i < model::kThrustersTotal; ++i)
    read_thruster((*list)[i], join_path(path, std::to_string(i)), i, out.thrusters[i], r.diagnostics());
}

}  // namespace

// Timing limits that depend on the control period are checked in validate_scenario.
void read_thrusters(MapReader& r, model::ThrusterSetParams& out) {
  r.number("delay_max_s", Range::non_negative(), out.delay_max_s);
  r.number("rise_time_s", Range::non_negative(), out.rise_time_s);
  r.number("min_on_time_s", Range::non_negative(), out.min_on_time_s);
  r.number("min_off_time_s", Range::non_negative(), out.min_off_time_s);
  r.number("thrust_sigma", Range::closed(0.0, kMaxThrustSigma), out.thrust_sigma);
  r.angle_deg("misalignment_sigma_deg", Range::closed(0.0, kMaxMisalignmentSigmaDeg),
              out.misalignment_sigma_rad);
  read_thruster_list(r, out);
}

}  // namespace chaser::io
