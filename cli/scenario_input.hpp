#pragma once
// Loading a scenario for a subcommand: every problem printed at once, or the loaded scenario.
#include <optional>
#include <string>
#include <vector>

#include "io/scenario_loader.hpp"

namespace chaser::cli {

std::optional<io::LoadResult> load_or_report(const std::string& path, const std::vector<std::string>& overrides);

}  // namespace chaser::cli
