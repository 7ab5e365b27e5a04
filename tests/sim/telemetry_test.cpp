// telemetry.csv from the channel table: the header is the table's names, and every row has a
// finite value for every channel, for thruster sets of 8, 16 (MSR) and 24; the .npy of a run holds
// the same doubles; --channels selects.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <iterator>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/constants.hpp"
#include "io/scenario_loader.hpp"
#include "plant/orbit_plant.hpp"
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

// Runs `s` twice, writing telemetry.csv by record_every_channel (the straight-line row of the whole
// table) and by the table channel by channel (the selection '*'), expects the two files byte for
// byte equal, and returns the first run and the file's text. The folder is named per process, so
// concurrent runs of the suite do not share it.
struct BothRowPaths {
  RunResult fast;
  std::string text;
};
BothRowPaths run_both_row_paths(const model::Scenario& s, const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  BothRowPaths out;
  out.fast = run_scenario(s, {.telemetry_path = (dir / "fast.csv").string(), .telemetry_channels = {}});
  const RunResult table = run_scenario(s, {.telemetry_path = (dir / "table.csv").string(), .telemetry_channels = {"*"}});
  EXPECT_TRUE(out.fast.telemetry_ok && table.telemetry_ok);
  const auto text = [](const std::filesystem::path& p) {
    std::ifstream in(p);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  out.text = text(dir / "fast.csv");
  EXPECT_EQ(out.text, text(dir / "table.csv"));
  std::filesystem::remove_all(dir);
  return out;
}

TEST_P(TelemetryTable, EveryChannelHasAFiniteValueInEveryRow) {
  const int count = GetParam();
  const model::Scenario s = scenario_with(count);
  const auto path = std::filesystem::temp_directory_path() / ("chaser_telemetry_" + std::to_string(count) + ".csv");
  const RunResult r = run_scenario(s, {.telemetry_path = path.string(), .telemetry_channels = {}});
  ASSERT_TRUE(r.telemetry_ok);
  std::ifstream in(path);
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  const std::vector<std::string> header = split(line);
  EXPECT_EQ(header, channel_names(telemetry_channels({.thrusters = count})));
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

// record_every_channel (the straight-line row of the whole table) against its reference, the table
// channel by channel (what a selection takes, here '*': every channel): the same file, byte for
// byte, from a run where the FDI alarms, isolates and recovers (T8 stuck open at 5 s), so its
// columns are not zero.
TEST_P(TelemetryTable, EveryChannelRowIsTheTablesRow) {
  const int count = GetParam();
  model::Scenario s = scenario_with(count);
  if (count == 16) s = *io::load_scenario_file("scenarios/msr_terminal.yaml",
                                               {"faults=[{thruster: T8, kind: stuck_open, onset_s: 5}]", "duration_s=20"})
                            .scenario;
  const BothRowPaths run = run_both_row_paths(s, "chaser_every_channel_" + std::to_string(count));
  if (count == 16) {
    EXPECT_GE(run.fast.fdir.isolation_s, 0.0) << "the run was meant to isolate T8";
  }
}

// The COMRADE chaser's channels (24 thrusters, two sloshing tanks, a tumbling target): the
// straight-line row against the table, byte for byte, and what the new channels hold. Row 0's target
// rate is the spin case's initial condition, bit for bit (S1: 2.5 deg/s about body +Y); the slosh
// masses move only across their tanks' axes (+z here: the constraint holds s_z and s'_z at
// round-off), and the run's thrusting sets them swinging.
TEST(TelemetryTable, ComradeRowsCarryTargetRatesAndSlosh) {
  const io::LoadResult loaded = io::load_scenario_file("scenarios/comrade_envisat.yaml", {"duration_s=30"});
  ASSERT_TRUE(loaded.scenario) << io::format_errors(loaded.errors);
  const model::Scenario& s = *loaded.scenario;
  const TelemetryShape shape = telemetry_shape(s);
  ASSERT_EQ(shape.thrusters, 24);
  ASSERT_EQ(shape.slosh_tanks, 2);
  const BothRowPaths run = run_both_row_paths(s, "chaser_every_channel_comrade");
  const RunResult& fast = run.fast;
  const std::string& fast_text = run.text;

  std::stringstream lines(fast_text);
  std::string line;
  ASSERT_TRUE(std::getline(lines, line));
  const std::vector<std::string> header = split(line);
  EXPECT_EQ(header, channel_names(telemetry_channels(shape)));
  const auto column = [&header](const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    EXPECT_NE(it, header.end()) << name;
    return static_cast<std::size_t>(it - header.begin());
  };
  std::vector<std::vector<double>> rows;
  while (std::getline(lines, line)) {
    std::vector<double> row;
    for (const std::string& f : split(line)) row.push_back(std::strtod(f.c_str(), nullptr));
    rows.push_back(row);
  }
  ASSERT_EQ(static_cast<std::int64_t>(rows.size()), fast.periods);
  const Vec3 spin = plant::initial_target_spin(s.target).omega_target_body_radps;
  for (int i = 0; i < 3; ++i)
    EXPECT_EQ(rows.front()[column(fmt::format("omega_target_body_{}_radps", "xyz"[i]))], spin[i]);
  EXPECT_NEAR(spin.norm(), 2.5 * kPi / 180.0, 1e-15);
  // The tanks' pendulums (axis +z): each mass on its sphere about the hinge L above its rest point,
  // its rate along the sphere; to the CSV's 17 digits.
  const model::ChaserSloshParams slosh = model::chaser_slosh(s.chaser);
  double swing_m = 0.0;
  for (const std::vector<double>& row : rows)
    for (int tank = 1; tank <= 2; ++tank) {
      const auto channel = [&](const char* name, char axis, const char* unit) {
        return row[column(fmt::format("slosh{}_{}_{}_{}", tank, name, axis, unit))];
      };
      const double length = slosh.tanks[static_cast<std::size_t>(tank - 1)].pendulum_length_m;
      ASSERT_GT(length, 0.0);
      const Vec3 from_hinge(channel("s_body", 'x', "m"), channel("s_body", 'y', "m"), channel("s_body", 'z', "m") - length);
      const Vec3 rate(channel("s_dot_body", 'x', "mps"), channel("s_dot_body", 'y', "mps"),
                      channel("s_dot_body", 'z', "mps"));
      EXPECT_NEAR(from_hinge.norm(), length, 1e-12);
      EXPECT_NEAR(rate.dot(from_hinge), 0.0, 1e-12);
      swing_m = std::max({swing_m, std::abs(from_hinge.x()), std::abs(from_hinge.y())});
    }
  EXPECT_GT(swing_m, 1e-6);
}

// Units: every name ends with its unit (or has none), so a reader can take the unit from the name.
TEST(TelemetryTable, NamesEndWithTheirUnit) {
  for (const TelemetryChannel& c : telemetry_channels({.thrusters = 16, .slosh_tanks = 2})) {
    if (c.unit.empty()) continue;
    const std::string suffix = "_" + c.unit;
    ASSERT_GE(c.name.size(), suffix.size());
    EXPECT_EQ(c.name.substr(c.name.size() - suffix.size()), suffix) << c.name;
  }
}

// The run's telemetry reads back to the run's numbers: the CSV and the .npy of one run hold the
// same doubles, bit for bit, and the last row's propellant is the run result's.
TEST(TelemetryFile, CsvAndNpyOfARunHoldTheSameDoublesAsTheRun) {
  const model::Scenario s = scenario_with(16);
  const auto dir = std::filesystem::temp_directory_path() / "chaser_telemetry_formats";
  std::filesystem::create_directories(dir);
  const RunResult csv_run = run_scenario(s, {.telemetry_path = (dir / "t.csv").string(), .telemetry_channels = {}});
  const RunResult npy_run = run_scenario(s, {.telemetry_path = (dir / "t.npy").string(), .telemetry_channels = {}});
  ASSERT_TRUE(csv_run.telemetry_ok && npy_run.telemetry_ok);
  EXPECT_FALSE(std::filesystem::exists(dir / "t.csv.partial"));

  std::ifstream csv(dir / "t.csv");
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  const std::vector<std::string> header = split(line);
  std::vector<double> from_csv;
  while (std::getline(csv, line))
    for (const std::string& field : split(line)) from_csv.push_back(std::strtod(field.c_str(), nullptr));

  std::ifstream npy(dir / "t.npy", std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(npy)), std::istreambuf_iterator<char>());
  ASSERT_GT(bytes.size(), 10u);
  const std::size_t header_len = static_cast<unsigned char>(bytes[8]) | static_cast<unsigned char>(bytes[9]) << 8;
  const std::string dict = bytes.substr(10, header_len);
  EXPECT_NE(dict.find(fmt::format("'shape': ({},)", csv_run.periods)), std::string::npos) << dict;
  EXPECT_NE(dict.find("('propellant_used_kg', '<f8')"), std::string::npos);
  const std::size_t data = 10 + header_len;
  ASSERT_EQ((bytes.size() - data) % sizeof(double), 0u);
  std::vector<double> from_npy((bytes.size() - data) / sizeof(double));
  std::memcpy(from_npy.data(), bytes.data() + data, bytes.size() - data);

  ASSERT_EQ(from_csv.size(), header.size() * static_cast<std::size_t>(csv_run.periods));
  ASSERT_EQ(from_npy.size(), from_csv.size());
  for (std::size_t i = 0; i < from_csv.size(); ++i)
    ASSERT_EQ(std::bit_cast<std::uint64_t>(from_csv[i]), std::bit_cast<std::uint64_t>(from_npy[i]))
        << header[i % header.size()] << " row " << i / header.size();
  const auto column = std::find(header.begin(), header.end(), "propellant_used_kg") - header.begin();
  EXPECT_EQ(from_csv[from_csv.size() - header.size() + static_cast<std::size_t>(column)], csv_run.propellant_used_kg);
  std::filesystem::remove_all(dir);
}

// The rows kept in memory (RunOptions::telemetry_rows, the Python module's) are the file's doubles,
// with every channel or a selection, with a file beside them or alone.
TEST(TelemetryFile, RowsInMemoryAreTheNpyFilesDoubles) {
  const model::Scenario s = scenario_with(16);
  const auto dir = std::filesystem::temp_directory_path() / "chaser_telemetry_rows";
  std::filesystem::create_directories(dir);
  for (const std::vector<std::string>& patterns : {std::vector<std::string>{}, std::vector<std::string>{"glr_*", "ton_*"}}) {
    TelemetryRows with_file, alone;
    const RunResult r = run_scenario(
        s, {.telemetry_path = (dir / "t.npy").string(), .telemetry_channels = patterns, .telemetry_rows = &with_file});
    run_scenario(s, {.telemetry_path = "", .telemetry_channels = patterns, .telemetry_rows = &alone});
    ASSERT_TRUE(r.telemetry_ok);
    EXPECT_EQ(with_file.channels, channel_names(select_channels(telemetry_channels(telemetry_shape(s)), patterns)));
    EXPECT_EQ(with_file.rows(), static_cast<std::size_t>(r.periods));

    std::ifstream npy(dir / "t.npy", std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(npy)), std::istreambuf_iterator<char>());
    ASSERT_GT(bytes.size(), 10u);
    const std::size_t data = 10 + (static_cast<unsigned char>(bytes[8]) | static_cast<unsigned char>(bytes[9]) << 8);
    ASSERT_EQ(bytes.size() - data, with_file.values.size() * sizeof(double));
    EXPECT_EQ(std::memcmp(bytes.data() + data, with_file.values.data(), bytes.size() - data), 0);
    ASSERT_EQ(alone.values.size(), with_file.values.size());
    EXPECT_EQ(std::memcmp(alone.values.data(), with_file.values.data(), alone.values.size() * sizeof(double)), 0);
  }
  std::filesystem::remove_all(dir);
}

