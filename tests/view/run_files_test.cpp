// A run's folder read by `chaser view`: bad input is named, with its file, and exits 2 with no page.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "tests/support/command.hpp"
#include "view/run_files.hpp"

namespace {

namespace fs = std::filesystem;
using chaser::testing::CommandResult;
using chaser::view::ViewInputError;

CommandResult run_chaser(const std::string& args) { return chaser::testing::run_shell(std::string(CHASER_BINARY) + " " + args); }

// A short MSR run (2 s, 20 rows) in a fresh folder.
fs::path fresh_run(const std::string& name, const std::string& telemetry = "csv") {
  const fs::path dir = chaser::testing::scratch_path(name);
  fs::remove_all(dir);
  const CommandResult r = run_chaser("run scenarios/msr_terminal.yaml --set duration_s=2 --telemetry " + telemetry +
                                     " --out " + dir.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
void write(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

// Every failure: exit 2, the message names the file, no page.
void expect_refused(const fs::path& dir, const std::string& file, const std::string& words) {
  const fs::path page = dir / "view.html";
  fs::remove(page);
  const CommandResult r = run_chaser("view " + dir.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find((dir / file).string()), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(words), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(page));
}

TEST(ViewFiles, AWholeRunReadsAndWritesAPage) {
  const fs::path dir = fresh_run("view_whole");
  const chaser::view::RunFiles files = chaser::view::read_run_files(dir);
  EXPECT_EQ(files.telemetry.rows(), 20U);
  EXPECT_EQ(files.telemetry.channels.front(), "t_s");
  EXPECT_EQ(files.summary["scenario"], "msr_terminal");
  EXPECT_EQ(files.geometry["chaser"]["thrusters"].size(), 16U);
  const CommandResult r = run_chaser("view " + dir.string() + " --out " + (dir / "page.html").string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const std::string page = slurp(dir / "page.html");
  EXPECT_NE(page.find("chaser-data"), std::string::npos);
  EXPECT_NE(page.find("Copyright © 2010-2024 three.js authors"), std::string::npos) << "three.js's licence notice";
  EXPECT_EQ(page.find("src=\"http"), std::string::npos) << "nothing fetched from the network";
  fs::remove_all(dir);
}

// The .npy and the .csv of the same run read to the same numbers.
TEST(ViewFiles, NpyAndCsvReadTheSame) {
  const fs::path csv = fresh_run("view_csv"), npy = fresh_run("view_npy", "npy");
  const auto a = chaser::view::read_run_files(csv), b = chaser::view::read_run_files(npy);
  EXPECT_EQ(a.telemetry.channels, b.telemetry.channels);
  ASSERT_EQ(a.telemetry.values.size(), b.telemetry.values.size());
  for (std::size_t i = 0; i < a.telemetry.values.size(); ++i) {
    const double x = a.telemetry.values[i], y = b.telemetry.values[i];
    ASSERT_TRUE(x == y || (std::isnan(x) && std::isnan(y))) << "value " << i << ": " << x << " vs " << y;
  }
  fs::remove_all(csv);
  fs::remove_all(npy);
}

TEST(ViewFiles, MissingFilesAreNamed) {
  const fs::path dir = fresh_run("view_missing");
  fs::remove(dir / "summary.json");
  expect_refused(dir, "summary.json", "missing");
  fs::remove(dir / "telemetry.csv");
  expect_refused(dir, "telemetry.csv", "missing");
  fs::remove_all(dir);
  const fs::path dir2 = fresh_run("view_missing_geometry");
  fs::remove(dir2 / "geometry.json");
  expect_refused(dir2, "geometry.json", "missing");
  fs::remove_all(dir2);
  const CommandResult r = run_chaser("view no/such/run");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("no/such/run"), std::string::npos) << r.output;
}

TEST(ViewFiles, TruncatedTelemetryIsRefused) {
  const fs::path dir = fresh_run("view_truncated");
  const std::string csv = slurp(dir / "telemetry.csv");
  write(dir / "telemetry.csv", csv.substr(0, csv.size() - 40));  // cut inside the last row
  expect_refused(dir, "telemetry.csv", "truncated");
  write(dir / "telemetry.csv", csv.substr(0, csv.find('\n') + 1));  // the header alone
  expect_refused(dir, "telemetry.csv", "no rows");
  write(dir / "telemetry.csv", "");
  expect_refused(dir, "telemetry.csv", "no header");
  // A row cut and the file then ended by a newline: the row's fields are counted.
  const std::size_t last = csv.rfind('\n', csv.size() - 2);
  write(dir / "telemetry.csv", csv.substr(0, last + 30) + "\n");
  expect_refused(dir, "telemetry.csv", "fields");
  fs::remove_all(dir);

  const fs::path npy = fresh_run("view_truncated_npy", "npy");
  const std::string bytes = slurp(npy / "telemetry.npy");
  write(npy / "telemetry.npy", bytes.substr(0, bytes.size() - 100));
  expect_refused(npy, "telemetry.npy", "truncated");
  write(npy / "telemetry.npy", bytes.substr(0, 60));
  expect_refused(npy, "telemetry.npy", "truncated");
  fs::remove_all(npy);
}

TEST(ViewFiles, DamagedSummaryIsRefused) {
  const fs::path dir = fresh_run("view_damaged_summary");
  const std::string summary = slurp(dir / "summary.json");
  write(dir / "summary.json", summary.substr(0, summary.size() / 2));
  expect_refused(dir, "summary.json", "not a JSON object");
  fs::remove_all(dir);
}

}  // namespace
