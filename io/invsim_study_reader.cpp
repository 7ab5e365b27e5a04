// The layout-study sections of an inverse-simulation scenario (io/invsim_study_reader.hpp; schema
// in docs/invsim.md, "Reconfiguration").
#include "io/invsim_study_reader.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include <fmt/format.h>

#include "core/plain_name.hpp"

namespace chaser::io {
namespace {

using model::InvSimConfiguration;
using model::InvSimParams;

constexpr std::size_t kMaxListSize = 256;  // configurations, choices, options: a study, not a search space

std::optional<std::size_t> thruster_index(const InvSimParams& p, const std::string& name) {
  for (std::size_t i = 0; i < p.thrusters.size(); ++i)
    if (p.thrusters[i].name == name) return i;
  return std::nullopt;
}

// `thrusters: {NAME: {thrust_N: .., position_body_m: [..], direction_body: [..]}, ...}`
void read_changes(const YAML::Node& node, const std::string& path, const InvSimParams& p,
                  std::vector<model::InvSimThrusterChange>& out, Diagnostics& diag) {
  if (!node.IsMap()) {
    diag.add(path, fmt::format("must be a mapping of thruster names to changes (got {})", describe_node(node)));
    return;
  }
  for (const auto& entry : node) {
    const std::string name = entry.first.IsScalar() ? entry.first.Scalar() : std::string();
    const std::string item_path = join_path(path, name);
    const std::optional<std::size_t> index = thruster_index(p, name);
    if (!index) {
      diag.add(item_path, fmt::format("'{}' is not a thruster of the scenario", name));
      continue;
    }
    model::InvSimThrusterChange change;
    change.thruster = *index;
    MapReader m(entry.second, item_path, diag);
    double thrust_N = 0.0;
    Vec3 position = Vec3::Zero(), direction = Vec3::UnitX();
    if (m.has("thrust_N") && m.number("thrust_N", Range::positive(), thrust_N)) change.thrust_N = thrust_N;
    if (m.has("position_body_m") && m.vec3("position_body_m", position)) change.position_body_m = position;
    if (m.has("direction_body") && m.direction("direction_body", direction)) change.direction_body = direction;
    if (m.valid() && !m.has("thrust_N") && !m.has("position_body_m") && !m.has("direction_body"))
      diag.add(item_path, "must change at least one of thrust_N, position_body_m, direction_body");
    m.finish();
    out.push_back(change);
  }
}

// {name, description, thrusters}; `thrusters` may be left out only where `optional_changes`.
InvSimConfiguration read_configuration(const YAML::Node& node, const std::string& path, const InvSimParams& p,
                                       bool optional_changes, Diagnostics& diag) {
  InvSimConfiguration c;
  MapReader m(node, path, diag);
  m.text("name", c.name);
  if (m.has("description")) m.text("description", c.description);
  if (!optional_changes || m.has("thrusters")) {
    if (const auto changes = m.child("thrusters", "a mapping of thruster names to changes"))
      read_changes(*changes, m.path_of("thrusters"), p, c.changes, diag);
  }
  m.finish();
  return c;
}

std::optional<YAML::Node> read_list(MapReader& m, std::string_view key, std::string_view what) {
  const auto node = m.child(key, what);
  if (!node) return std::nullopt;
  if (!node->IsSequence() || node->size() == 0 || node->size() > kMaxListSize) {
    m.diagnostics().add(m.path_of(key), fmt::format("must be {} with 1 to {} entries (got {})", what,
                                                    kMaxListSize, describe_node(*node)));
    return std::nullopt;
  }
  return node;
}

// A configuration (or option) must leave a layout that can fly the approach.
void check_configuration(const InvSimParams& p, const InvSimConfiguration& c, const std::string& path,
                         Diagnostics& diag) {
  if (!diag.clean(path)) return;
  std::set<std::size_t> changed;
  for (const auto& change : c.changes)
    if (!changed.insert(change.thruster).second)
      diag.add(path, fmt::format("changes thruster '{}' twice", p.thrusters[change.thruster].name));
  check_invsim_layout(model::apply_configuration(p, c), path, diag);
}

void read_configurations(MapReader& root, const InvSimParams& p, std::vector<InvSimConfiguration>& out) {
  const auto list = read_list(root, "configurations", "a list of configurations");
  if (!list) return;
  const std::string path = root.path_of("configurations");
  std::set<std::string> names{"baseline"};  // the scenario's own layout
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string item_path = join_path(path, std::to_string(i));
    InvSimConfiguration c = read_configuration((*list)[i], item_path, p, false, root.diagnostics());
    if (!c.name.empty() && !is_plain_name(c.name))
      root.diagnostics().add(join_path(item_path, "name"),
                             fmt::format("must be a plain name: {} (it names a directory; got '{}')", kPlainNameRule, c.name));
    else if (!c.name.empty() && !names.insert(c.name).second)
      root.diagnostics().add(join_path(item_path, "name"),
                             fmt::format("'{}' is taken (by 'baseline' or an earlier configuration)", c.name));
    check_configuration(p, c, item_path, root.diagnostics());
    out.push_back(std::move(c));
  }
}

void read_choice(const YAML::Node& node, const std::string& path, const InvSimParams& p,
                 model::InvSimFreeChoice& out, Diagnostics& diag) {
  MapReader m(node, path, diag);
  m.text("name", out.name);
  if (const auto options = read_list(m, "options", "a list of options")) {
    std::set<std::string> labels;
    for (std::size_t j = 0; j < options->size(); ++j) {
      const std::string option_path = join_path(m.path_of("options"), std::to_string(j));
      InvSimConfiguration option = read_configuration((*options)[j], option_path, p, true, diag);
      if (!option.name.empty() && !labels.insert(option.name).second)
        diag.add(join_path(option_path, "name"), fmt::format("'{}' is used by an earlier option", option.name));
      check_configuration(p, option, option_path, diag);
      out.options.push_back(std::move(option));
    }
  }
  m.finish();
}

// Two choices must not change the same thruster: a candidate would then depend on the order.
void check_choices_disjoint(const std::vector<model::InvSimFreeChoice>& choices, const InvSimParams& p,
                            const std::string& path, Diagnostics& diag) {
  std::map<std::size_t, std::size_t> owner;  // thruster -> choice
  for (std::size_t k = 0; k < choices.size(); ++k)
    for (const auto& option : choices[k].options)
      for (const auto& change : option.changes) {
        const auto [it, inserted] = owner.emplace(change.thruster, k);
        if (!inserted && it->second != k)
          diag.add(join_path(path, std::to_string(k)),
                   fmt::format("changes thruster '{}', which choice '{}' changes too", p.thrusters[change.thruster].name,
                               choices[it->second].name));
      }
}

void read_optimize(MapReader& root, const InvSimParams& p, model::InvSimStudy& out) {
  read_section(root, "optimize", [&](MapReader& m) {
    std::uint64_t keep = 0;
    if (m.count("keep", keep)) {
      if (keep < 1 || keep > 100) m.diagnostics().add(m.path_of("keep"), fmt::format("must be in [1, 100] (got {})", keep));
      else out.optimize_keep = static_cast<int>(keep);
    }
    const auto list = read_list(m, "choices", "a list of free choices");
    if (!list) return;
    const std::string path = m.path_of("choices");
    std::set<std::string> names;
    for (std::size_t k = 0; k < list->size(); ++k) {
      model::InvSimFreeChoice choice;
      read_choice((*list)[k], join_path(path, std::to_string(k)), p, choice, m.diagnostics());
      if (!choice.name.empty() && !names.insert(choice.name).second)
        m.diagnostics().add(join_path(path, std::to_string(k)) + ".name",
                            fmt::format("'{}' is used by an earlier choice", choice.name));
      out.free_choices.push_back(std::move(choice));
    }
    if (!m.diagnostics().clean(path)) return;
    check_choices_disjoint(out.free_choices, p, path, m.diagnostics());
    const std::size_t n = model::candidate_count(out.free_choices);
    if (n > model::kMaxOptimizeCandidates) {
      m.diagnostics().add(path, fmt::format("give more than {} candidates (the product of the option counts); "
                                            "fix more of the layout", model::kMaxOptimizeCandidates));
      return;
    }
    // Each option flies on its own; a combination could still undo a group (two options turning
    // two thrusters of one group), so every candidate is checked, the first few failures reported.
    int reported = 0;
    for (std::size_t i = 0; i < n && reported < 3; ++i) {
      Diagnostics scratch;
      const InvSimConfiguration c = model::candidate(out.free_choices, i);
      check_invsim_layout(model::apply_configuration(p, c), path, scratch);
      if (scratch.errors().empty()) continue;
      ++reported;
      m.diagnostics().add(path, fmt::format("candidate '{}': {}", c.name, scratch.errors().front().message));
    }
  });
}

}  // namespace

void read_invsim_study(MapReader& root, const model::InvSimParams& p, model::InvSimStudy& out) {
  if (root.has("configurations")) read_configurations(root, p, out.configurations);
  if (root.has("optimize")) read_optimize(root, p, out);
}

}  // namespace chaser::io
