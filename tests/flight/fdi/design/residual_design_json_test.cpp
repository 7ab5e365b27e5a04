#include "flight/fdi/design/residual_design_json.hpp"

#include <gtest/gtest.h>

#include "../msr_test_setup.hpp"

namespace chaser::flight::fdi {
namespace {

// The JSON carries what a runtime observer needs (A_bar, B_bar, C, L, Q, exactly as designed,
// rows of arrays) and the figures; it survives a dump/parse round trip.
TEST(ResidualDesignJson, CarriesTheObserverAndFigures) {
  const model::Scenario s = testing::msr_test_scenario();
  const ResidualDesign d = design_residual_generator(attitude_design_inputs(s, testing::msr_test_configuration(s)));
  const nlohmann::json j = nlohmann::json::parse(to_json(d).dump());
  ASSERT_EQ(j["L"].size(), 6u);
  ASSERT_EQ(j["L"][0].size(), 3u);
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(j["L"][r][c].get<double>(), d.L(r, c));
  EXPECT_EQ(j["Q"][0][2].get<double>(), d.Q(0, 2));
  EXPECT_EQ(j["A_bar"].size(), 6u);
  EXPECT_EQ(j["B_bar"][0].size(), 3u);
  EXPECT_EQ(j["inputs"]["name"], "attitude");
  EXPECT_EQ(j["inputs"]["low_rank"], "truncate_seen_part");
  EXPECT_EQ(j["figures"]["achieved_eigenvalues"].size(), 6u);
  EXPECT_EQ(j["figures"]["fault_gain_dc"].size(), 8u);
  EXPECT_EQ(j["figures"]["assignability_error"][0].get<double>(), d.assignment.relative_miss[0]);
  EXPECT_EQ(j["unknown_input"]["columns"].get<int>(), d.E_d.cols());
}

}  // namespace
}  // namespace chaser::flight::fdi
