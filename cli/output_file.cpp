#include "cli/output_file.hpp"

#include <fstream>
#include <iostream>

#include <fmt/format.h>

namespace chaser::cli {

bool write_output_file(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::path partial = path;
  partial += ".partial";
  bool ok = false;
  {
    std::ofstream out(partial, std::ios::binary);
    out << text;
    ok = static_cast<bool>(out.flush());
  }
  std::error_code ec;
  if (ok) std::filesystem::rename(partial, path, ec);
  if (ok && !ec) return true;
  std::filesystem::remove(partial, ec);
  std::cerr << fmt::format("chaser: cannot write {}\n", path.string());
  return false;
}

}  // namespace chaser::cli
