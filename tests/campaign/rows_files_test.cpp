// Resuming a campaign keeps the rows of its own column set only: a runs.csv with the reach's columns
// resumes as a campaign of a capture scenario and is refused, naming the file, by one without.
#include "campaign/rows_files.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "campaign/glr_envelope.hpp"
#include "core/random.hpp"

namespace chaser::campaign {
namespace {

TEST(RowsFiles, AResumeKeepsTheRowsOfItsOwnColumnSetOnly) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("chaser_rows_files_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  constexpr std::uint64_t kSeed = 7;
  const RunLayout layout({{FaultCase::kNone, 3}});
  {
    std::ofstream runs(dir / "runs.csv", std::ios::binary);
    runs << runs_header(RunColumnSet::kReach) << '\n';
    for (std::int64_t i = 0; i < 2; ++i) {
      RunSetup setup;
      setup.run = i;
      setup.seed = run_seed(kSeed, static_cast<std::uint64_t>(i));
      runs << format_row(error_record(setup), RunColumnSet::kReach) << '\n';
    }
    std::ofstream(dir / "glr_runs.csv", std::ios::binary)
        << kGlrRunsHeader << '\n' << format_glr_line(0, {}) << '\n' << format_glr_line(1, {}) << '\n';
  }
  const RowsScan reach = scan_rows(dir.string(), {0, 3}, layout, kSeed, RunColumnSet::kReach);
  EXPECT_TRUE(reach.error.empty()) << reach.error;
  EXPECT_EQ(reach.runs_done, 2);
  EXPECT_EQ(reach.runs_bytes, std::filesystem::file_size(dir / "runs.csv"));
  EXPECT_EQ(reach.glr_bytes, std::filesystem::file_size(dir / "glr_runs.csv"));

  const RowsScan standard = scan_rows(dir.string(), {0, 3}, layout, kSeed, RunColumnSet::kStandard);
  EXPECT_EQ(standard.runs_done, 0);
  EXPECT_NE(standard.error.find("runs.csv has other columns"), std::string::npos) << standard.error;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace chaser::campaign
