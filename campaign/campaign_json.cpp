#include "campaign/campaign_json.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "sim/summary.hpp"

namespace chaser::campaign {

nlohmann::ordered_json campaign_json(const CampaignPlan& plan, const Shard& shard) {
  const model::CampaignParams& c = plan.nominal.campaign;
  nlohmann::ordered_json cases = nlohmann::ordered_json::object();
  for (const CaseRuns& cr : plan.layout.cases()) cases[std::string(to_string(cr.fault_case))] = cr.runs;
  const RunRange range = shard_range(shard, plan.layout.total_runs());
  nlohmann::ordered_json j;
  j["chaser_version"] = sim::kChaserVersion;
  j["scenario"] = plan.nominal.name;
  j["scenario_hash"] = plan.scenario_hash;
  j["campaign_seed"] = c.seed;
  j["cases"] = cases;
  j["total_runs"] = plan.layout.total_runs();
  j["shard"] = {shard.index, shard.count};
  j["shard_runs"] = {range.begin, range.end};
  j["onset_s"] = c.onset_s;
  j["horizon_after_onset_s"] = c.horizon_after_onset_s;
  if (c.onset_max_s) j["onset_max_s"] = *c.onset_max_s;  // onsets drawn in [onset_s, onset_max_s]
  j["run_duration_s"] = run_duration_s(plan.nominal);
  j["threshold_margin"] = c.threshold_margin;
  j["glr_threshold"] = plan.nominal.fdi.glr_threshold;
  j["fdi_recovery"] = plan.nominal.fdi.recovery != model::RecoveryPolicy::kNone;
  return j;
}

std::string campaign_json_text(const nlohmann::ordered_json& j) { return j.dump(2) + "\n"; }

std::optional<nlohmann::ordered_json> read_campaign_json(const std::string& dir, std::string& error) {
  const std::filesystem::path path = std::filesystem::path(dir) / "campaign.json";
  std::ifstream in(path);
  if (!in) {
    error = fmt::format("{} does not exist (not a campaign directory)", path.string());
    return std::nullopt;
  }
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object()) {
    error = fmt::format("{} is not valid JSON", path.string());
    return std::nullopt;
  }
  return j;
}

std::optional<CampaignInfo> campaign_info(const nlohmann::ordered_json& j, std::string& error) {
  try {
    CampaignInfo info;
    for (const auto& [name, runs] : j.at("cases").items()) {
      const auto c = parse_case(name);
      if (!c) throw std::runtime_error("unknown case " + name);
      info.cases.push_back({*c, runs.get<std::int64_t>()});
    }
    info.seed = j.at("campaign_seed").get<std::uint64_t>();
    info.shard = Shard{j.at("shard").at(0).get<int>(), j.at("shard").at(1).get<int>()};
    info.range = RunRange{j.at("shard_runs").at(0).get<std::int64_t>(), j.at("shard_runs").at(1).get<std::int64_t>()};
    info.summary = SummaryContext{j.at("scenario").get<std::string>(), j.at("threshold_margin").get<double>(),
                                  j.at("glr_threshold").get<double>(), {}};  // no --target: merge sets its own
    return info;
  } catch (const std::exception& e) {
    error = fmt::format("campaign.json lacks a field or has a wrong one ({})", e.what());
    return std::nullopt;
  }
}

std::string differing_keys(const nlohmann::ordered_json& a, const nlohmann::ordered_json& b,
                           const std::vector<std::string>& ignored) {
  std::vector<std::string> keys;
  const auto note = [&](const std::string& key) {
    if (std::find(ignored.begin(), ignored.end(), key) == ignored.end() &&
        std::find(keys.begin(), keys.end(), key) == keys.end())
      keys.push_back(key);
  };
  for (const auto& [key, value] : a.items())
    if (!b.contains(key) || b.at(key) != value) note(key);
  for (const auto& [key, value] : b.items())
    if (!a.contains(key)) note(key);
  return fmt::format("{}", fmt::join(keys, ", "));
}

}  // namespace chaser::campaign
