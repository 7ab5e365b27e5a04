#pragma once
// Loading a shipped scenario with overrides, for the tests that fly it or check that a key is
// refused by name (docs/style.md, "Bad input": the key's path and its allowed range).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/scenario_loader.hpp"
#include "model/scenario.hpp"

namespace chaser::testing {

// The scenario at `path` with `overrides` (--set's form); a test failure where it does not load.
inline model::Scenario load_with(const std::string& path, const std::vector<std::string>& overrides) {
  const io::LoadResult loaded = io::load_scenario_file(path, overrides);
  EXPECT_TRUE(loaded.scenario) << io::format_errors(loaded.errors);
  return loaded.scenario ? *loaded.scenario : model::Scenario{};
}

// `path` with `overrides` is refused, and the message names `key` and says `says`.
inline void expect_refused(const std::string& path, const std::vector<std::string>& overrides, const std::string& key,
                           const std::string& says) {
  const io::LoadResult r = io::load_scenario_file(path, overrides);
  ASSERT_FALSE(r.errors.empty()) << key;
  const std::string text = io::format_errors(r.errors);
  EXPECT_NE(text.find(key), std::string::npos) << text;
  EXPECT_NE(text.find(says), std::string::npos) << text;
}

}  // namespace chaser::testing
