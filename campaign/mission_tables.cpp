#include "campaign/mission_tables.hpp"

#include <algorithm>
#include <cstdint>

#include <fmt/format.h>

#include "campaign/csv.hpp"
#include "sim/phase_verdicts.hpp"

namespace chaser::campaign {

namespace {

// The count of `phase` in `counts`, added in flight order (sim::kMissionPhases', then "other") if new.
int& count_of(std::vector<std::pair<std::string, int>>& counts, const std::string& phase) {
  for (auto& [name, n] : counts)
    if (name == phase) return n;
  const auto rank = [](const std::string& p) {
    return std::distance(sim::kMissionPhases.begin(),
                         std::find_if(sim::kMissionPhases.begin(), sim::kMissionPhases.end(), [&](const char* n) { return p == n; }));
  };
  const auto at = std::find_if(counts.begin(), counts.end(), [&](const auto& c) { return rank(c.first) > rank(phase); });
  return counts.insert(at, {phase, 0})->second;
}

int count(const std::vector<std::pair<std::string, int>>& counts, const std::string& phase) {
  for (const auto& [name, n] : counts)
    if (name == phase) return n;
  return 0;
}

// Every phase any column names, in order.
std::vector<std::string> phases_named(const std::vector<MissionColumn>& columns) {
  std::vector<std::pair<std::string, int>> all;
  for (const MissionColumn& c : columns)
    for (const auto& [phase, n] : c.not_met) count_of(all, phase);
  std::vector<std::string> out;
  for (const auto& [phase, n] : all) out.push_back(phase);
  return out;
}

}  // namespace

std::optional<MissionColumn> read_mission_column(const std::string& name, const std::string& runs_csv,
                                                 std::string& error) {
  const std::optional<CsvTable> table = read_csv_table(runs_csv, error);
  if (!table) return std::nullopt;
  const auto col = table->columns({"status", "mission_met", "phases_not_met"}, runs_csv,
                                  "(not a campaign of a scenario with a capture section?)", error);
  if (!col) return std::nullopt;
  MissionColumn c;
  c.name = name;
  for (const std::vector<std::string>& f : table->rows) {
    const auto field = [&](int k) -> const std::string& { return f[static_cast<std::size_t>((*col)[static_cast<std::size_t>(k)])]; };
    ++c.runs;
    if (field(0) != "ok") continue;
    ++c.flown;
    c.mission_met += field(1) == "1";
    const std::optional<double> bits = parse_number(field(2));
    if (!bits || *bits < 0.0) continue;
    bool first = true;
    for (std::size_t i = 0; i <= sim::kMissionPhases.size(); ++i) {
      if (((static_cast<std::int64_t>(*bits) >> i) & 1) == 0) continue;
      const std::string phase = i < sim::kMissionPhases.size() ? sim::kMissionPhases[i] : "other";
      ++count_of(c.not_met, phase);
      if (first) ++count_of(c.first_not_met, phase);
      first = false;
    }
  }
  return c;
}

std::string mission_markdown(const std::vector<MissionColumn>& columns) {
  std::string out = "| |";
  for (const MissionColumn& c : columns) out += fmt::format(" {} |", c.name);
  out += "\n|---|";
  for (std::size_t i = 0; i < columns.size(); ++i) out += "---|";
  out += "\n| runs (flown to the end) |";
  for (const MissionColumn& c : columns) out += fmt::format(" {} ({}) |", c.runs, c.flown);
  out += "\n| every phase's requirements met |";
  for (const MissionColumn& c : columns) out += fmt::format(" {} of {} |", c.mission_met, c.flown);
  for (const std::string& phase : phases_named(columns)) {
    out += fmt::format("\n| {} not met (first) |", phase);
    for (const MissionColumn& c : columns) out += fmt::format(" {} ({}) |", count(c.not_met, phase), count(c.first_not_met, phase));
  }
  return out + "\n";
}

std::string mission_csv(const std::vector<MissionColumn>& columns) {
  std::string out = "case,phase,runs_not_met,runs_first_not_met,runs_flown\n";
  for (const MissionColumn& c : columns) {
    out += fmt::format("{},every,{},{},{}\n", c.name, c.flown - c.mission_met, c.flown - c.mission_met, c.flown);
    for (const auto& [phase, n] : c.not_met)
      out += fmt::format("{},{},{},{},{}\n", c.name, phase, n, count(c.first_not_met, phase), c.flown);
  }
  return out;
}

}  // namespace chaser::campaign
