#include "campaign/faults_tables.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "campaign/csv.hpp"
#include "campaign/proportion_text.hpp"
#include "campaign/run_row.hpp"
#include "campaign/table5.hpp"

namespace chaser::campaign {

namespace {

// The index of a fault case in kFaultKinds, -1 for none.
int kind_index(const std::string& name) {
  const std::optional<FaultCase> c = parse_case(name);
  const auto at = c ? std::find(kFaultKinds.begin(), kFaultKinds.end(), *c) : kFaultKinds.end();
  return at == kFaultKinds.end() ? -1 : static_cast<int>(at - kFaultKinds.begin());
}

// Every column's cells of one kind added together (the "all" column).
FaultsCell pooled(const std::vector<FaultsColumn>& columns, std::size_t kind) {
  FaultsCell all;
  for (const FaultsColumn& c : columns) {
    const FaultsCell& x = c.kinds[kind];
    all.runs += x.runs;
    all.flown += x.flown;
    all.false_alarms += x.false_alarms;
    all.missed += x.missed;
    all.wrong += x.wrong;
    all.right += x.right;
    all.detection_s.insert(all.detection_s.end(), x.detection_s.begin(), x.detection_s.end());
    all.isolation_s.insert(all.isolation_s.end(), x.isolation_s.begin(), x.isolation_s.end());
    all.table1_met += x.table1_met;
    all.diagnosed_flown += x.diagnosed_flown;
    all.diagnosed_table1_met += x.diagnosed_table1_met;
    all.switches += x.switches;
    all.max_switches = std::max(all.max_switches, x.max_switches);
  }
  return all;
}

// A run's mode switches: its recovery (one at most) and its supervisor's switches.
int mode_switches(const std::string& recovery_s, const std::string& supervisor_switches) {
  const std::optional<double> recovery = parse_number(recovery_s), supervisor = parse_number(supervisor_switches);
  return (recovery && std::isfinite(*recovery) ? 1 : 0) + (supervisor ? static_cast<int>(*supervisor) : 0);
}

std::string switches_pair(int switches, int max_switches, int flown) {
  if (flown == 0) return "-";
  return fmt::format("{:.2f} / {}", static_cast<double>(switches) / flown, max_switches);
}

std::string seconds_pair(const std::vector<double>& v) {
  if (v.empty()) return "-";
  const FigureStats s = figure_stats(v);
  return fmt::format("{:.1f} / {:.1f} s", s.mean, s.p95);
}

std::string verdict(bool met) { return met ? "met" : "**not met**"; }

}  // namespace

FaultsColumn pooled_column(const std::string& name, const std::vector<FaultsColumn>& columns) {
  FaultsColumn out{.name = name, .kinds = {}};
  for (std::size_t k = 0; k < kFaultKinds.size(); ++k) out.kinds[k] = pooled(columns, k);
  return out;
}

bool add_faults_runs(FaultsColumn& column, const std::string& runs_csv, bool diagnosed, std::string& error) {
  const std::optional<CsvTable> table = read_csv_table(runs_csv, error);
  if (!table) return false;
  const auto col = table->columns({"case", "status", "fault_thruster", "fdir_detection_s", "fdir_isolation_s",
                                   "fdir_isolated", "fdir_false_alarm", "fdir_missed", "fdir_wrong_isolation", "capture",
                                   "recovery_s", "supervisor_switches"},
                                  runs_csv, "(not a campaign's runs.csv?)", error);
  if (!col) return false;
  for (const std::vector<std::string>& f : table->rows) {
    const auto field = [&](int k) -> const std::string& { return f[static_cast<std::size_t>((*col)[static_cast<std::size_t>(k)])]; };
    const int kind = kind_index(field(0));
    if (kind < 0) continue;  // case none: read_fault_free's
    FaultsCell& c = column.kinds[static_cast<std::size_t>(kind)];
    const bool ok = field(1) == "ok";
    if (diagnosed) {
      c.diagnosed_flown += ok;
      c.diagnosed_table1_met += ok && field(9) == "1";
      continue;
    }
    ++c.runs;
    if (!ok) continue;
    ++c.flown;
    c.false_alarms += field(6) == "1";
    c.missed += field(7) == "1";
    c.wrong += field(8) == "1";
    const bool right = field(5) == field(2) && field(2) != "0";
    c.right += right;
    const std::optional<double> td = parse_number(field(3)), ti = parse_number(field(4));
    if (td && std::isfinite(*td)) c.detection_s.push_back(*td);
    if (right && ti && std::isfinite(*ti)) c.isolation_s.push_back(*ti);
    c.table1_met += field(9) == "1";
    const int switches = mode_switches(field(10), field(11));
    c.switches += switches;
    c.max_switches = std::max(c.max_switches, switches);
  }
  return true;
}

std::optional<FaultFreeFigures> read_fault_free(const std::string& runs_csv, std::string& error) {
  const std::optional<CsvTable> table = read_csv_table(runs_csv, error);
  if (!table) return std::nullopt;
  const auto col = table->columns({"case", "status", "fdir_false_alarm", "capture", "recovery_s", "supervisor_switches"}, runs_csv,
                                  "(not a campaign's runs.csv?)", error);
  if (!col) return std::nullopt;
  FaultFreeFigures out;
  for (const std::vector<std::string>& f : table->rows) {
    const auto field = [&](int k) -> const std::string& { return f[static_cast<std::size_t>((*col)[static_cast<std::size_t>(k)])]; };
    if (field(0) != "none") continue;
    ++out.runs;
    if (field(1) != "ok") continue;
    ++out.flown;
    out.false_alarms += field(2) == "1";
    out.table1_met += field(3) == "1";
    const int switches = mode_switches(field(4), field(5));
    out.switches += switches;
    out.max_switches = std::max(out.max_switches, switches);
  }
  return out;
}

std::string faults_markdown(const FaultFreeFigures& fault_free, const std::vector<FaultsColumn>& columns,
                            const std::vector<FaultsColumn>& each) {
  std::string out = fmt::format(
      "Fault-free: {} runs ({} flown to the end); false alarms {}; COMRADE Table 1 met at the end in {} of {}; "
      "mode switches per run, mean / max, {}.\n\n",
      fault_free.runs, fault_free.flown, proportion_cell({fault_free.false_alarms, fault_free.flown}),
      fault_free.table1_met, fault_free.flown, switches_pair(fault_free.switches, fault_free.max_switches, fault_free.flown));
  out += "| fault | |";
  for (const FaultsColumn& c : columns) out += fmt::format(" {} |", c.name);
  out += " all |\n|---|---|";
  for (std::size_t i = 0; i <= columns.size(); ++i) out += "---|";
  out += '\n';
  const FaultsColumn all_kinds = pooled_column("all", columns);
  for (std::size_t k = 0; k < kFaultKinds.size(); ++k) {
    std::vector<FaultsCell> cells;
    for (const FaultsColumn& c : columns) cells.push_back(c.kinds[k]);
    cells.push_back(all_kinds.kinds[k]);
    std::string kind(to_string(kFaultKinds[k]));
    std::replace(kind.begin(), kind.end(), '_', ' ');
    const auto row = [&](const char* what, auto cell) {
      out += fmt::format("| {} | {} |", kind, what);
      for (const FaultsCell& c : cells) out += fmt::format(" {} |", cell(c));
      out += '\n';
    };
    row("missed, wrong, right", [](const FaultsCell& c) { return fmt::format("{}, {}, {} of {}", c.missed, c.wrong, c.right, c.flown); });
    row("right isolation", [](const FaultsCell& c) { return proportion_cell({c.right, c.flown}); });
    row("t_d mean / 95th pct.", [](const FaultsCell& c) { return seconds_pair(c.detection_s); });
    row("t_i mean / 95th pct.", [](const FaultsCell& c) { return seconds_pair(c.isolation_s); });
    row("Table 1 met: accommodated; diagnosis only", [](const FaultsCell& c) {
      return fmt::format("{} of {}; {} of {}", c.table1_met, c.flown, c.diagnosed_table1_met, c.diagnosed_flown);
    });
    row("mode switches per run, mean / max", [](const FaultsCell& c) { return switches_pair(c.switches, c.max_switches, c.flown); });
  }
  // The targets, over every faulty run (kFaultKinds[0]: stuck open).
  FaultsCell all;
  const int stuck_open_missed = all_kinds.kinds[0].missed;
  for (const FaultsCell& kind : all_kinds.kinds) {
    all.flown += kind.flown;
    all.right += kind.right;
    all.table1_met += kind.table1_met;
    all.false_alarms += kind.false_alarms;
  }
  const double right_rate = all.flown > 0 ? static_cast<double>(all.right) / all.flown : 0.0;
  const double table1_rate = all.flown > 0 ? static_cast<double>(all.table1_met) / all.flown : 0.0;
  out += "\n| target | measured | verdict |\n|---|---|---|\n";
  out += fmt::format("| no false alarm in the fault-free runs | {} of {} | {} |\n", fault_free.false_alarms,
                     fault_free.flown, verdict(fault_free.false_alarms == 0 && fault_free.flown > 0));
  out += fmt::format("| no stuck-open fault missed | {} missed | {} |\n", stuck_open_missed, verdict(stuck_open_missed == 0));
  out += fmt::format("| the right thruster named in >= 99 % of the faulty runs | {} | {} |\n",
                     proportion_cell({all.right, all.flown}), verdict(all.flown > 0 && right_rate >= 0.99));
  out += fmt::format("| COMRADE Table 1 met at the end in >= 95 % of them (accommodated) | {} | {} |\n",
                     proportion_cell({all.table1_met, all.flown}), verdict(all.flown > 0 && table1_rate >= 0.95));
  out += fmt::format("\nFaulty runs alarmed before their onset: {} of {}.\n", all.false_alarms, all.flown);
  if (each.empty()) return out;
  out += "\nOne by one: missed, wrong, right of the flown runs per kind.\n\n| thruster |";
  for (const FaultCase kind : kFaultKinds) out += fmt::format(" {} |", to_string(kind));
  out += "\n|---|---|---|---|---|\n";
  for (const FaultsColumn& c : each) {
    out += fmt::format("| {} |", c.name);
    for (const FaultsCell& x : c.kinds) out += fmt::format(" {}, {}, {} of {} |", x.missed, x.wrong, x.right, x.flown);
    out += '\n';
  }
  return out;
}

std::string faults_csv(const FaultFreeFigures& fault_free, const std::vector<FaultsColumn>& columns,
                       const std::vector<FaultsColumn>& each) {
  std::string out =
      "group,case,runs,flown,false_alarms,missed,wrong,right,detection_mean_s,detection_p95_s,isolation_mean_s,"
      "isolation_p95_s,table1_met,diagnosed_flown,diagnosed_table1_met,switches,max_switches\n";
  out += fmt::format("none,none,{},{},{},0,0,0,nan,nan,nan,nan,{},0,0,{},{}\n", fault_free.runs, fault_free.flown,
                     fault_free.false_alarms, fault_free.table1_met, fault_free.switches, fault_free.max_switches);
  const auto line = [&](const std::string& group, std::size_t k, const FaultsCell& c) {
    const FigureStats detection = figure_stats(c.detection_s), isolation = figure_stats(c.isolation_s);
    out += fmt::format("{},{},{},{},{},{},{},{}", group, to_string(kFaultKinds[k]), c.runs, c.flown, c.false_alarms,
                       c.missed, c.wrong, c.right);
    for (const double v : {detection.mean, detection.p95, isolation.mean, isolation.p95}) {
      out += ',';
      append_number(out, v);
    }
    out += fmt::format(",{},{},{},{},{}\n", c.table1_met, c.diagnosed_flown, c.diagnosed_table1_met, c.switches,
                       c.max_switches);
  };
  for (const FaultsColumn& c : columns)
    for (std::size_t k = 0; k < kFaultKinds.size(); ++k) line(c.name, k, c.kinds[k]);
  const FaultsColumn all_kinds = pooled_column("all", columns);
  for (std::size_t k = 0; k < kFaultKinds.size(); ++k) line(all_kinds.name, k, all_kinds.kinds[k]);
  for (const FaultsColumn& c : each)
    for (std::size_t k = 0; k < kFaultKinds.size(); ++k) line(c.name, k, c.kinds[k]);
  return out;
}

}  // namespace chaser::campaign
