// chaser campaign as a user meets it: bad input exits 2 naming the option, a campaign killed with
// SIGKILL resumes to the very bytes of an uninterrupted one, shards merge.
#include <gtest/gtest.h>

#include "tests/support/command.hpp"

#include <signal.h>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;

using chaser::testing::CommandResult;
using chaser::testing::read_file;

CommandResult chaser(const std::string& args) {
  return chaser::testing::run_shell(std::string(CHASER_BINARY) + " " + args);
}

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = chaser::testing::scratch_path("chaser_campaign_cli_" + name);
  fs::remove_all(dir);
  return dir;
}

// Short runs: 100 s to the onset, 20 s after it (1200 periods, a few ms each).
const std::string kShort =
    "campaign scenarios/msr_terminal.yaml --set campaign.onset_s=100 --set campaign.horizon_after_onset_s=20 ";

void expect_bad(const std::string& args, const std::string& fragment) {
  const CommandResult r = chaser(kShort + args);
  EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
  EXPECT_NE(r.output.find(fragment), std::string::npos) << args << "\n" << r.output;
}

TEST(CampaignCli, BadInputExitsWith2AndNamesTheOption) {
  const std::string out = "--out " + fresh_dir("bad").string() + " ";
  expect_bad(out + "--cases none,bogus", "--cases: unknown case 'bogus' (allowed: none, stuck_open, stuck_closed, leak, loss)");
  expect_bad(out + "--runs 0", "--runs");
  expect_bad(out + "--runs leak=-2", "--runs");
  expect_bad(out + "--shard 3/3", "--shard: expected I/M with whole numbers 0 <= I < M (got '3/3')");
  expect_bad(out + "--shard x", "--shard");
  expect_bad(out + "--threads 0", "--threads");
  expect_bad(out + "--preset nope",
             "--preset: unknown preset 'nope' (allowed: fonod2015-table2, comrade-table5, comrade-reach, comrade-stabilise, "
             "comrade-mission, comrade-rigidise, comrade-faults)");
  expect_bad(out + "--set campaign.loss_size_max=0.2", "campaign.loss_size_max: must be >= campaign.loss_size_min");
  expect_bad(out + "--resume", "--resume");
  EXPECT_EQ(chaser("campaign").exit_code, 2);
  EXPECT_EQ(chaser("campaign merge --out " + fresh_dir("m0").string()).exit_code, 2);
}

// --preset comrade-table5: one campaign per spin case of the synchronisation (here one run each,
// 3,000 s) and one of ASSIST's approach (--also), table5.md beside them, resumable; refused with a
// shard, on a scenario without a COMRADE target, and --also without the preset, naming the option.
TEST(CampaignCli, ComradeTable5WritesACaseFolderPerSpinCaseAndTheTable) {
  const fs::path dir = chaser::testing::scratch_path("chaser_table5_cli");
  fs::remove_all(dir);
  const std::string preset = "campaign scenarios/comrade_sync.yaml --preset comrade-table5 --also "
                             "scenarios/comrade_assist.yaml --runs 1 --threads 2 --out " + dir.string();
  const CommandResult sync = chaser(preset);
  ASSERT_EQ(sync.exit_code, 0) << sync.output;
  for (const char* spin : {"S1", "S2", "S3", "comrade_assist"}) EXPECT_TRUE(fs::exists(dir / spin / "runs.csv")) << spin;
  const std::string table = read_file(dir / "table5.md");
  EXPECT_NE(table.find("| figure | Table 1 | COMRADE 2018 | S1 | S2 | S3 | comrade_assist |"), std::string::npos) << table;
  EXPECT_NE(table.find("| runs flown of runs | | 100 | 1 of 1 | 1 of 1 | 1 of 1 | 1 of 1 |"), std::string::npos) << table;
  const CommandResult again = chaser(preset + " --resume");  // resumable: every case found done
  EXPECT_EQ(again.exit_code, 0) << again.output;
  EXPECT_EQ(read_file(dir / "table5.md"), table);
  const CommandResult stray = chaser("campaign scenarios/comrade_assist.yaml --also scenarios/comrade_sync.yaml --out " +
                                     dir.string());
  EXPECT_EQ(stray.exit_code, 2);
  EXPECT_NE(stray.output.find("--also: only with --preset comrade-table5"), std::string::npos) << stray.output;
  const CommandResult shard = chaser("campaign scenarios/comrade_assist.yaml --preset comrade-table5 --shard 0/2 --out " +
                                     dir.string());
  EXPECT_EQ(shard.exit_code, 2);
  EXPECT_NE(shard.output.find("leave out --mpi, --shard and --cases"), std::string::npos) << shard.output;
  const CommandResult msr = chaser("campaign scenarios/msr_terminal.yaml --preset comrade-table5 --out " + dir.string());
  EXPECT_EQ(msr.exit_code, 2);
  EXPECT_NE(msr.output.find("--preset comrade-table5: scenarios/msr_terminal.yaml has no COMRADE target"),
            std::string::npos)
      << msr.output;
  fs::remove_all(dir);
}

