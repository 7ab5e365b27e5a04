#include "sim/run_directory.hpp"

#include <fstream>
#include <system_error>

namespace chaser::sim {

std::string prepare_run_directory(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return "cannot create output directory " + dir.string() + ": " + ec.message();
  // A previous run's files go first: a run that is stopped leaves none of them beside its own to be
  // taken for its results (a telemetry.csv beside a new telemetry.npy, an older summary.json), and
  // the renames that finish the files then replace nothing (ext4 flushes a file renamed over
  // another before the rename returns: 16 ms for a 10 MB telemetry file). geometry.json (`chaser
// view`'s) goes with them.
  for (const char* name : {"summary.json", "geometry.json", "telemetry.csv", "telemetry.npy"})
    std::filesystem::remove(dir / name, ec);
  return {};
}

std::filesystem::path run_telemetry_path(const std::filesystem::path& dir, const std::string& format) {
  return format == "none" ? std::filesystem::path() : dir / ("telemetry." + format);
}

bool write_whole_file(const std::filesystem::path& path, const std::string& text) {
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
  return false;
}

}  // namespace chaser::sim