// --channels: the chosen channels and t_s, in table order.
TEST(TelemetryFile, ChannelSelectionKeepsTableOrderAndTime) {
  const std::vector<TelemetryChannel> all = telemetry_channels({.thrusters = 16});
  const std::vector<TelemetryChannel> some = select_channels(all, {"ton_cmd_1?", "r_lvlh_*"});
  std::vector<std::string> names = channel_names(some);
  EXPECT_EQ(names, (std::vector<std::string>{"t_s", "r_lvlh_x_m", "r_lvlh_y_m", "r_lvlh_z_m", "ton_cmd_10",
                                             "ton_cmd_11", "ton_cmd_12", "ton_cmd_13", "ton_cmd_14",
                                             "ton_cmd_15", "ton_cmd_16"}));
  EXPECT_EQ(select_channels(all, {}).size(), all.size());
  EXPECT_EQ(unmatched_patterns(all, {"glr_*", "r_lvhl_*"}), std::vector<std::string>{"r_lvhl_*"});
}

}  // namespace
}  // namespace chaser::sim

namespace chaser::sim {
namespace {

// With a target pose sensor the table gains the target estimator's channels (issue 18): the
// straight-line row agrees with the table byte for byte, the first row is NaN (the first pose is
// delivered after its 0.1 s latency, at the second period), and in the closed loop
// (gravity gradient on the tumbling ENVISAT, the chaser's own attitude estimate in the chain) the
// estimate is within 1 deg after the first 60 s (measured over 1,200 s: 0.20 deg RMS, 0.58 deg
// worst past 300 s).
TEST(TelemetryTable, TargetEstimatorChannels) {
  const io::LoadResult loaded = io::load_scenario_file(
      "scenarios/comrade_envisat.yaml",
      {"duration_s=200", "sensors.target_pose={period_s: 0.3333333333333333, attitude_noise_deg: 1.0, latency_s: 0.1}"});
  ASSERT_TRUE(loaded.scenario) << io::format_errors(loaded.errors);
  const model::Scenario& s = *loaded.scenario;
  ASSERT_TRUE(telemetry_shape(s).target_estimator);
  const std::string fast_text = run_both_row_paths(s, "chaser_every_channel_target_estimator").text;
  std::stringstream lines(fast_text);
  std::string line;
  ASSERT_TRUE(std::getline(lines, line));
  const std::vector<std::string> header = split(line);
  const auto at = [&header](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const std::size_t err = at("target_est_att_err_rad"), t_col = at("t_s");
  ASSERT_LT(err, header.size());
  int rows = 0, checked = 0;
  while (std::getline(lines, line)) {
    const std::vector<std::string> row = split(line);
    const double t = std::stod(row[t_col]);
    if (rows++ == 0) {
      EXPECT_EQ(row[err], "nan");
    }
    if (t >= 60.0) {
      EXPECT_LT(std::stod(row[err]), 1.0 * kPi / 180.0) << t;
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);
}

}  // namespace
}  // namespace chaser::sim
