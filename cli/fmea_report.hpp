#pragma once
// The files of `chaser fmea` (docs/invsim.md, "chaser fmea"): fmea.csv, one row per layout and mode;
// fmea.md, Zhou 2018's Tables 4, 5 and 6 in the paper's layout and the ranking by risk for the
// scenario's own layout, then the comparison of the layouts (Schemes I and II, section 4.2) and the
// --optimize search; optimize.csv, every candidate of the search, best first; and the per-step
// histories that python/plot_invsim.py draws.
#include <array>
#include <filesystem>
#include <string>
#include <string_view>
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

// The FMEA of `chaser fmea` without --optimize: the scenario's own layout ("baseline") and each of
// its configurations, every mode of invsim::fmea_cases on `threads` workers, rows ranked within each
// layout. With `histories`, (*histories)[l][i] receives the history of mode i on layout l (with
// several noise draws, the worst draw's: invsim::FmeaHistory).
// `nominal_only`: the nominal case alone (a calibration reads nothing else). Without histories the
// layouts share their flights (invsim::run_fmea_of_configurations); `flights`, when given, receives
// the number flown.
std::vector<FmeaLayout> run_fmea_layouts(const io::InvSimLoadResult& loaded, bool three_axis, int threads,
                                         std::vector<std::vector<invsim::FmeaHistory>>* histories,
                                         bool nominal_only = false, std::size_t* flights = nullptr);

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
