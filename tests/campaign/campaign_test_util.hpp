#pragma once
// Helpers of the campaign tests: a short campaign plan from the shipped scenario (onset 20 s,
// horizon 10 s: 300 periods a run) and whole-file reads.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "campaign/plan.hpp"
#include "io/scenario_loader.hpp"

namespace chaser::campaign::testing {

inline CampaignPlan short_plan(std::vector<CaseRuns> cases, std::vector<std::string> overrides = {}) {
  overrides.insert(overrides.begin(), {"campaign.onset_s=20", "campaign.horizon_after_onset_s=10"});
  const io::LoadResult loaded = io::load_scenario_file("scenarios/msr_terminal.yaml", overrides);
  EXPECT_TRUE(loaded.errors.empty()) << io::format_errors(loaded.errors);
  return CampaignPlan{*loaded.scenario, loaded.hash, RunLayout(std::move(cases))};
}

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("chaser_campaign_test_" + name);
  std::filesystem::remove_all(dir);
  return dir;
}

}  // namespace chaser::campaign::testing
