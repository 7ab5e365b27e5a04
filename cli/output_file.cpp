#include "cli/output_file.hpp"

#include <iostream>

#include <fmt/format.h>

#include "sim/run_directory.hpp"

namespace chaser::cli {

bool write_output_file(const std::filesystem::path& path, const std::string& text) {
  if (sim::write_whole_file(path, text)) return true;
  std::cerr << fmt::format("chaser: cannot write {}\n", path.string());
  return false;
}

}  // namespace chaser::cli
