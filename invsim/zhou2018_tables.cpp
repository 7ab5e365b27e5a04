#include "invsim/zhou2018_tables.hpp"

namespace chaser::invsim {
namespace {

// Zhou 2018, Table 4 "Operational amount of the single-axis thruster fault".
constexpr std::array<PaperRow, 17> kTable4{{
    {"nominal", true, {114, 50, 230, 327, 289, 567}, 0.53},
    {"e1~", true, {114, 50, 464, 328, 292, 568}, 0.61},
    {"e2~", true, {114, 50, 459, 326, 289, 565}, 0.60},
    {"e1/e1~", true, {116, 52, 459, 645, 289, 567}, 0.71},
    {"e2/e1~", true, {115, 51, 458, 647, 290, 568}, 0.71},
    {"e1/e2~", true, {116, 52, 457, 645, 289, 568}, 0.71},
    {"f1", true, {116, 51, 231, 327, 576, 567}, 0.62},
    {"f2~", true, {114, 50, 231, 328, 288, 1131}, 0.71},
    {"f1/f1~", true, {116, 51, 230, 326, 579, 1088}, 0.80},
    {"f2/f1~", true, {116, 51, 229, 328, 577, 1088}, 0.81},
    {"f1/f2~", true, {116, 51, 227, 325, 577, 1089}, 0.80},
    {"f2/f2~", true, {117, 52, 230, 326, 576, 1088}, 0.80},
    {"d1", true, {230, 49, 228, 325, 290, 567}, 0.56},
    {"d1~", true, {123, 104, 231, 326, 288, 564}, 0.55},
    {"d1/d1~", true, {250, 105, 232, 328, 288, 564}, 0.59},
    {"d2/d1~", true, {251, 106, 228, 323, 288, 563}, 0.59},
    {"d1/d2~", true, {252, 105, 229, 325, 290, 569}, 0.59},
}};

// Zhou 2018, Table 5 "Physical workloads of the multi-axis thruster faults" (its first row, the
// nominal case, repeats Table 4's and is left out).
constexpr std::array<PaperRow, 16> kTable5{{
    {"d1/d1~+e1/e1~", true, {245, 104, 459, 620, 288, 565}, 0.76},
    {"d1/d1~+e1/e2~", true, {245, 104, 457, 622, 285, 565}, 0.76},
    {"d1/d1~+e2/e1~", true, {251, 105, 456, 641, 291, 568}, 0.77},
    {"d1/d1~+e2/e2~", true, {252, 106, 456, 641, 291, 568}, 0.77},
    {"d1/d2~+e1/e1~", true, {250, 104, 457, 643, 292, 569}, 0.77},
    {"d1/d2~+e1/e2~", true, {250, 104, 456, 643, 289, 566}, 0.77},
    {"d1/d2~+e2/e1~", false, {}, 0.0},
    {"d1/d2~+e2/e2~", false, {}, 0.0},
    {"d2/d1~+e2/e1~", true, {250, 104, 457, 643, 289, 567}, 0.77},
    {"d2/d1~+e2/e2~", true, {250, 104, 458, 643, 289, 567}, 0.77},
    {"d2/d1~+e1/e1~", false, {}, 0.0},
    {"d2/d1~+e1/e2~", false, {}, 0.0},
    {"d2/d2~+e1/e1~", true, {250, 104, 455, 640, 290, 567}, 0.77},
    {"d2/d2~+e1/e2~", true, {250, 104, 460, 645, 289, 566}, 0.76},
    {"d2/d2~+e2/e1~", true, {251, 104, 457, 611, 293, 575}, 0.76},
    {"d2/d2~+e2/e2~", true, {254, 107, 456, 611, 292, 574}, 0.76},
}};

}  // namespace

std::span<const PaperRow> zhou2018_table4() { return kTable4; }
std::span<const PaperRow> zhou2018_table5() { return kTable5; }

std::optional<PaperRow> zhou2018_row(std::string_view label) {
  for (const auto table : {zhou2018_table4(), zhou2018_table5()})
    for (const PaperRow& row : table)
      if (row.label == label) return row;
  return std::nullopt;
}

}  // namespace chaser::invsim
