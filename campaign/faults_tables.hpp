#pragma once
// Thruster faults in COMRADE's synchronised flight over dispersed runs (the comrade-faults preset;
// docs/fdi.md, "Every thruster's faults over the whole synchronisation"). Per group of fault
// thrusters (each of COMRADE 2018's four, sec. 6.3, and the others pooled) and fault kind, the FDIR
// as a whole: Fonod 2015's indices (missed detections, wrong and right isolations; sec. V) with their
// exact 95 % bounds, the mean and 95th-percentile detection and isolation delays after the onset,
// and COMRADE Table 1 at the end with the scenario's accommodation and with diagnosis only; the
// fault-free runs' false alarms; and the targets judged on them.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "campaign/cases.hpp"

namespace chaser::campaign {

// One group's runs of one fault kind.
struct FaultsCell {
  int runs = 0;   // rows of the case
  int flown = 0;  // status ok: the figures below are theirs
  int false_alarms = 0;  // alarmed before the onset
  int missed = 0, wrong = 0, right = 0;
  std::vector<double> detection_s;  // [s] after the onset, every detected run
  std::vector<double> isolation_s;  // [s] after the onset, every right isolation
  int table1_met = 0;               // COMRADE Table 1 met at the end (runs.csv's capture)
  // The same runs flown with diagnosis only (fdi.recovery: none): Table 1 at the end.
  int diagnosed_flown = 0, diagnosed_table1_met = 0;
  // Mode switches of the accommodated runs: each changes how the allocation flies (a recovery,
  // fdi.recovery; a supervisor's switch, fdi.supervisor.accommodate).
  int switches = 0, max_switches = 0;
};

// The four fault kinds in the campaign's order (campaign/cases.hpp).
inline constexpr std::array<FaultCase, 4> kFaultKinds = {FaultCase::kStuckOpen, FaultCase::kStuckClosed,
                                                         FaultCase::kLeak, FaultCase::kLoss};

struct FaultsColumn {
  std::string name;  // "T1" or "other 20"
  std::array<FaultsCell, 4> kinds;  // kFaultKinds' order
};

struct FaultFreeFigures {
  int runs = 0, flown = 0, false_alarms = 0, table1_met = 0;
  int switches = 0, max_switches = 0;  // mode switches, as FaultsCell's
};

// Adds the rows of a faulty campaign's runs.csv (the FDIR's columns, case, status, capture) to the
// column: `diagnosed` false for the accommodated runs, true for the diagnosis-only ones (their
// Table 1 only). False with `error` set when the file cannot be read or lacks a column.
bool add_faults_runs(FaultsColumn& column, const std::string& runs_csv, bool diagnosed, std::string& error);
// The fault-free campaign's figures; nullopt with `error` set.
std::optional<FaultFreeFigures> read_fault_free(const std::string& runs_csv, std::string& error);

// The columns' runs together, named `name` (the others' column from each of theirs).
FaultsColumn pooled_column(const std::string& name, const std::vector<FaultsColumn>& columns);

// faults.md: the fault-free figures, a table of the groups (columns, then all pooled) by kind, the
// targets (0 false alarms, no stuck-open fault missed, the right thruster named in >= 99 % of the
// faulty runs, Table 1 met in >= 95 % of them) with their verdicts, and, where given, each of the
// thrusters pooled into a group, one by one (`each`: missed, wrong and right per kind).
std::string faults_markdown(const FaultFreeFigures& fault_free, const std::vector<FaultsColumn>& columns,
                            const std::vector<FaultsColumn>& each = {});
// faults.csv: group,case,runs,flown,false_alarms,missed,wrong,right,detection_mean_s,detection_p95_s,
// isolation_mean_s,isolation_p95_s,table1_met,diagnosed_flown,diagnosed_table1_met, a row per group
// and kind, then "all" per kind, then each of `each` per kind; the fault-free row first (group and
// case "none").
std::string faults_csv(const FaultFreeFigures& fault_free, const std::vector<FaultsColumn>& columns,
                       const std::vector<FaultsColumn>& each = {});

}  // namespace chaser::campaign