// --preset comrade-reach: one campaign per combined controller of a capture scenario (here one run
// each, cut to 30 s of the reach), reach.md and reach.csv beside them, each row of runs.csv with the
// reach's columns, resumable; refused on a scenario without a capture section and with a shard.
TEST(CampaignCli, ComradeReachWritesALawFolderPerControllerAndTheTables) {
  const fs::path dir = chaser::testing::scratch_path("chaser_reach_cli");
  fs::remove_all(dir);
  const std::string preset = "campaign scenarios/comrade_capture.yaml --preset comrade-reach --runs 1 --threads 2 "
                             "--set duration_s=2790 --set campaign.horizon_after_onset_s=1290 --out " + dir.string();
  const CommandResult reach = chaser(preset);
  ASSERT_EQ(reach.exit_code, 0) << reach.output;
  for (const char* law : {"hinf", "compliance"}) {
    const std::string runs = read_file(dir / law / "runs.csv");
    EXPECT_NE(runs.find(",reach_final_error_x_m,"), std::string::npos) << law;
    EXPECT_EQ(std::count(runs.begin(), runs.end(), '\n'), 2) << runs;
  }
  const std::string table = read_file(dir / "reach.md");
  EXPECT_NE(table.find("| figure | Table 2 | COMRADE H-inf | H-infinity | COMRADE compliant | compliance |"),
            std::string::npos) << table;
  EXPECT_NE(table.find("| runs flown of runs | | 1 of 1 | 1 of 1 |"), std::string::npos) << table;
  EXPECT_NE(read_file(dir / "reach.csv").find("\nhinf,reach_max_error_x_m,1,"), std::string::npos);
  const CommandResult again = chaser(preset + " --resume");  // resumable: every law found done
  EXPECT_EQ(again.exit_code, 0) << again.output;
  EXPECT_EQ(read_file(dir / "reach.md"), table);
  const CommandResult sync = chaser("campaign scenarios/comrade_sync.yaml --preset comrade-reach --out " + dir.string());
  EXPECT_EQ(sync.exit_code, 2);
  EXPECT_NE(sync.output.find("--preset comrade-reach: scenarios/comrade_sync.yaml has no capture section"),
            std::string::npos) << sync.output;
  const CommandResult shard =
      chaser("campaign scenarios/comrade_capture.yaml --preset comrade-reach --shard 0/2 --out " + dir.string());
  EXPECT_EQ(shard.exit_code, 2);
  EXPECT_NE(shard.output.find("leave out --mpi, --shard, --cases and --also"), std::string::npos) << shard.output;
  fs::remove_all(dir);
}

