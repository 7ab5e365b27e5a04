// chaser fmea: the failure-mode and effects analysis of the manually controlled approach
// (Zhou 2018; docs/invsim.md, "chaser fmea").
#include <algorithm>
#include <array>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/fmea_report.hpp"
#include "invsim/fmea.hpp"
#include "io/invsim_loader.hpp"

namespace chaser::cli {
namespace {

bool write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  return static_cast<bool>(out);
}

void print_summary(const std::vector<invsim::FmeaRow>& rows, double seconds, int threads) {
  std::array<int, 3> per_class{0, 0, 0};
  for (const auto& row : rows) ++per_class[static_cast<int>(row.risk)];
  std::cout << fmt::format("chaser fmea: {} modes in {:.2f} s on {} thread{}: class I {}, class II {}, class III {}\n",
                           rows.size(), seconds, threads, threads == 1 ? "" : "s", per_class[0], per_class[1],
                           per_class[2]);
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
  const model::InvSimParams& params = *loaded.params;
  std::error_code ec;
  std::filesystem::create_directories(args.out_dir, ec);
  if (ec) {
    std::cerr << fmt::format("chaser fmea: cannot create output directory {}: {}\n", args.out_dir, ec.message());
    return kExitFailure;
  }
  const int threads = args.threads.value_or(static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
  const auto start = std::chrono::steady_clock::now();
  const std::vector<invsim::FmeaRow> rows =
      invsim::run_fmea(params, invsim::fmea_cases(params, loaded.faults), threads);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const std::filesystem::path out(args.out_dir);
  for (const auto& [name, text] : {std::pair{"fmea.csv", fmea_csv(params, rows)},
                                   std::pair{"fmea.md", fmea_markdown(params, rows)}}) {
    if (!write_text(out / name, text)) {
      std::cerr << fmt::format("chaser fmea: cannot write {}\n", (out / name).string());
      return kExitFailure;
    }
  }
  print_summary(rows, seconds, threads);
  std::cout << fmt::format("  wrote {} and {}\n", (out / "fmea.csv").string(), (out / "fmea.md").string());
  return kExitOk;
}

}  // namespace chaser::cli
