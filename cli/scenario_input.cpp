#include "cli/scenario_input.hpp"

#include <iostream>

#include <fmt/format.h>

namespace chaser::cli {

std::optional<io::LoadResult> load_or_report(const std::string& path, const std::vector<std::string>& overrides) {
  io::LoadResult loaded = io::load_scenario_file(path, overrides);
  if (!loaded.errors.empty()) {
    std::cerr << fmt::format("chaser: {} has {} problem{}:\n", path, loaded.errors.size(),
                             loaded.errors.size() == 1 ? "" : "s")
              << io::format_errors(loaded.errors);
    return std::nullopt;
  }
  return loaded;
}

}  // namespace chaser::cli
