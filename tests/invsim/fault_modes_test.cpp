#include "invsim/fault_modes.hpp"

#include <bitset>

#include <gtest/gtest.h>

#include "io/invsim_loader.hpp"

namespace chaser::invsim {
namespace {

model::InvSimParams scenario() {
  const io::InvSimLoadResult loaded = io::load_invsim_file("scenarios/manual_rvd.yaml");
  EXPECT_TRUE(loaded.errors.empty()) << io::format_errors(loaded.errors);
  return *loaded.params;
}

// Zhou 2018, Table 2: 8 modes per axis (4 single, 4 double), in the paper's column order, each
// failing exactly the named thrusters.
TEST(FaultModes, Table2SingleAxisModes) {
  const std::vector<FaultMode> modes = single_axis_fault_modes(scenario());
  ASSERT_EQ(modes.size(), 24u);
  const char* expected_x[] = {"d1", "d2", "d1~", "d2~", "d1/d1~", "d1/d2~", "d2/d2~", "d2/d1~"};
  for (int k = 0; k < 8; ++k) {
    EXPECT_EQ(modes[k].label, expected_x[k]);
    EXPECT_EQ(std::bitset<64>(modes[k].faults.failed_mask).count(), k < 4 ? 1u : 2u);
  }
  EXPECT_EQ(modes[8].label, "e1");
  EXPECT_EQ(modes[23].label, "f2/f1~");
  EXPECT_EQ(modes[0].faults.failed_mask, std::uint64_t{1} << 7);  // d1 is thruster 7
}

// Table 5: the 16 combinations of an x double fault and a y double fault, in its row order.
TEST(FaultModes, Table5MultiAxisModes) {
  const std::vector<FaultMode> modes = multi_axis_fault_modes(scenario());
  ASSERT_EQ(modes.size(), 16u);
  EXPECT_EQ(modes[0].label, "d1/d1~+e1/e1~");
  EXPECT_EQ(modes[6].label, "d1/d2~+e2/e1~");  // uncontrollable in the paper
  EXPECT_EQ(modes[15].label, "d2/d2~+e2/e2~");
  for (const FaultMode& m : modes) EXPECT_EQ(std::bitset<64>(m.faults.failed_mask).count(), 4u);
}

// Our three-axis extension: every Table 5 mode with each of the four z pairs, 64 modes of six
// distinct failed thrusters, each the union of its Table 5 mode and its z pair.
TEST(FaultModes, ThreeAxisModesAddAZPairToEachTable5Mode) {
  const model::InvSimParams p = scenario();
  const std::vector<FaultMode> xy = multi_axis_fault_modes(p);
  const std::vector<FaultMode> modes = three_axis_fault_modes(p);
  ASSERT_EQ(modes.size(), 64u);
  EXPECT_EQ(modes[0].label, "d1/d1~+e1/e1~+f1/f1~");
  EXPECT_EQ(modes[63].label, "d2/d2~+e2/e2~+f2/f2~");
  for (std::size_t k = 0; k < modes.size(); ++k) {
    EXPECT_EQ(std::bitset<64>(modes[k].faults.failed_mask).count(), 6u) << modes[k].label;
    EXPECT_EQ(modes[k].faults.failed_mask & xy[k / 4].faults.failed_mask, xy[k / 4].faults.failed_mask);
    EXPECT_EQ(modes[k].label.rfind(xy[k / 4].label + "+f", 0), 0u) << modes[k].label;
  }
}

}  // namespace
}  // namespace chaser::invsim
