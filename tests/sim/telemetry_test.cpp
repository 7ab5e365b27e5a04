// telemetry.csv from the channel table: the header is the table's names, and every row has a
// finite value for every channel, for thruster sets of 8, 16 (MSR) and 24.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "io/scenario_loader.hpp"
#include "sim/run.hpp"
#include "sim/telemetry_channels.hpp"
#include "tests/sim/thruster_layouts.hpp"

namespace chaser::sim {
namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  for (std::string field; std::getline(ss, field, ',');) out.push_back(field);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

// The MSR scenario with its 16 thrusters, or `count` thrusters in one set (tests/sim/
// thruster_layouts.hpp: copies of branch A; no groups, no recovery, the eight-lane FDI off unless
// exactly eight fly).
model::Scenario scenario_with(int count) {
  std::vector<std::string> overrides;
  if (count != 16) {
    overrides = testing::one_set_overrides(count);
    if (count == 8) overrides.resize(3);  // the FDI watches these eight
  }
  const io::LoadResult r = io::load_scenario_file("scenarios/msr_terminal.yaml", overrides);
  EXPECT_TRUE(r.scenario.has_value()) << io::format_errors(r.errors);
  model::Scenario s = *r.scenario;
  s.duration_s = 20.0;
  return s;
}

class TelemetryTable : public ::testing::TestWithParam<int> {};

TEST_P(TelemetryTable, EveryChannelHasAFiniteValueInEveryRow) {
  const int count = GetParam();
  const model::Scenario s = scenario_with(count);
  const auto path = std::filesystem::temp_directory_path() / ("chaser_telemetry_" + std::to_string(count) + ".csv");
  const RunResult r = run_scenario(s, {.telemetry_path = path.string()});
  ASSERT_TRUE(r.telemetry_ok);
  std::ifstream in(path);
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  const std::vector<std::string> header = split(line);
  EXPECT_EQ(header, channel_names(telemetry_channels(count)));
  EXPECT_EQ(std::set<std::string>(header.begin(), header.end()).size(), header.size()) << "duplicate channel names";
  EXPECT_EQ(header.front(), "t_s");
  EXPECT_NE(std::find(header.begin(), header.end(), fmt::format("ton_cmd_{}", count)), header.end());
  EXPECT_EQ(std::find(header.begin(), header.end(), fmt::format("ton_cmd_{}", count + 1)), header.end());
  int rows = 0;
  while (std::getline(in, line)) {
    const std::vector<std::string> fields = split(line);
    ASSERT_EQ(fields.size(), header.size()) << "row " << rows;
    for (std::size_t c = 0; c < fields.size(); ++c) {
      char* end = nullptr;
      const double v = std::strtod(fields[c].c_str(), &end);
      ASSERT_TRUE(!fields[c].empty() && *end == '\0' && std::isfinite(v)) << header[c] << " row " << rows << ": '" << fields[c] << "'";
    }
    ++rows;
  }
  EXPECT_EQ(rows, r.periods);
  std::filesystem::remove(path);
}

INSTANTIATE_TEST_SUITE_P(ThrusterCounts, TelemetryTable, ::testing::Values(8, 16, 24));

// Units: every name ends with its unit (or has none), so a reader can take the unit from the name.
TEST(TelemetryTable, NamesEndWithTheirUnit) {
  for (const TelemetryChannel& c : telemetry_channels(16)) {
    if (c.unit.empty()) continue;
    const std::string suffix = "_" + c.unit;
    ASSERT_GE(c.name.size(), suffix.size());
    EXPECT_EQ(c.name.substr(c.name.size() - suffix.size()), suffix) << c.name;
  }
}

// The writer's shortcut for +0.0 writes what the formatter writes: every value's text is
// fmt's "{:.10g}" of it, zeros of both signs included.
TEST(TelemetryWriter, ZeroShortcutWritesWhatFmtWrites) {
  const auto path = std::filesystem::temp_directory_path() / "chaser_telemetry_writer.csv";
  const std::vector<double> values = {0.0, -0.0, 1.0, -1.5e-300, 123456.789012345, 1e-320, 0.1};
  {
    TelemetryWriter w(path.string());
    ASSERT_TRUE(w.ok());
    for (const double v : values) w.add(v);
    w.end_row();
  }
  std::string expected;
  for (std::size_t i = 0; i < values.size(); ++i) expected += (i ? "," : "") + fmt::format("{:.10g}", values[i]);
  std::ifstream in(path);
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  EXPECT_EQ(line, expected);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace chaser::sim
