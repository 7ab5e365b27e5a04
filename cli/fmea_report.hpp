#pragma once
// The files of `chaser fmea` (docs/invsim.md, "chaser fmea"): fmea.csv, one row per layout and mode;
// fmea.md, Zhou 2018's Tables 4, 5 and 6 in the paper's layout and the ranking by risk for the
// scenario's own layout, then the comparison of the layouts (Schemes I and II, section 4.2) and the
// --optimize search; optimize.csv, every candidate of the search, best first; and the per-step
// histories that python/plot_invsim.py draws.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "invsim/fmea.hpp"
#include "invsim/layout_study.hpp"
#include "io/invsim_loader.hpp"
#include "model/invsim.hpp"

namespace chaser::cli {

struct FmeaLayout {
  std::string name;         // "baseline" for the scenario's own layout, else the configuration's
  std::string description;
  model::InvSimParams params;
  std::vector<invsim::FmeaRow> rows;
};

struct FmeaOptions {
  bool three_axis = false;    // --three-axis
  bool optimize = false;      // --optimize
  bool history = false;       // --history
  bool nominal_only = false;  // --nominal-only: the nominal case alone (a calibration reads nothing else)
  int threads = 1;            // workers
};

// What `chaser fmea` computes, for the command and for chaser.fmea alike.
struct FmeaStudy {
  // The scenario's own layout ("baseline") and each of its configurations, every mode of
  // invsim::fmea_cases, rows ranked within each layout.
  std::vector<FmeaLayout> layouts;
  // With `history`: [l][i] the history of mode i on layout l (with several noise draws, the worst
  // draw's: invsim::FmeaHistory). Without, the layouts share their flights
  // (invsim::run_fmea_of_configurations).
  std::vector<std::vector<invsim::FmeaHistory>> histories;
  std::size_t flights = 0;  // distinct flights flown for the layouts' rows
  // With `optimize`: every candidate of the scenario's free choices, best first (invsim::search_layouts).
  std::optional<std::vector<invsim::LayoutCandidate>> optimized;
  std::size_t search_flights = 0;  // distinct flights of the search
};

// Why `options` cannot run on this (loaded, valid) scenario, or "": --optimize without free
// choices, --nominal-only with --optimize or --three-axis. Named as the command's options.
std::string fmea_options_problem(const io::InvSimLoadResult& loaded, const std::string& scenario_path,
                                 const FmeaOptions& options);
FmeaStudy run_fmea_study(const io::InvSimLoadResult& loaded, const FmeaOptions& options);

// The study's files by name: fmea.csv, fmea.md (`keep` candidates of the search listed) and, with
// the search, optimize.csv. (The histories: write_fmea_histories.)
std::vector<std::pair<std::string, std::string>> fmea_files(const FmeaStudy& study, int keep);

std::string fmea_csv(const std::vector<FmeaLayout>& layouts);
// `optimized`: the --optimize candidates, best first (nullptr: no search); `keep` of them are listed.
std::string fmea_markdown(const std::vector<FmeaLayout>& layouts,
                          const std::vector<invsim::LayoutCandidate>* optimized, int keep);
std::string optimize_csv(const std::vector<invsim::LayoutCandidate>& candidates);

// Table 6's 4 x 4 grid of the multi-axis modes' classes, after `title` (nothing without 16 of them).
void append_table6(std::string& md, const model::InvSimParams& p, const std::vector<invsim::FmeaRow>& rows,
                   const std::string& title);

// Markdown sections comparing the layouts and the search (cli/fmea_layout_report.cpp).
void append_reconfiguration(std::string& md, const std::vector<FmeaLayout>& layouts);
void append_optimization(std::string& md, const std::vector<FmeaLayout>& layouts,
                         const std::vector<invsim::LayoutCandidate>& optimized, int keep);

// The columns of a history file (DIR/history/<layout>/<NN>_<mode>.csv), in order, and one sample's
// values in the file's units (angles in degrees; the last six, pulse_x .. count_z, integers). The
// file rounds them (t to 0.1 s, positions to 10 um, velocities to 1 um/s, angles to 1e-5 deg, u to
// 7 digits); chaser.fmea(history=True) gives them whole.
inline constexpr std::array<std::string_view, 24> kHistoryColumns{
    "t_s",         "x_m",       "y_m",         "z_m",         "vx_mps",       "vy_mps",
    "vz_mps",      "x_desired_m", "y_desired_m", "z_desired_m", "roll_deg",     "pitch_deg",
    "yaw_deg",     "azimuth_deg", "elevation_deg", "ux_mps2",   "uy_mps2",      "uz_mps2",
    "pulse_x",     "pulse_y",   "pulse_z",     "count_x",     "count_y",      "count_z"};
inline constexpr std::size_t kHistoryIntegerColumns = 6;  // the last six
std::array<double, kHistoryColumns.size()> history_values(const invsim::InvSimSample& sample);

// DIR/history/index.csv (configuration,mode,file,draws,draw_seed: the noise draws the row combines and
// the seed of the one shown, empty without noise) and DIR/history/<layout>/<NN>_<mode>.csv, one row
// per IS step, for every row of every layout; false (with `error`) on an I/O failure.
bool write_fmea_histories(const std::filesystem::path& dir, const std::vector<FmeaLayout>& layouts,
                          const std::vector<std::vector<invsim::FmeaHistory>>& histories,
                          std::string& error);

}  // namespace chaser::cli
