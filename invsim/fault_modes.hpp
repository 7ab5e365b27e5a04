#pragma once
// The fault modes of Zhou 2018's failure-mode analysis: every fault shuts its thrusters down from
// the start (section 3.1).
//  - Table 2 (single-axis), per axis with thrusters p1, p2 (positive) and n1, n2 (negative):
//    {p1}, {p2}, {n1}, {n2}, {p1, n1}, {p1, n2}, {p2, n2}, {p2, n1}: 8 modes per axis, 24 in all,
//    in the paper's column order; the letters are d (x), e (y), f (z), whichever sign each answers.
//  - Table 5 (multi-axis): one x-axis double fault with one y-axis double fault, both drawn from
//    the pairs {d1, d1~}, {d1, d2~}, {d2, d1~}, {d2, d2~} and {e1, e1~}, {e1, e2~}, {e2, e1~},
//    {e2, e2~}: 16 modes, in the paper's row order.
//  - three-axis (ours, beyond the paper): each Table 5 mode with one z-axis double fault from
//    {f1, f1~}, {f1, f2~}, {f2, f1~}, {f2, f2~}: 64 modes of six failed thrusters, for the paper's
//    "the maximum tolerant number of faulty thrusters reaches six" (section 4.2).
// Thrusters are found by the paper's names (d1 ... f2~); a scenario without them yields no modes
// for the missing names' axis.
#include <string>
#include <vector>

#include "model/invsim.hpp"

namespace chaser::invsim {

struct FaultMode {
  std::string label;              // "d1", "e1/e1~", "d1/d2~+e2/e1~"
  model::InvSimFaultSet faults;
};

std::vector<FaultMode> single_axis_fault_modes(const model::InvSimParams& p);  // Table 2 / 4
std::vector<FaultMode> multi_axis_fault_modes(const model::InvSimParams& p);   // Table 5
std::vector<FaultMode> three_axis_fault_modes(const model::InvSimParams& p);   // Table 5 x z pairs

}  // namespace chaser::invsim
