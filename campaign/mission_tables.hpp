#pragma once
// COMRADE's whole servicing mission over dispersed runs (the comrade-mission preset, one campaign per
// spin case; docs/servicing.md, "The whole mission over dispersed runs"): per case, how many runs met
// every phase's requirements (sim/phase_verdicts.hpp, runs.csv's mission_met), and where runs fail:
// for each phase of the mission the runs that broke it, and the phase each failing run broke first.
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace chaser::campaign {

struct MissionColumn {
  std::string name;  // the spin case
  int runs = 0;      // rows in runs.csv
  int flown = 0;     // status ok
  int mission_met = 0;  // of the flown, every phase met
  // Of the flown, per phase broken (sim::kMissionPhases' order, then "other"): the runs that broke
  // it, and the runs whose first phase broken it was.
  std::vector<std::pair<std::string, int>> not_met;
  std::vector<std::pair<std::string, int>> first_not_met;
};

// One case's column from its runs.csv (a campaign of a capture scenario: its mission_met and
// phases_not_met columns, the latter the phases' bits); nullopt with `error` set when the file cannot be read or lacks them.
std::optional<MissionColumn> read_mission_column(const std::string& name, const std::string& runs_csv,
                                                 std::string& error);

// mission.md: per case the runs meeting every phase, and per phase the runs that broke it (first).
std::string mission_markdown(const std::vector<MissionColumn>& columns);
// mission.csv: case,phase,runs_not_met,runs_first_not_met,runs_flown, per phase broken; the phase
// "every" first: the runs that broke any phase (each broke a first one).
std::string mission_csv(const std::vector<MissionColumn>& columns);

}  // namespace chaser::campaign
