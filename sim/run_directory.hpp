#pragma once
// The folder of one run, as `chaser run --out DIR` and the Python module's chaser.run(out=DIR)
// write it: DIR/telemetry.csv or DIR/telemetry.npy, DIR/geometry.json (the scenario's shapes, for
// `chaser view`: sim/run_geometry.hpp), then DIR/summary.json, last.
#include <filesystem>
#include <string>

namespace chaser::sim {

// Creates `dir` and removes an earlier run's summary.json, geometry.json and telemetry.* from it. An error
// message, or empty when the folder is ready.
std::string prepare_run_directory(const std::filesystem::path& dir);

// DIR/telemetry.<format> for format "csv" or "npy"; empty for "none".
std::filesystem::path run_telemetry_path(const std::filesystem::path& dir, const std::string& format);

// Writes `text` to "<path>.partial" and renames it to `path`, so that a file under its real name
// is never half-written. False if anything failed (the partial file is then removed).
bool write_whole_file(const std::filesystem::path& path, const std::string& text);

}  // namespace chaser::sim
