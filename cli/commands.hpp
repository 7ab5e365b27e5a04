#pragma once
// Subcommands of the `chaser` command. Each returns the process exit code:
// 0 success, 1 a run or I/O failure, 2 a bad scenario or bad command-line input.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace chaser::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitBadInput = 2;

struct RunArgs {
  std::string scenario_path;
  std::string out_dir = "out";
  std::optional<std::uint64_t> seed;
  std::vector<std::string> overrides;
};

struct FdiDesignArgs {
  std::string scenario_path;
  std::string model = "position";  // "position" or "attitude"
  std::string out_path;            // empty: print only
  std::vector<std::string> overrides;
};

int run_command(const RunArgs& args);
int fdi_design_command(const FdiDesignArgs& args);
int validate_command(const std::string& scenario_path, const std::vector<std::string>& overrides);

}  // namespace chaser::cli
