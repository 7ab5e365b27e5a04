// chaser campaign --mpi under `mpirun -n 2`: every result file is byte-identical to the same
// campaign flown by threads, because run i depends only on (campaign seed, i) and rank 0 writes
// rows strictly in index order. Also: --shard, --resume and --keep-telemetry work with --mpi, and
// bad input ends every rank with exit 2 instead of leaving one waiting. Skipped when mpirun is
// not on PATH or chaser was built without MPI.
#include <gtest/gtest.h>

#include "tests/support/command.hpp"

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace campaign_mpi_test {

namespace fs = std::filesystem;

using chaser::testing::CommandResult;
using chaser::testing::read_file;

CommandResult shell(const std::string& command) { return chaser::testing::run_shell(command); }

bool mpirun_found() {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && fs::exists(fs::path(dir) / "mpirun")) return true;
  return false;
}

// What works as root in a container: the two OMPI_ALLOW_* variables, shared-memory transport only,
// no core binding (rank 0's coordinator and worker thread may share a core), more ranks than cores
// allowed. `timeout` turns a hang into a failure. Under make sanitize the ranks' leak check is off:
// OpenMPI leaves allocations of its dlopened components at MPI_Finalize (frames in unloaded
// modules, which no LeakSanitizer suppression can name); AddressSanitizer's other checks stay on,
// and the campaign code's own leaks are checked by test_campaign without MPI.
const std::string kMpiEnv =
    "ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ";

std::string mpirun(int ranks) {
  return kMpiEnv + "timeout 300 mpirun -n " + std::to_string(ranks) +
         " --oversubscribe --bind-to none --mca btl self,vader " + std::string(CHASER_BINARY) + " ";
}

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = chaser::testing::scratch_path("chaser_campaign_mpi_" + name);
  fs::remove_all(dir);
  return dir;
}

// Short runs (100 s to the onset, 20 s after it), 3 per case, all five cases: 15 runs.
const std::string kShort =
    "campaign scenarios/msr_terminal.yaml --set campaign.onset_s=100 --set campaign.horizon_after_onset_s=20 --runs 3 ";

const std::vector<std::string> kResultFiles = {"runs.csv",        "glr_runs.csv", "summary.csv",
                                               "summary.md",      "campaign.json", "glr_envelope.csv",
                                               "runs/0/telemetry.csv", "runs/1/summary.json"};

// A file's text without its wall-clock lines (summary.json's wall_s, its parts wall_*_s and
// simulated_s_per_wall_s measure the machine, not the run).
std::string without_wall_clock(const std::string& text) {
  std::istringstream in(text);
  std::string kept;
  for (std::string line; std::getline(in, line);)
    if (line.find("wall_s") == std::string::npos && line.find("\"wall_") == std::string::npos) kept += line + "\n";
  return kept;
}

void expect_same_files(const fs::path& expected, const fs::path& got) {
  for (const std::string& name : kResultFiles) {
    ASSERT_TRUE(fs::exists(expected / name)) << name;
    EXPECT_EQ(without_wall_clock(read_file(expected / name)), without_wall_clock(read_file(got / name)))
        << name << " differs";
  }
}

class CampaignMpi : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!mpirun_found()) GTEST_SKIP() << "mpirun not on PATH";
    const CommandResult probe = shell(mpirun(1) + "campaign scenarios/msr_terminal.yaml --mpi --threads 0");
    if (probe.output.find("built without MPI") != std::string::npos) {
      EXPECT_EQ(probe.exit_code, 2) << probe.output;
      GTEST_SKIP() << "chaser built without MPI";
    }
  }
};

// Two ranks (rank 0: coordinator, writer and one worker thread; rank 1: one worker) against two
// threads in one process: same bytes in every result file, the kept telemetry included.
TEST_F(CampaignMpi, TwoRanksWriteTheSameBytesAsThreads) {
  const fs::path threaded = fresh_dir("threads"), spread = fresh_dir("ranks");
  const CommandResult t = shell(std::string(CHASER_BINARY) + " " + kShort + "--threads 2 --keep-telemetry 2 --out " +
                                threaded.string());
  ASSERT_EQ(t.exit_code, 0) << t.output;
  const CommandResult m = shell(mpirun(2) + kShort + "--mpi --keep-telemetry 2 --out " + spread.string());
  ASSERT_EQ(m.exit_code, 0) << m.output;
  EXPECT_NE(m.output.find("campaign: 15 runs; wrote"), std::string::npos) << m.output;  // rank 0 alone reports
  expect_same_files(threaded, spread);
  EXPECT_FALSE(fs::exists(spread / "runs" / "2")) << "--keep-telemetry 2 keeps runs 0 and 1 only";
}

