#pragma once
// Helpers shared by the io tests: the shipped MSR scenario and error matching.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "io/scenario_loader.hpp"

namespace chaser::io::testing {

inline constexpr const char* kMsrPath = "scenarios/msr_terminal.yaml";  // ctest runs in the repo root

inline std::string msr_text() {
  std::ifstream file(kMsrPath);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

inline LoadResult load_msr(const std::vector<std::string>& overrides = {}) {
  return load_scenario_file(kMsrPath, overrides);
}

// Success if some error has exactly this key path and a message containing `fragment`.
inline ::testing::AssertionResult has_error(const LoadResult& r, const std::string& key_path,
                                            const std::string& fragment) {
  for (const ScenarioError& e : r.errors)
    if (e.key_path == key_path && e.message.find(fragment) != std::string::npos)
      return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "no error at '" << key_path << "' containing '" << fragment
                                       << "'; errors were:\n" << format_errors(r.errors);
}

}  // namespace chaser::io::testing
