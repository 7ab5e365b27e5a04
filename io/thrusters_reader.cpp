// The thrusters section: timing and dispersion parameters, then the list of 1..32 thrusters, named
// T1..TN in list order, each optionally in a redundancy group (a latch valve), and the standby
// groups that fly only after a recovery switches to them.
#include <algorithm>

#include <fmt/format.h>

#include "io/scenario_sections.hpp"

namespace chaser::io {
namespace {

// The plant draws the per-run dispersion truncated at 3 sigma (plant/thruster_hardware.hpp): up to
// 0.25 every dispersed thrust stays >= 25 % of nominal, and up to 10 deg every direction stays
// within 30 deg of nominal about each axis, so a thruster keeps its role in the layout.
constexpr double kMaxThrustSigma = 0.25;
constexpr double kMaxMisalignmentSigmaDeg = 10.0;

// The group's index, added in order of first appearance.
int group_index(const std::string& name, std::vector<model::ThrusterGroup>& groups) {
  const auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.name == name; });
  if (it != groups.end()) return static_cast<int>(it - groups.begin());
  groups.push_back(model::ThrusterGroup{.name = name});
  return static_cast<int>(groups.size()) - 1;
}

void read_thruster(const YAML::Node& node, const std::string& path, int index, model::ThrusterSetParams& set,
                   Diagnostics& diag) {
  MapReader m(node, path, diag);
  model::ThrusterParams& out = set.thrusters[static_cast<std::size_t>(index)];
  std::string name, group;
  if (m.text("name", name) && name != model::thruster_name(index))
    diag.add(m.path_of("name"), fmt::format("must be {} (thrusters are named T1..TN in list order; got '{}')",
                                            model::thruster_name(index), name));
  if (m.has("group") && m.text("group", group)) out.group = group_index(group, set.groups);
  m.vec3("position_body_m", Range::closed(-kMaxLayoutExtentM, kMaxLayoutExtentM), out.position_body_m);
  m.direction("direction_body", out.direction_body);
  m.number("max_thrust_N", Range::left_open(0.0, kMaxThrustN), out.max_thrust_N);
  m.finish();
}

void read_thruster_list(MapReader& r, model::ThrusterSetParams& out) {
  const std::string expected = fmt::format("a list of 1..{} thrusters T1..TN", model::kMaxThrusters);
  const auto list = r.child("list", expected);
  const std::string path = r.path_of("list");
  if (!list) return;
  if (!list->IsSequence() || list->size() < 1 || list->size() > static_cast<std::size_t>(model::kMaxThrusters)) {
    r.diagnostics().add(path, fmt::format("must be {} (got {})", expected, describe_node(*list)));
    return;
  }
  out.count = static_cast<int>(list->size());
  for (int i = 0; i < out.count; ++i)
    read_thruster((*list)[static_cast<std::size_t>(i)], join_path(path, std::to_string(i)), i, out, r.diagnostics());
}

// standby_groups: names of groups listed under `group` in thrusters.list.
void read_standby_groups(MapReader& r, model::ThrusterSetParams& out) {
  if (!r.has("standby_groups")) return;
  const auto node = r.child("standby_groups", "a list of group names");
  const std::string path = r.path_of("standby_groups");
  if (!node || out.count == 0) return;  // no thruster list: its error is already reported
  if (!node->IsSequence() || node->size() > static_cast<std::size_t>(model::kMaxThrusters)) {
    r.diagnostics().add(path, fmt::format("must be a list of at most {} group names, e.g. [B] (got {})",
                                          model::kMaxThrusters, describe_node(*node)));
    return;
  }
  for (std::size_t i = 0; i < node->size(); ++i) {
    const YAML::Node& item = (*node)[i];
    const auto it = std::find_if(out.groups.begin(), out.groups.end(), [&](const model::ThrusterGroup& g) {
      return item.IsScalar() && g.name == item.Scalar();
    });
    if (it == out.groups.end()) {
      std::vector<std::string> names;
      for (const model::ThrusterGroup& g : out.groups) names.push_back(g.name);
      r.diagnostics().add(join_path(path, std::to_string(i)),
                          fmt::format("must name a group of thrusters.list ({}) (got {})",
                                      names.empty() ? std::string("none has a group") : fmt::format("{}", fmt::join(names, ", ")),
                                      describe_node(item)));
      continue;
    }
    it->standby = true;
  }
}

}  // namespace

// Timing limits that depend on the control period, and what the layout can do, are checked in
// validate_scenario.
void read_thrusters(MapReader& r, model::ThrusterSetParams& out) {
  r.number("delay_max_s", Range::non_negative(), out.delay_max_s);
  r.number("rise_time_s", Range::non_negative(), out.rise_time_s);
  r.number("min_on_time_s", Range::non_negative(), out.min_on_time_s);
  r.number("min_off_time_s", Range::non_negative(), out.min_off_time_s);
  r.number("thrust_sigma", Range::closed(0.0, kMaxThrustSigma), out.thrust_sigma);
  r.angle_deg("misalignment_sigma_deg", Range::closed(0.0, kMaxMisalignmentSigmaDeg),
              out.misalignment_sigma_rad);
  if (r.has("tolerates_single_loss")) r.boolean("tolerates_single_loss", out.tolerates_single_loss);
  read_thruster_list(r, out);
  read_standby_groups(r, out);
}

// A list of thruster names T1..TN under `key`, as a mask.
void read_thruster_names(MapReader& r, std::string_view key, model::ThrusterMask& out) {
  const auto node = r.child(key, "a list of thruster names");
  const std::string path = r.path_of(key);
  if (!node) return;
  if (!node->IsSequence() || node->size() == 0 || node->size() > static_cast<std::size_t>(model::kMaxThrusters)) {
    r.diagnostics().add(path, fmt::format("must be a list of 1 to {} thruster names, e.g. [T1, T5] (got {})",
                                          model::kMaxThrusters, describe_node(*node)));
    return;
  }
  out = 0;
  for (std::size_t i = 0; i < node->size(); ++i) {
    const YAML::Node& item = (*node)[i];
    const std::optional<int> index = item.IsScalar() ? model::thruster_index(item.Scalar()) : std::nullopt;
    if (!index) {
      r.diagnostics().add(join_path(path, std::to_string(i)),
                          fmt::format("must be a thruster name T1..T{} (got {})", model::kMaxThrusters, describe_node(item)));
      continue;
    }
    out |= model::ThrusterMask{1} << *index;
  }
}

}  // namespace chaser::io