// A campaign killed mid-row (runs.csv cut inside a row) resumed under MPI, and a shard under MPI,
// both equal the threaded results.
TEST_F(CampaignMpi, ResumeAndShardWorkUnderMpi) {
  const fs::path whole = fresh_dir("whole"), resumed = fresh_dir("resumed");
  ASSERT_EQ(shell(std::string(CHASER_BINARY) + " " + kShort + "--keep-telemetry 2 --out " + whole.string()).exit_code, 0);
  fs::copy(whole, resumed, fs::copy_options::recursive);
  const std::string runs = read_file(whole / "runs.csv");
  const std::size_t cut = runs.find('\n', runs.size() / 2) - 7;  // a torn row half-way through
  fs::resize_file(resumed / "runs.csv", cut);
  fs::remove(resumed / "summary.csv");
  const CommandResult r = shell(mpirun(2) + kShort + "--mpi --resume --keep-telemetry 2 --out " + resumed.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("found done, resumed"), std::string::npos) << r.output;
  expect_same_files(whole, resumed);

  const fs::path shard_threads = fresh_dir("shard_t"), shard_ranks = fresh_dir("shard_m");
  const std::string shard = kShort + "--shard 1/2 --keep-telemetry 9 --out ";
  ASSERT_EQ(shell(std::string(CHASER_BINARY) + " " + shard + shard_threads.string()).exit_code, 0);
  const CommandResult s = shell(mpirun(2) + shard + shard_ranks.string() + " --mpi");
  ASSERT_EQ(s.exit_code, 0) << s.output;
  for (const std::string name : {"runs.csv", "glr_runs.csv", "summary.csv", "summary.md", "campaign.json",
                                 "runs/8/telemetry.csv"})
    EXPECT_EQ(read_file(shard_threads / name), read_file(shard_ranks / name)) << name << " differs";
}

// Bad input found by every rank (--threads 0), ranks that disagree on the campaign, or bad input
// found by rank 0 alone (--out already holds a campaign): exit 2 with the message, and no rank is
// left waiting (timeout would give 124).
TEST_F(CampaignMpi, BadInputEndsEveryRankWithExit2) {
  const fs::path dir = fresh_dir("bad");
  const CommandResult zero = shell(mpirun(2) + kShort + "--mpi --threads 0 --out " + dir.string());
  EXPECT_EQ(zero.exit_code, 2) << zero.output;
  EXPECT_NE(zero.output.find("--threads: must be >= 1"), std::string::npos) << zero.output;

  // Rank 1 given another seed (as if its node read another scenario): refused before any run.
  const std::string rank = std::string(CHASER_BINARY) + " " + kShort + "--mpi --cases none --out " + dir.string();
  const CommandResult other = shell(kMpiEnv + "timeout 300 mpirun --oversubscribe --bind-to none --mca btl self,vader -n 1 " +
                                    rank + " : -n 1 " + rank + " --seed 7");
  EXPECT_EQ(other.exit_code, 2) << other.output;
  // Found by a torn line here in a fresh-root run: each rank now writes a message in one write,
  // so the two ranks' lines on the shared stderr cannot interleave inside a line.
  EXPECT_NE(other.output.find("MPI rank 1 prepared another campaign than rank 0"), std::string::npos) << other.output;
  EXPECT_FALSE(fs::exists(dir / "runs.csv"));

  ASSERT_EQ(shell(mpirun(2) + kShort + "--mpi --cases none --out " + dir.string()).exit_code, 0);
  const CommandResult again = shell(mpirun(2) + kShort + "--mpi --cases none --out " + dir.string());
  EXPECT_EQ(again.exit_code, 2) << again.output;
  EXPECT_NE(again.output.find("already holds a campaign"), std::string::npos) << again.output;
}

}  // namespace campaign_mpi_test