// --preset comrade-faults: the fault-free campaign, each of COMRADE's four thrusters' and every other
// named one's (here T2 only, one run per kind), each also flown with diagnosis only, faults.md and
// faults.csv beside them, resumable; refused with a count that is not one, on a scenario without a
// synchronisation and with a shard.
TEST(CampaignCli, ComradeFaultsFliesEachThrusterWithAndWithoutAccommodation) {
  const fs::path dir = chaser::testing::scratch_path("chaser_faults_cli");
  fs::remove_all(dir);
  const std::string preset = "campaign scenarios/comrade_sync.yaml --preset comrade-faults --runs 1 --threads 2 "
                             "--set 'campaign.fault_thrusters=[T2]' --out " + dir.string();
  const CommandResult faults = chaser(preset);
  ASSERT_EQ(faults.exit_code, 0) << faults.output;
  for (const char* folder : {"none", "T1", "T5", "T13", "T17", "T2", "diagnosis-only/T1", "diagnosis-only/T2"})
    EXPECT_TRUE(fs::exists(dir / folder / "runs.csv")) << folder;
  EXPECT_FALSE(fs::exists(dir / "T3"));
  // The diagnosis-only runs are the same runs (seeds, faults, onsets), with fdi.recovery=none.
  const auto fault_columns = [](const std::string& runs) {  // seed, case, fault_thruster, fault_size, onset_s
    std::istringstream in(runs);
    std::string line, out;
    std::vector<std::size_t> keep;
    for (bool header = true; std::getline(in, line); header = false) {
      std::vector<std::string> fields;
      std::istringstream row(line);
      for (std::string f; std::getline(row, f, ',');) fields.push_back(f);
      if (header)
        for (std::size_t i = 0; i < fields.size(); ++i)
          if (fields[i] == "seed" || fields[i] == "case" || fields[i] == "fault_thruster" || fields[i] == "fault_size" ||
              fields[i] == "onset_s")
            keep.push_back(i);
      for (const std::size_t i : keep) out += fields.at(i) + ",";
      out += "\n";
    }
    EXPECT_EQ(keep.size(), 5u);
    return out;
  };
  EXPECT_EQ(fault_columns(read_file(dir / "T5" / "runs.csv")), fault_columns(read_file(dir / "diagnosis-only" / "T5" / "runs.csv")));
  const std::string none = read_file(dir / "none" / "runs.csv");
  EXPECT_EQ(std::count(none.begin(), none.end(), '\n'), 3) << none;  // 2 N fault-free runs and the header
  const std::string table = read_file(dir / "faults.md");
  EXPECT_NE(table.find("| fault | | T1 | T5 | T13 | T17 | other 1 | all |"), std::string::npos) << table;
  EXPECT_NE(table.find("| no false alarm in the fault-free runs |"), std::string::npos) << table;
  const std::string csv = read_file(dir / "faults.csv");
  EXPECT_NE(csv.find("\nall,loss,5,"), std::string::npos) << csv;  // 4 + 1 loss runs
  EXPECT_NE(csv.find("\nT2,loss,1,"), std::string::npos) << csv;   // the others one by one
  EXPECT_NE(table.find("| T2 | "), std::string::npos) << table;
  const CommandResult again = chaser(preset + " --resume");  // resumable: every campaign found done
  EXPECT_EQ(again.exit_code, 0) << again.output;
  EXPECT_EQ(read_file(dir / "faults.md"), table);
  const CommandResult zero = chaser("campaign scenarios/comrade_sync.yaml --preset comrade-faults --runs none=3 --out " +
                                    dir.string());
  EXPECT_EQ(zero.exit_code, 2);
  EXPECT_NE(zero.output.find("--runs: --preset comrade-faults takes a count of runs per fault kind"), std::string::npos)
      << zero.output;
  const CommandResult msr = chaser("campaign scenarios/msr_terminal.yaml --preset comrade-faults --out " + dir.string());
  EXPECT_EQ(msr.exit_code, 2);
  EXPECT_NE(msr.output.find("--preset comrade-faults: scenarios/msr_terminal.yaml flies no synchronisation"),
            std::string::npos) << msr.output;
  const CommandResult shard =
      chaser("campaign scenarios/comrade_sync.yaml --preset comrade-faults --shard 0/2 --out " + dir.string());
  EXPECT_EQ(shard.exit_code, 2);
  EXPECT_NE(shard.output.find("leave out --mpi, --shard, --cases and --also"), std::string::npos) << shard.output;
  fs::remove_all(dir);
}

