// runs.csv rows: thrusters are written as n of their name Tn, 0 for none (docs/style.md), from the
// index and kNoThruster the code holds; the summary reads them back to the same indices.
#include "campaign/run_row.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>

#include "campaign/csv.hpp"

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace chaser::campaign {
namespace {

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out(1);
  for (char c : line) {
    if (c == ',') out.emplace_back();
    else out.back().push_back(c);
  }
  return out;
}

std::string column(const RunRecord& r, const std::string& name, RunColumnSet set = RunColumnSet::kStandard) {
  const std::vector<std::string> names = fields(runs_header(set));
  const std::vector<std::string> values = fields(format_row(r, set));
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return values[i];
  ADD_FAILURE() << "no column " << name;
  return {};
}

TEST(RunRow, ThrustersAreWrittenAsTheNumberOfTheirNameAndZeroForNone) {
  RunSetup faulty;
  faulty.fault_case = FaultCase::kLeak;
  faulty.fault = model::FaultParams{.kind = model::FaultKind::kLeak, .thruster = 2, .onset_s = 1000.0};
  RunRecord r = error_record(faulty);  // no figures: every scheme isolated none
  EXPECT_EQ(r.fault_thruster, 2);
  EXPECT_EQ(column(r, "fault_thruster"), "3");  // T3
  for (const char* scheme : {"position", "attitude", "deficit", "fdir"})
    EXPECT_EQ(column(r, std::string(scheme) + "_isolated"), "0") << scheme;
  r.schemes[flight::kAttitudeScheme].isolated = 7;
  EXPECT_EQ(column(r, "attitude_isolated"), "8");  // T8

  const RunRecord none = error_record(RunSetup{});
  EXPECT_EQ(none.fault_thruster, model::kNoThruster);
  EXPECT_EQ(column(none, "fault_thruster"), "0");
}

// Every field reads back as its column's kind says (the Python module types its array by it): the
// faulty record has numbers, nan, flags set and unset, a seed above 2^63; in both column sets.
class RunRowSets : public ::testing::TestWithParam<RunColumnSet> {};
INSTANTIATE_TEST_SUITE_P(BothSets, RunRowSets, ::testing::Values(RunColumnSet::kStandard, RunColumnSet::kReach));

TEST_P(RunRowSets, EveryFieldReadsBackAsItsColumnKind) {
  const RunColumnSet set = GetParam();
  RunSetup setup;
  setup.seed = 18446744073709551557ull;
  setup.fault_case = FaultCase::kStuckClosed;
  setup.fault = model::FaultParams{.kind = model::FaultKind::kStuckClosed, .thruster = 4, .onset_s = 1000.0};
  RunRecord r = error_record(setup);
  r.capture = true;
  r.propellant_kg = 1.25;
  r.reach.final_error_m = Vec3(0.001, -0.002, 0.003);
  r.reach.table2_met = true;
  const std::vector<std::string> values = fields(format_row(r, set));
  ASSERT_EQ(values.size(), run_columns(set).size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    const std::string& v = values[i];
    const RunColumn& c = run_columns(set)[i];
    switch (c.kind) {
      case ColumnKind::kInteger: EXPECT_TRUE(parse_integer(v).has_value()) << c.name << " " << v; break;
      case ColumnKind::kUnsigned: {
        std::uint64_t u = 0;
        EXPECT_EQ(std::from_chars(v.data(), v.data() + v.size(), u).ptr, v.data() + v.size()) << c.name;
        break;
      }
      case ColumnKind::kText: EXPECT_FALSE(v.empty() || parse_number(v).has_value()) << c.name << " " << v; break;
      case ColumnKind::kNumber: EXPECT_TRUE(parse_number(v).has_value()) << c.name << " " << v; break;
      case ColumnKind::kFlag: EXPECT_TRUE(v == "0" || v == "1") << c.name << " " << v; break;
    }
  }
  EXPECT_EQ(column(r, "seed", set), "18446744073709551557");
  EXPECT_EQ(column(r, "case", set), "stuck_closed");
  EXPECT_EQ(run_column_set_of(runs_header(set)), set);  // a file's header says which set it holds
}

// The reach's set is the standard one followed by the reach's columns, each figure in its own column
// per axis, and the mission's two; a run whose arm never woke has NaN figures and Table 2 not met.
TEST(RunRow, TheReachSetAddsTheReachFiguresAfterTheStandardColumns) {
  const std::string standard = runs_header(RunColumnSet::kStandard), reach = runs_header(RunColumnSet::kReach);
  ASSERT_EQ(reach.substr(0, standard.size() + 1), standard + ",");
  EXPECT_EQ(run_columns(RunColumnSet::kReach).size(), run_columns(RunColumnSet::kStandard).size() + 8 * 3 + 3 + 2 + 7 + 2);
  EXPECT_FALSE(run_column_set_of(standard + ",extra").has_value());

  RunRecord r = error_record(RunSetup{});
  EXPECT_EQ(column(r, "reach_max_rate_z_deg_s", RunColumnSet::kReach), "nan");
  EXPECT_EQ(column(r, "reach_table2_met", RunColumnSet::kReach), "0");
  r.reach.final_error_m = Vec3(0.001, -0.002, 0.003);
  r.reach.max_rate_deg_s = Vec3(0.04, 0.05, 0.125);
  r.reach.peak_joint_torque_Nm = 6.5;
  EXPECT_EQ(column(r, "reach_final_error_x_m", RunColumnSet::kReach), "0.001");
  EXPECT_EQ(column(r, "reach_final_error_y_m", RunColumnSet::kReach), "-0.002");
  EXPECT_EQ(column(r, "reach_final_error_z_m", RunColumnSet::kReach), "0.0030000000000000001");
  EXPECT_EQ(column(r, "reach_max_rate_z_deg_s", RunColumnSet::kReach), "0.125");
  EXPECT_EQ(column(r, "reach_peak_joint_torque_Nm", RunColumnSet::kReach), "6.5");
  EXPECT_EQ(column(r, "grasp_captured_s", RunColumnSet::kReach), "nan");
  EXPECT_EQ(column(r, "grasp_table2_met", RunColumnSet::kReach), "0");
  r.reach.grasp_captured_s = 2880.25;
  r.reach.grasp_table2_met = true;
  EXPECT_EQ(column(r, "grasp_captured_s", RunColumnSet::kReach), "2880.25");
  EXPECT_EQ(column(r, "grasp_table2_met", RunColumnSet::kReach), "1");
  EXPECT_EQ(column(r, "stabilise_below_goal_s", RunColumnSet::kReach), "nan");
  EXPECT_EQ(column(r, "stabilise_final_rate_y_deg_s", RunColumnSet::kReach), "nan");
  EXPECT_EQ(column(r, "stabilise_table3_met", RunColumnSet::kReach), "0");
  r.reach.stabilise_below_goal_s = 241.5;
  r.reach.stabilise_final_rate_deg_s = Vec3(0.001, -0.25, 0.003);
  r.reach.stabilise_peak_load_Nm = 91.5;
  r.reach.stabilise_propellant_kg = 3.25;
  r.reach.stabilise_table3_met = true;
  EXPECT_EQ(column(r, "stabilise_below_goal_s", RunColumnSet::kReach), "241.5");
  EXPECT_EQ(column(r, "stabilise_final_rate_y_deg_s", RunColumnSet::kReach), "-0.25");
  EXPECT_EQ(column(r, "stabilise_peak_load_Nm", RunColumnSet::kReach), "91.5");
  EXPECT_EQ(column(r, "stabilise_propellant_kg", RunColumnSet::kReach), "3.25");
  EXPECT_EQ(column(r, "stabilise_table3_met", RunColumnSet::kReach), "1");
}

// split_fields: plain fields, empty ones kept; a field in double quotes (optimize.csv's candidate
// names) given whole, commas and all, without its quotes; a bad quote is an error, not a guess.
TEST(CsvFields, PlainAndQuotedFields) {
  using V = std::vector<std::string_view>;
  EXPECT_EQ(split_fields("a,,b,"), (V{"a", "", "b", ""}));
  EXPECT_EQ(split_fields(""), (V{""}));
  EXPECT_EQ(split_fields("1,\"x=1, y=2\",true"), (V{"1", "x=1, y=2", "true"}));
  EXPECT_EQ(split_fields("\"a,b\""), (V{"a,b"}));
  EXPECT_EQ(split_fields("\"\",z"), (V{"", "z"}));
  EXPECT_THROW(split_fields("1,\"open"), std::runtime_error);
  EXPECT_THROW(split_fields("\"a\"b,c"), std::runtime_error);
}

}  // namespace
}  // namespace chaser::campaign
