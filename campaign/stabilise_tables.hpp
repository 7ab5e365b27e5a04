#pragma once
// COMRADE 2018 Table 8 (ENVISAT's detumbling: the composite's angular rate at the end, per axis)
// from the comrade-stabilise preset's campaigns, one per spin case (docs/servicing.md, "The
// stabilisation over dispersed runs"): means +- 1 sigma as the paper gives them, beside the paper's
// H-infinity column, and the 95th percentiles against Table 3 (the rate below 0.5 deg/s, the braked
// joints within the drives' repeated peak), with the time it took and the propellant.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "campaign/statistics.hpp"
#include "campaign/table5.hpp"

namespace chaser::campaign {

struct StabiliseColumn {
  std::string name;  // the spin case
  int runs = 0;      // rows in runs.csv
  int flown = 0;     // status ok and the stabilisation flown
  Proportion table3_met;                        // over the runs
  std::array<FigureStats, 3> final_rate_deg_s;  // signed, the target's axes (Table 8's)
  FigureStats final_rate_norm_deg_s;            // |w| at the end
  FigureStats below_goal_s;                     // from the stabilisation's start, the runs that got below
  FigureStats peak_load_Nm;                     // the braked joints' largest load per run
  FigureStats propellant_kg;
};

// One spin case's column from its runs.csv (a campaign of a scenario with capture.stabilise);
// nullopt with `error` set when the file cannot be read or lacks the stabilisation's columns.
std::optional<StabiliseColumn> read_stabilise_column(const std::string& name, const std::string& runs_csv,
                                                     std::string& error);

// stabilise.md: Table 8 beside the paper's, with Table 3's limits.
std::string stabilise_markdown(const std::vector<StabiliseColumn>& columns);
// stabilise.csv: one row per case and figure: its statistics, Table 3's limit (NaN: none) and the
// paper's value where it gives one.
std::string stabilise_csv(const std::vector<StabiliseColumn>& columns);

}  // namespace chaser::campaign
