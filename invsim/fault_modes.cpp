#include "invsim/fault_modes.hpp"

#include <array>
#include <optional>

#include "invsim/thruster_set.hpp"

namespace chaser::invsim {
namespace {

// Table 2's columns: which of (x1, x2, x1~, x2~) fail.
constexpr std::array<std::array<int, 2>, 8> kTable2Columns{{
    {0, -1}, {1, -1}, {2, -1}, {3, -1}, {0, 2}, {0, 3}, {1, 3}, {1, 2}}};
// Table 5's pairs on each axis, as indices into (x1, x2, x1~, x2~).
constexpr std::array<std::array<int, 2>, 4> kDoublePairs{{{0, 2}, {0, 3}, {1, 2}, {1, 3}}};

std::optional<std::array<std::size_t, 4>> axis_thrusters(const model::InvSimParams& p, char letter) {
  const std::string l(1, letter);
  std::array<std::size_t, 4> out{};
  const std::array<std::string, 4> names{l + "1", l + "2", l + "1~", l + "2~"};
  for (std::size_t k = 0; k < 4; ++k) {
    const auto i = find_thruster(p, names[k]);
    if (!i) return std::nullopt;
    out[k] = *i;
  }
  return out;
}

void add(const model::InvSimParams& p, std::size_t i, FaultMode& mode) {
  mode.label += (mode.label.empty() || mode.label.back() == '+' ? "" : "/") + p.thrusters[i].name;
  mode.faults.failed_mask |= std::uint64_t{1} << i;
}

}  // namespace

std::vector<FaultMode> single_axis_fault_modes(const model::InvSimParams& p) {
  std::vector<FaultMode> modes;
  for (char letter : {'d', 'e', 'f'}) {
    const auto t = axis_thrusters(p, letter);
    if (!t) continue;
    for (const auto& column : kTable2Columns) {
      FaultMode mode;
      for (int k : column)
        if (k >= 0) add(p, (*t)[k], mode);
      modes.push_back(mode);
    }
  }
  return modes;
}

std::vector<FaultMode> multi_axis_fault_modes(const model::InvSimParams& p) {
  std::vector<FaultMode> modes;
  const auto x = axis_thrusters(p, 'd');
  const auto y = axis_thrusters(p, 'e');
  if (!x || !y) return modes;
  for (const auto& px : kDoublePairs) {
    for (const auto& py : kDoublePairs) {
      FaultMode mode;
      add(p, (*x)[px[0]], mode);
      add(p, (*x)[px[1]], mode);
      mode.label += "+";
      add(p, (*y)[py[0]], mode);
      add(p, (*y)[py[1]], mode);
      modes.push_back(mode);
    }
  }
  return modes;
}

std::vector<FaultMode> three_axis_fault_modes(const model::InvSimParams& p) {
  std::vector<FaultMode> modes;
  const auto z = axis_thrusters(p, 'f');
  if (!z) return modes;
  for (const FaultMode& xy : multi_axis_fault_modes(p)) {
    for (const auto& pz : kDoublePairs) {
      FaultMode mode = xy;
      mode.label += "+";
      add(p, (*z)[pz[0]], mode);
      add(p, (*z)[pz[1]], mode);
      modes.push_back(mode);
    }
  }
  return modes;
}

}  // namespace chaser::invsim
