// chaser fmea: the failure-mode and effects analysis of the manually controlled approach and the
// comparison of thruster layouts (Zhou 2018; docs/invsim.md, "chaser fmea").
#include <algorithm>
#include <array>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/fmea_report.hpp"
#include "core/wall_clock.hpp"
#include "core/worker_threads.hpp"
#include "invsim/fmea.hpp"
#include "invsim/layout_study.hpp"
#include "invsim/noise_draws.hpp"
#include "invsim/paper_reading.hpp"
#include "io/invsim_loader.hpp"

namespace chaser::cli {
namespace {

bool write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  return static_cast<bool>(out);
}

// `flights`: the distinct flights flown for the layouts' rows (invsim::run_fmea_of_configurations).
// With `histories` and several noise draws each row's worst draw is flown once more to record it
// (invsim/fmea.cpp, fly_row): the line counts those flights too.
void print_summary(const std::vector<FmeaLayout>& layouts, std::size_t flights, bool histories, double seconds,
                   int threads) {
  const model::InvSimParams& p = layouts.front().params;
  const std::uint64_t draws = invsim::noise_draws_per_mode(p);
  const std::size_t modes = layouts.front().rows.size();  // every layout flies the same modes
  const std::size_t row_count = layouts.size() * modes;
  std::string flown = fmt::format("{} flown", flights);
  if (draws > 1) flown += fmt::format(" x {} noise draws", draws);
  if (draws > 1 && histories) flown += fmt::format(", and {} worst draws again for their histories", row_count);
  std::cout << fmt::format("chaser fmea: {} layout{} x {} mode{} = {} rows, {} in {:.2f} s on {} thread{}; "
                           "pulses.reading {}\n",
                           layouts.size(), layouts.size() == 1 ? "" : "s", modes, modes == 1 ? "" : "s", row_count, flown,
                           seconds, threads, threads == 1 ? "" : "s", invsim::reading_name(p.pulses.reading));
  for (const FmeaLayout& layout : layouts) {
    const invsim::LayoutSummary s = invsim::summarize_layout(layout.rows);
    std::cout << fmt::format("  {}: class I {}, class II {}, class III {}; propellant {:.1f} kg\n", layout.name,
                             s.per_class[0], s.per_class[1], s.per_class[2], s.propellant_kg);
  }
  const auto& rows = layouts.front().rows;
  const auto order = invsim::risk_order(rows);
  for (std::size_t k = 0; k < std::min<std::size_t>(3, order.size()); ++k) {
    const auto& row = rows[order[k]];
    std::cout << fmt::format("  #{} {}: {}, k_p {:.3f}\n", row.rank, row.fmea_case.mode.label,
                             invsim::risk_class_name(row.risk), row.result.k_p);
  }
}

}  // namespace

int fmea_command(const FmeaArgs& args) {
  if (args.threads && *args.threads < 1) {
    std::cerr << fmt::format("chaser fmea: --threads: must be >= 1 (got {})\n", *args.threads);
    return kExitBadInput;
  }
  const io::InvSimLoadResult loaded = io::load_invsim_file(args.scenario_path, args.overrides);
  if (!loaded.errors.empty() || !loaded.params) {
    std::cerr << fmt::format("chaser: {} has {} problem{}:\n", args.scenario_path, loaded.errors.size(),
                             loaded.errors.size() == 1 ? "" : "s")
              << io::format_errors(loaded.errors);
    return kExitBadInput;
  }
  const FmeaOptions options{args.three_axis, args.optimize, args.history, args.nominal_only,
                            args.threads.value_or(default_worker_threads())};
  if (const std::string problem = fmea_options_problem(loaded, args.scenario_path, options); !problem.empty()) {
    std::cerr << "chaser fmea: " << problem << "\n";
    return kExitBadInput;
  }
  std::error_code ec;
  std::filesystem::create_directories(args.out_dir, ec);
  if (ec) {
    std::cerr << fmt::format("chaser fmea: cannot create output directory {}: {}\n", args.out_dir, ec.message());
    return kExitFailure;
  }
  const auto start = std::chrono::steady_clock::now();
  const FmeaStudy study = run_fmea_study(loaded, options);
  const double seconds = seconds_since(start);

  const std::filesystem::path out(args.out_dir);
  for (const auto& [name, text] : fmea_files(study, loaded.study.optimize_keep)) {
    if (!write_text(out / name, text)) {
      std::cerr << fmt::format("chaser fmea: cannot write {}\n", (out / name).string());
      return kExitFailure;
    }
  }
  std::string error;
  if (args.history && !write_fmea_histories(out, study.layouts, study.histories, error)) {
    std::cerr << "chaser fmea: " << error << "\n";
    return kExitFailure;
  }
  print_summary(study.layouts, study.flights, args.history, seconds, options.threads);
  if (study.optimized && !study.optimized->empty()) {
    const invsim::LayoutCandidate& best = study.optimized->front();
    std::cout << fmt::format("  --optimize: {} candidates x {} modes, {} flown; best: {} (class III {}, {:.1f} kg)\n",
                             study.optimized->size(), study.layouts.front().rows.size(), study.search_flights,
                             best.configuration.name, best.summary.per_class[2], best.summary.propellant_kg);
  }
  std::cout << fmt::format("  wrote {}{}\n", (out / "fmea.md").string(),
                           args.history ? " and " + (out / "history").string() : std::string());
  return kExitOk;
}

}  // namespace chaser::cli
