#pragma once
// One closed-loop run: the fixed-order schedule of plant and flight blocks, period after period.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "flight/flight_software.hpp"
#include "model/scenario.hpp"
#include "sim/mission_monitor.hpp"
#include "sim/phase_sequence.hpp"
#include "sim/escape_result.hpp"
#include "sim/phase_verdicts.hpp"
#include "sim/reach_result.hpp"
#include "sim/telemetry.hpp"

namespace chaser::sim {

struct RunOptions {
  std::string telemetry_path;  // empty: no telemetry (campaigns, benchmarks); ".csv" or ".npy" (sim/telemetry.hpp)
  std::vector<std::string> telemetry_channels;  // name patterns ('*' and '?'); empty: every channel
  // Telemetry in memory as well as (or instead of) the file, with the same channels: filled with
  // one row per period when set (the Python module). Its channels are set by the run.
  TelemetryRows* telemetry_rows = nullptr;
  bool record_glr_per_second = false;  // fill RunResult::glr_max_per_s (threshold selection)
};

// What one FDI scheme concluded over the run (times from the start of the run).
struct SchemeResult {
  bool enabled = false;
  double alarm_s = -1;        // [s] first GLR alarm, -1: none
  double isolated_s = -1;     // [s] thruster confirmed, -1: none
  int isolated_thruster = model::kNoThruster;  // index; its name is model::thruster_name
  // With isolation_method deficit: what the deficit bank read from the fit (flight/fdi/deficit_isolation.hpp).
  std::optional<model::FaultKind> diagnosed_kind;  // empty: no diagnosis
  double diagnosed_size = 0;   // [-] leak a or loss -b; 1 for stuck open / closed
  double estimated_onset_s = -1;  // [s] the onset the fit found
};

struct FdirResult {
  // Each scheme's, in the order of flight::diagnosis_schemes() (position, attitude, deficit, ...).
  std::vector<SchemeResult> schemes;
  // The FDIR as a whole: the first alarm of any scheme, the first confirmed thruster.
  double detection_s = -1;       // [s] -1: none
  double isolation_s = -1;       // [s] -1: none
  int isolated_thruster = model::kNoThruster;   // index
  double recovery_s = -1;        // [s] the recovery this diagnosis triggered; -1: none
  int recovered_thruster = model::kNoThruster;  // index of the thruster the recovery acted on
  // Every diagnosis in order (the FDI watches again after a recovery): the fields above are the
  // first's; empty entries' `episodes` are empty.
  std::vector<FdirResult> episodes;
  double stood_down_s = -1;      // [s] the diagnosis stood down at the capture (flight/flight_software.cpp); -1: not
};

// The multi-estimator supervisor's switching over the run (fdi.supervisor; flight/fdi/mode_supervisor.hpp).
struct SupervisorResult {
  bool enabled = false;
  int switches = 0;                        // mode switches in the run
  int thruster = model::kNoThruster;       // the last mode's thruster (index), kNoThruster: nominal
  flight::fdi::SupervisorFault fault = flight::fdi::SupervisorFault::kNone;  // and its fault
  std::vector<flight::fdi::SupervisorSwitch> log;  // the first kMaxSupervisorSwitches switches
};

struct RunResult {
  MissionFigures figures;
  double propellant_used_kg = 0;  // [kg]
  double simulated_s = 0;         // [s] simulated time actually flown (less than duration if diverged)
  double wall_s = 0;              // [s] wall-clock time of the run (with the design when done by the run)
  // Its parts: the flight software's set-up (the FDI designs) when done by the run, the closed loop
  // (telemetry rows handed over included), and waiting for the telemetry file to be finished.
  double wall_design_s = 0;       // [s]
  double wall_loop_s = 0;         // [s]
  double wall_files_s = 0;        // [s]
  std::int64_t periods = 0;
  std::int64_t infeasible_allocations = 0;  // periods where the TMF could not reach the demand exactly
  std::int64_t active_checks = 0;           // periods whose command carried an active check's test pulse
  // Thruster saturation: the largest on-time any thruster was commanded (a fraction of the period)
  // and the periods in which some thruster was commanded the whole period (no margin left in it).
  double max_on_fraction = 0.0;             // [-]
  std::int64_t saturated_periods = 0;
  bool telemetry_ok = true;
  FdirResult fdir;
  SupervisorResult supervisor;
  // With RunOptions::record_glr_per_second: the largest GLR statistic S of each scheme in each whole
  // second of the run, by scheme slot per second (index floor(t)); 0 for a disabled scheme.
  std::vector<std::array<float, flight::kMaxDiagnosisSchemes>> glr_max_per_s;
  // The phases flown in order, with their start and end times and the reason each ended
  // (sim/run_phases.hpp); a run ended early ends its last phase there.
  std::vector<FlownPhase> phases;
  // With a capture: the reach against COMRADE Table 2 (sim/reach_result.hpp).
  ReachResult reach;
  // With capture.escape: the escape against Chaser's requirements (sim/escape_result.hpp).
  EscapeResult escape;
  // Each phase's figures while it was flown, by its index in the run's phases (sim/phase_verdicts.hpp).
  std::vector<PhaseFigures> phase_figures;
};

// A scheme's result by its name (flight/diagnosis_schemes.hpp); the name must be in the table.
const SchemeResult& scheme_result(const FdirResult& fdir, std::string_view name);

// One run where the flight software is built from the same scenario as the plant (nominal = truth).
RunResult run_scenario(const model::Scenario& scenario, const RunOptions& options = {});

// One run of a plant built from `truth` (a campaign's dispersed chaser, its seed and fault) flown by
// flight software designed beforehand from the nominal scenario (make_flight_params). The design,
// FDI included, is then done once per campaign and shared read-only by every run and thread.
RunResult run_scenario(const model::Scenario& truth, const flight::FlightParams& flight_params,
                       const RunOptions& options = {});

}  // namespace chaser::sim
