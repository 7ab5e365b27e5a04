#pragma once
// The diagnosis schemes as the rest of the product sees them: one row each in one table, in the
// order of their slots. Slot i of FdirOutput::schemes, FdirEpisode::schemes and the run's results
// is row i; from its name come the scheme's telemetry channels (residual_<name>_1..n, glr_<name>,
// alarm_<name>, candidate_<name>, confirmed_<name>), its runs.csv columns (<name>_detection_s ...),
// its summary.json entry (fdir.<name>), its line in a run's report and its rows in a campaign's
// Table 2. Adding a scheme is its module and one row here: nothing downstream names a scheme.
//
// The first three are Fonod 2015's position- and attitude-model schemes and Chaser's impulse-deficit
// detector; step_fdir runs them itself, since their isolation, the event resolution and the
// deficit bank are coupled (flight/fdir.hpp). A scheme with a `step` is run by step_fdir after
// them, each period, on the period's measurements and the FDI's inputs; its first alarm and first
// confirmation are latched for it. The fourth row, the observer bank, and the fifth, the active
// checks read from the rates, are such schemes.
#include <string>
#include <vector>

#include "flight/fdi/fdi_scheme.hpp"
#include "model/messages.hpp"

namespace chaser::flight {

namespace fdi {
struct DeficitDecision;
}
struct FdirParams;
struct FdirState;
struct FdirInput;

inline constexpr int kMaxDiagnosisSchemes = 6;  // the five built in and one more
inline constexpr int kPositionScheme = 0;
inline constexpr int kAttitudeScheme = 1;
inline constexpr int kDeficitScheme = 2;
inline constexpr int kBankScheme = 3;  // the observer bank (flight/fdi/observer_bank.hpp), a registered row
inline constexpr int kRateCheckScheme = 4;  // the active checks read from the rates (flight/fdi/rate_check.hpp), the same

struct DiagnosisScheme {
  std::string name;           // a plain name: it names channels, columns and keys
  int residual_channels = 0;  // residual_<name>_1..n in telemetry (0: none)
  bool (*enabled)(const FdirParams&) = nullptr;
  // A scheme module's period; nullptr for the three step_fdir runs itself. Lanes of the watched set.
  // A scheme keeps its own state in FdirState (the FDIR's state is the one place a run's flight
  // software state lives), reading the rest of it at most.
  void (*step)(const FdirParams&, FdirState&, const model::SensorMeasurements&, const FdirInput&,
               fdi::FdiSchemeOutput&) = nullptr;
  // The deficit bank's decision the scheme may take its name from (flight/fdi/deficit_isolation.hpp),
  // nullptr where it names without it: where the two agree on the confirmed lane, the bank's reading
  // of the fault (stuck open, leak, its size) goes with the name to the recovery and the episode.
  const fdi::DeficitDecision* (*deficit)(const FdirState&) = nullptr;
};

// The table, in slot order.
const std::vector<DiagnosisScheme>& diagnosis_schemes();

// Adds a scheme in the next slot and returns it. Before anything reads the table (a scheme module
// registers itself at start-up): runs.csv's columns are fixed when first asked for. Refuses (returns
// -1) a name that is not plain or is taken, and a table already full.
int register_diagnosis_scheme(DiagnosisScheme scheme);

}  // namespace chaser::flight
