#pragma once
// The published figures of Zhou 2018, Tables 4 and 5 (pulses per body axis and direction, and the
// operational amount k_p = P / 3000, eq. 22), as printed. Data, not a model: fmea.md prints them
// beside Chaser's figures, and the tests and python/invsim_study/calibrate_invsim.py compare
// against them.
// Labels are Chaser's (fault_modes.hpp): the paper's e_1^- is e1~, its multi-axis row
// (d1/d2~, e2/e1~) is "d1/d2~+e2/e1~". The paper prints `---` for its four uncontrollable
// Table 5 rows: `controllable` false and no figures.
#include <array>
#include <optional>
#include <span>
#include <string_view>

namespace chaser::invsim {

struct PaperRow {
  std::string_view label;    // "nominal", "e1~", "d1/d1~+e1/e1~"
  bool controllable;         // false: the paper prints `---`
  std::array<int, 6> pulses; // x+, x-, y+, y-, z+, z- (zero when not controllable)
  double k_p;                // operational amount as printed (two decimals)
};

// Zhou 2018, Table 4 (the nominal row and the 16 single-axis fault rows, in the paper's order).
std::span<const PaperRow> zhou2018_table4();
// Zhou 2018, Table 5 (the 16 multi-axis fault rows, in the paper's order; nominal not repeated).
std::span<const PaperRow> zhou2018_table5();
// The row of either table with this label.
std::optional<PaperRow> zhou2018_row(std::string_view label);

}  // namespace chaser::invsim