// --preset comrade-rigidise: per rigidisation law the capture flown once, then the runs from it
// (here two of 120 s each); rigidise.md with COMRADE Table 7 beside ours, rigidise.csv, each law's
// runs.csv; refused with a bad count and on a scenario without capture.rigidise.
TEST(CampaignCli, ComradeRigidiseFliesTable7sStartsFromOneCapturePerLaw) {
  const fs::path dir = chaser::testing::scratch_path("chaser_rigidise_cli");
  fs::remove_all(dir);
  const CommandResult r = chaser("campaign scenarios/comrade_capture.yaml --preset comrade-rigidise --runs 2 --threads 2 "
                                 "--out " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string table = read_file(dir / "rigidise.md");
  EXPECT_NE(table.find("| figure | COMRADE H-inf | COMRADE compliant | hinf | compliance |"), std::string::npos) << table;
  EXPECT_NE(table.find("| runs flown of runs | | | 2 of 2 | 2 of 2 |"), std::string::npos) << table;
  EXPECT_NE(table.find("| +-1 on every joint |"), std::string::npos) << table;
  for (const char* law : {"hinf", "compliance"}) {
    const std::string runs = read_file(dir / law / "runs.csv");
    EXPECT_EQ(std::count(runs.begin(), runs.end(), '\n'), 3) << runs;
    EXPECT_NE(runs.find("run,start_rate_deg_s_1,"), std::string::npos) << runs;
  }
  EXPECT_NE(read_file(dir / "rigidise.csv").find("\ncompliance,runs_flown,2\n"), std::string::npos);
  const CommandResult zero = chaser("campaign scenarios/comrade_capture.yaml --preset comrade-rigidise --runs 0 --out " +
                                    dir.string());
  EXPECT_EQ(zero.exit_code, 2);
  EXPECT_NE(zero.output.find("--runs: --preset comrade-rigidise takes a count of runs per law in [1, 100000] (got '0')"),
            std::string::npos) << zero.output;
  const CommandResult sync = chaser("campaign scenarios/comrade_sync.yaml --preset comrade-rigidise --out " + dir.string());
  EXPECT_EQ(sync.exit_code, 2);
  EXPECT_NE(sync.output.find("--preset comrade-rigidise: scenarios/comrade_sync.yaml has no capture.rigidise section"),
            std::string::npos) << sync.output;
  fs::remove_all(dir);
}

// --preset comrade-stabilise: one campaign per spin case of a scenario with capture.stabilise (here
// one run each, the stabilisation cut to 25 s of a 20 s reference), stabilise.md and stabilise.csv
// beside them, each row with the stabilisation's columns; refused on a scenario without the section.
// Then --preset comrade-mission on the same folders.
TEST(CampaignCli, ComradeStabiliseAndMissionWriteASpinCaseFolderPerCaseAndTheirTables) {
  const fs::path dir = chaser::testing::scratch_path("chaser_stabilise_cli");
  fs::remove_all(dir);
  const std::string preset = "campaign scenarios/comrade_capture.yaml --preset comrade-stabilise --runs 1 --threads 2 "
                             "--set duration_s=2920 --set campaign.horizon_after_onset_s=1420 "
                             "--set capture.stabilise.duration_s=20 --out " + dir.string();
  const CommandResult done = chaser(preset);
  ASSERT_EQ(done.exit_code, 0) << done.output;
  for (const char* spin_case : {"S1", "S2", "S3"}) {
    const std::string runs = read_file(dir / spin_case / "runs.csv");
    EXPECT_NE(runs.find(",stabilise_final_rate_x_deg_s,"), std::string::npos) << spin_case;
    EXPECT_EQ(std::count(runs.begin(), runs.end(), '\n'), 2) << runs;
  }
  const std::string table = read_file(dir / "stabilise.md");
  EXPECT_NE(table.find("| figure | Table 3 | COMRADE H-inf | S1 | S2 | S3 |"), std::string::npos) << table;
  EXPECT_NE(table.find("| runs flown of runs | | | 1 of 1 | 1 of 1 | 1 of 1 |"), std::string::npos) << table;
  EXPECT_NE(read_file(dir / "stabilise.csv").find("\nS2,stabilise_peak_load_Nm,1,"), std::string::npos);
  const CommandResult sync =
      chaser("campaign scenarios/comrade_sync.yaml --preset comrade-stabilise --out " + dir.string());
  EXPECT_EQ(sync.exit_code, 2);
  EXPECT_NE(sync.output.find("--preset comrade-stabilise: scenarios/comrade_sync.yaml has no capture.stabilise section"),
            std::string::npos) << sync.output;

  // --preset comrade-mission --resume into the same folder: the same campaigns, resumed with nothing
  // left to fly, and mission.md from their runs' phase verdicts. The reach misses Table 2 in every run here
  // (its rate about z), the stabilisation cut short misses Table 3.
  std::string mission_preset = preset;
  mission_preset.replace(mission_preset.find("comrade-stabilise"), std::string("comrade-stabilise").size(), "comrade-mission");
  const CommandResult mission = chaser(mission_preset + " --resume");
  ASSERT_EQ(mission.exit_code, 0) << mission.output;
  for (const char* spin_case : {"S1", "S2", "S3"}) {
    const std::string runs = read_file(dir / spin_case / "runs.csv");
    EXPECT_NE(runs.find(",mission_met,phases_not_met\n"), std::string::npos) << spin_case;
    EXPECT_EQ(std::count(runs.begin(), runs.end(), '\n'), 2) << runs;  // no run flown again
  }
  const std::string phases = read_file(dir / "mission.md");
  EXPECT_NE(phases.find("| runs (flown to the end) | 1 (1) | 1 (1) | 1 (1) |"), std::string::npos) << phases;
  EXPECT_NE(phases.find("| every phase's requirements met | 0 of 1 | 0 of 1 | 0 of 1 |"), std::string::npos) << phases;
  EXPECT_NE(phases.find("| reach not met (first) | 1 (1) | 1 (1) | 1 (1) |"), std::string::npos) << phases;
  EXPECT_NE(read_file(dir / "mission.csv").find("\nS1,every,1,1,1\n"), std::string::npos);
  const CommandResult no_capture =
      chaser("campaign scenarios/comrade_sync.yaml --preset comrade-mission --out " + dir.string());
  EXPECT_EQ(no_capture.exit_code, 2);
  EXPECT_NE(no_capture.output.find("--preset comrade-mission: scenarios/comrade_sync.yaml has no capture section"),
            std::string::npos) << no_capture.output;
  fs::remove_all(dir);
}

// A scenario's name becomes its case folder under --out (--preset comrade-table5, --also): a name
// that climbs out of --out or replaces it is refused at the key before anything is written.
TEST(CampaignCli, ComradeTable5RefusesAScenarioNameThatIsNotAPlainName) {
  const fs::path root = fresh_dir("name_escape");
  const fs::path out = root / "a" / "b";
  for (const std::string& name : std::vector<std::string>{"../../escaped", root.string() + "/absolute", ".."}) {
    const CommandResult r = chaser("campaign scenarios/comrade_sync.yaml --preset comrade-table5 --also "
                                   "scenarios/comrade_assist.yaml --runs 1 --set 'name=" + name + "' --out " +
                                   out.string());
    EXPECT_EQ(r.exit_code, 2) << name << "\n" << r.output;
    EXPECT_NE(r.output.find("name: must be a plain name"), std::string::npos) << r.output;
  }
  EXPECT_FALSE(fs::exists(root / "escaped"));
  EXPECT_FALSE(fs::exists(root / "absolute"));
  EXPECT_FALSE(fs::exists(out));
  fs::remove_all(root);
}

// Runs a campaign in a child process and kills it with SIGKILL once `rows` rows are on disk.
// Returns false if the campaign finished before it could be killed.
bool kill_campaign_midway(const std::string& args, const fs::path& dir, std::size_t rows) {
  std::vector<std::string> words;
  std::istringstream split(args);
  for (std::string w; split >> w;) words.push_back(w);
  const pid_t pid = chaser::testing::start_process(CHASER_BINARY, words);  // the SIGKILL hits the campaign
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline) {
    const std::string runs = read_file(dir / "runs.csv");
    if (static_cast<std::size_t>(std::count(runs.begin(), runs.end(), '\n')) > rows) break;
    int status = 0;
    if (waitpid(pid, &status, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
}

// The proof of resume: kill -9 mid-way, a torn row appended as a kill during a write
// leaves it, then --resume: every result file equals the uninterrupted campaign's, byte for byte.
TEST(CampaignCli, ResumeAfterSigkillGivesTheUninterruptedBytes) {
  const fs::path whole = fresh_dir("whole"), killed = fresh_dir("killed");
  const std::string args = kShort + "--cases none,stuck_open,leak --runs 60 --threads 2 --seed 3 ";
  const CommandResult full = chaser(args + "--out " + whole.string());
  ASSERT_EQ(full.exit_code, 0) << full.output;
  ASSERT_TRUE(kill_campaign_midway(args + "--out " + killed.string(), killed, 30)) << "finished before the kill";
  std::ofstream(killed / "runs.csv", std::ios::app | std::ios::binary) << "77,123,stuck_open,ok,3,1,1";  // torn
  const CommandResult resumed = chaser(args + "--resume --out " + killed.string());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("found done, resumed"), std::string::npos) << resumed.output;
  for (const char* name : {"runs.csv", "summary.csv", "summary.md", "glr_envelope.csv", "campaign.json"})
    EXPECT_TRUE(read_file(whole / name) == read_file(killed / name)) << name;
}

TEST(CampaignCli, ResumeOfADifferentCampaignIsRefused) {
  const fs::path dir = fresh_dir("different");
  ASSERT_EQ(chaser(kShort + "--cases none --runs 2 --out " + dir.string()).exit_code, 0);
  const CommandResult r = chaser(kShort + "--cases none --runs 2 --seed 5 --resume --out " + dir.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("different campaign (differs in: scenario_hash, campaign_seed)"), std::string::npos)
      << r.output;
}

// Two shards from the command line merge into the one-shard campaign; merging a shard twice or an
// incomplete set is refused with exit code 2.
TEST(CampaignCli, ShardsMergeAndBadMergesExitWith2) {
  const std::string args = kShort + "--runs none=3,loss=2 --threads 1 ";
  const fs::path whole = fresh_dir("mwhole"), s0 = fresh_dir("s0"), s1 = fresh_dir("s1"), merged = fresh_dir("merged");
  ASSERT_EQ(chaser(args + "--out " + whole.string()).exit_code, 0);
  ASSERT_EQ(chaser(args + "--shard 0/2 --out " + s0.string()).exit_code, 0);
  ASSERT_EQ(chaser(args + "--shard 1/2 --out " + s1.string()).exit_code, 0);
  const CommandResult twice = chaser("campaign merge --out " + merged.string() + " " + s0.string() + " " + s0.string());
  EXPECT_EQ(twice.exit_code, 2);
  EXPECT_NE(twice.output.find("overlapping shards"), std::string::npos) << twice.output;
  EXPECT_EQ(chaser("campaign merge --out " + merged.string() + " " + s1.string()).exit_code, 2);
  const CommandResult ok = chaser("campaign merge --out " + merged.string() + " " + s1.string() + " " + s0.string());
  ASSERT_EQ(ok.exit_code, 0) << ok.output;
  for (const char* name : {"runs.csv", "summary.csv", "summary.md", "glr_envelope.csv"})
    EXPECT_TRUE(read_file(whole / name) == read_file(merged / name)) << name;
}

// --keep-telemetry K keeps the telemetry and summary of runs 0..K-1 only.
TEST(CampaignCli, KeepTelemetryOfTheFirstRuns) {
  const fs::path dir = fresh_dir("telemetry");
  ASSERT_EQ(chaser(kShort + "--cases leak --runs 3 --keep-telemetry 2 --out " + dir.string()).exit_code, 0);
  EXPECT_TRUE(fs::exists(dir / "runs" / "1" / "telemetry.csv"));
  EXPECT_TRUE(fs::exists(dir / "runs" / "1" / "summary.json"));
  EXPECT_FALSE(fs::exists(dir / "runs" / "2"));
}

// --rerun I flies run I alone: its telemetry and summary, and run.csv whose row is the campaign's own
// row for that run, byte for byte (each run depends only on scenario, seed and index). An index
// outside the campaign, or an option that makes no sense for one run, is refused.
TEST(CampaignCli, RerunFliesOneRunOfTheCampaign) {
  const fs::path dir = fresh_dir("rerun_campaign");
  const fs::path one = fresh_dir("rerun_one");
  ASSERT_EQ(chaser(kShort + "--cases none,loss --runs 2 --out " + dir.string()).exit_code, 0);
  const CommandResult r = chaser(kShort + "--cases none,loss --runs 2 --rerun 3 --out " + one.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(one / "telemetry.csv"));
  EXPECT_TRUE(fs::exists(one / "summary.json"));
  const std::string runs = read_file(dir / "runs.csv");
  const std::string row = read_file(one / "run.csv");
  const std::size_t header_end = runs.find('\n');
  EXPECT_EQ(row.substr(0, header_end + 1), runs.substr(0, header_end + 1));
  const std::size_t row3 = runs.find("\n3,");
  ASSERT_NE(row3, std::string::npos);
  EXPECT_EQ(row.substr(header_end + 1), runs.substr(row3 + 1));  // run 3 is the last row
  expect_bad("--cases none,loss --runs 2 --rerun 4", "--rerun: run index must be in [0, 3] for this campaign (got 4)");
  expect_bad("--runs 2 --rerun 0 --shard 0/2", "--rerun flies one run");
}

// --rerun ... --of DIR checks that the options describe the campaign DIR holds: without the
// campaign's --runs and --cases, run 3 would be another run (of the default cases), silently. The
// line it prints names the run's case and the campaign it belongs to.
TEST(CampaignCli, RerunOfACampaignFolderRefusesOptionsOfAnotherCampaign) {
  const fs::path dir = fresh_dir("rerun_of_campaign");
  ASSERT_EQ(chaser(kShort + "--cases none,loss --runs 2 --out " + dir.string()).exit_code, 0);
  const CommandResult same = chaser(kShort + "--cases none,loss --runs 2 --rerun 3 --of " + dir.string() +
                                    " --out " + fresh_dir("rerun_of_one").string());
  ASSERT_EQ(same.exit_code, 0) << same.output;
  EXPECT_NE(same.output.find("run 3 of 4: case loss, campaign seed"), std::string::npos) << same.output;
  EXPECT_NE(same.output.find("(none 2, loss 2)"), std::string::npos) << same.output;
  const fs::path other = fresh_dir("rerun_of_other");
  const CommandResult r = chaser(kShort + "--rerun 3 --of " + dir.string() + " --out " + other.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("holds a different campaign (differs in: cases, total_runs)"), std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(other / "summary.json"));
  expect_bad("--runs 2 --of " + dir.string(), "--of: only with --rerun");
}

}  // namespace

namespace {

int shell(const std::string& command) {
  const int status = std::system((command + " >/dev/null 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// python/plot_campaign.py on a real campaign directory (every case, fault-free runs for the GLR
// envelope): it must read what the engine writes and draw all four figures (Fonod 2015 Figs. 8,
// 11, 12 and the outcome bars). Skipped where /usr/bin/python3 lacks numpy or matplotlib.
TEST(CampaignCli, PlotCampaignDrawsEveryFigureFromARealCampaign) {
  if (shell("/usr/bin/python3 -c 'import numpy, matplotlib'") != 0) GTEST_SKIP() << "no numpy/matplotlib";
  const fs::path dir = fresh_dir("plot");
  const CommandResult r = chaser(kShort + "--runs 3 --threads 2 --out " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  ASSERT_EQ(shell("/usr/bin/python3 python/plot_campaign.py " + dir.string()), 0);
  for (const char* png : {"detection_times.png", "isolation_times.png", "outcome.png", "glr_envelope.png"})
    EXPECT_GT(fs::exists(dir / png) ? fs::file_size(dir / png) : 0u, 10000u) << png;
}

}  // namespace
