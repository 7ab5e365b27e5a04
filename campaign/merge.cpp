#include "campaign/merge.hpp"

#include <filesystem>
#include <fstream>
#include <optional>

#include <fmt/format.h>

#include "campaign/campaign_json.hpp"
#include "campaign/glr_envelope.hpp"
#include "campaign/rows_files.hpp"
#include "campaign/run_row.hpp"
#include "campaign/summary.hpp"

namespace chaser::campaign {

namespace {

namespace fs = std::filesystem;

struct ShardDir {
  std::string dir;
  nlohmann::ordered_json json;
  CampaignInfo info;
};

CampaignOutcome bad_input(std::string message) { return CampaignOutcome::bad_input(std::move(message)); }

// The column set of a shard's runs.csv, from its header; nullopt for a missing file or another header.
std::optional<RunColumnSet> column_set_of_file(const std::string& dir) {
  std::ifstream in(fs::path(dir) / "runs.csv", std::ios::binary);
  std::string header;
  if (!in || !std::getline(in, header)) return std::nullopt;
  return run_column_set_of(header);
}

// Every row of the shard is there and nothing after them; its columns are `columns`.
std::string check_complete(const ShardDir& s, RunColumnSet columns) {
  const RunLayout layout(s.info.cases);
  const RunRange expected = shard_range(s.info.shard, layout.total_runs());
  if (expected.begin != s.info.range.begin || expected.end != s.info.range.end)
    return fmt::format("merge: {}: campaign.json shard_runs does not match shard {}/{}", s.dir, s.info.shard.index,
                       s.info.shard.count);
  const RowsScan scan = scan_rows(s.dir, expected, layout, s.info.seed, columns);
  if (!scan.error.empty()) return fmt::format("merge: {}", scan.error);
  std::error_code ec1, ec2;
  const auto runs_size = fs::file_size(fs::path(s.dir) / "runs.csv", ec1);
  const auto glr_size = fs::file_size(fs::path(s.dir) / "glr_runs.csv", ec2);
  if (scan.runs_done != expected.size() || ec1 || ec2 || runs_size != scan.runs_bytes || glr_size != scan.glr_bytes)
    return fmt::format("merge: shard {}/{} in {} is incomplete ({} of {} runs valid); finish it with --resume",
                       s.info.shard.index, s.info.shard.count, s.dir, scan.runs_done, expected.size());
  return "";
}

// The shards ordered by index, each of the m exactly once, all of one campaign.
std::string order_shards(std::vector<ShardDir>& shards) {
  const nlohmann::ordered_json& ref = shards.front().json;
  for (const ShardDir& s : shards) {
    const std::string differ = differing_keys(ref, s.json, {"shard", "shard_runs"});
    if (!differ.empty())
      return fmt::format("merge: {} and {} are not shards of the same campaign (differ in: {})", shards.front().dir,
                         s.dir, differ);
  }
  const int m = shards.front().info.shard.count;
  std::vector<std::optional<ShardDir>> slots(static_cast<std::size_t>(m));
  for (ShardDir& s : shards) {
    auto& slot = slots[static_cast<std::size_t>(s.info.shard.index)];
    if (slot)
      return fmt::format("merge: {} and {} are both shard {}/{} (overlapping shards)", slot->dir, s.dir,
                         s.info.shard.index, m);
    slot = std::move(s);
  }
  shards.clear();
  for (int i = 0; i < m; ++i) {
    if (!slots[static_cast<std::size_t>(i)]) return fmt::format("merge: shard {}/{} is missing", i, m);
    shards.push_back(std::move(*slots[static_cast<std::size_t>(i)]));
  }
  return "";
}

// Concatenates the rows (every line after the header) of one file name across the shards.
bool concatenate(const std::vector<ShardDir>& shards, const fs::path& out_dir, const char* name, std::string_view header) {
  std::ofstream out(out_dir / name, std::ios::binary);
  out << header << '\n';
  std::string line;
  for (const ShardDir& s : shards) {
    std::ifstream in(fs::path(s.dir) / name, std::ios::binary);
    std::getline(in, line);
    while (std::getline(in, line)) out << line << '\n';
  }
  return static_cast<bool>(out);
}

}  // namespace

CampaignOutcome merge_shards(const std::string& out_dir, const std::vector<std::string>& shard_dirs,
                             const std::vector<Target>& targets) {
  if (shard_dirs.empty()) return bad_input("merge: give the shard directories to merge");
  std::vector<ShardDir> shards;
  for (const std::string& dir : shard_dirs) {
    std::string error;
    const auto json = read_campaign_json(dir, error);
    const auto info = json ? campaign_info(*json, error) : std::nullopt;
    if (!info) return bad_input(fmt::format("merge: {}", error));
    shards.push_back({dir, *json, *info});
  }
  if (std::string e = order_shards(shards); !e.empty()) return bad_input(e);
  // Every shard of one campaign has one scenario, so one column set: the first shard's says which.
  const std::optional<RunColumnSet> columns = column_set_of_file(shards.front().dir);
  if (!columns)
    return bad_input(fmt::format("merge: {}/runs.csv is missing or has other columns than this chaser writes",
                                 shards.front().dir));
  for (const ShardDir& s : shards)
    if (std::string e = check_complete(s, *columns); !e.empty()) return bad_input(e);
  if (fs::exists(fs::path(out_dir) / "campaign.json") || fs::exists(fs::path(out_dir) / "runs.csv"))
    return bad_input(fmt::format("merge: --out {} already holds a campaign; choose another --out", out_dir));

  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec) return CampaignOutcome::failure(fmt::format("cannot create --out directory {}: {}", out_dir, ec.message()));
  nlohmann::ordered_json merged = shards.front().json;
  const std::int64_t total = merged.at("total_runs").get<std::int64_t>();
  merged["shard"] = {0, 1};
  merged["shard_runs"] = {0, total};
  std::ofstream(fs::path(out_dir) / "campaign.json", std::ios::binary) << campaign_json_text(merged);
  if (!concatenate(shards, out_dir, "runs.csv", runs_header(*columns)) ||
      !concatenate(shards, out_dir, "glr_runs.csv", kGlrRunsHeader))
    return CampaignOutcome::failure(fmt::format("cannot write the rows files in {}", out_dir));
  std::vector<FaultCase> cases;
  for (const CaseRuns& c : shards.front().info.cases) cases.push_back(c.fault_case);
  SummaryContext context = shards.front().info.summary;
  context.targets = targets;
  const std::string error = write_summaries(out_dir, cases, context);
  if (!error.empty()) return CampaignOutcome::failure(error);
  CampaignOutcome outcome;
  outcome.shard_runs = total;
  return outcome;
}

}  // namespace chaser::campaign
