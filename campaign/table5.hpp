#pragma once
// COMRADE 2018 Table 5's "Synchronisation H-infinity" column from the comrade-table5 preset's
// campaigns (docs/campaigns.md, "COMRADE Table 5"): per spin case, the errors at the capture point at
// the end of each run (mean +- 1 sigma, as the paper gives them, and the 95th percentile against
// Table 1), the captures with their 95 % interval, Table 4's least clearances, and the propellant.
#include <optional>
#include <string>
#include <vector>

#include "campaign/statistics.hpp"

namespace chaser::campaign {

// A figure over the runs that flew (NaN rows, from diverged or failed runs, left out).
struct FigureStats {
  int n = 0;
  double mean = 0.0, sd = 0.0;  // sd: the sample's (n - 1)
  double min = 0.0;
  double p95 = 0.0;             // nearest rank: the ceil(0.95 n)-th smallest
  double max = 0.0;
};
FigureStats figure_stats(std::vector<double> values);

struct Table5Column {
  std::string name;  // the case: S1, S2, S3, or the scenario's approach
  int runs = 0;      // rows in runs.csv
  int flown = 0;     // status ok
  Proportion captured;
  FigureStats position_m, speed_mps, attitude_deg, rate_deg_s;
  double least_clearance_unsynchronised_m = 0.0, least_clearance_synchronised_m = 0.0;  // NaN: none
  double propellant_mean_kg = 0.0;
};

// One case's column from its runs.csv; nullopt with `error` set when the file cannot be read or
// lacks a column.
std::optional<Table5Column> read_table5_column(const std::string& name, const std::string& runs_csv,
                                               std::string& error);

// table5.md: the columns beside the paper's and Table 1's / Table 4's limits.
std::string table5_markdown(const std::vector<Table5Column>& columns);
// table5.csv: one row per case, the figures above.
std::string table5_csv(const std::vector<Table5Column>& columns);

}  // namespace chaser::campaign
