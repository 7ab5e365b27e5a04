#pragma once
// A run's folder as `chaser view` reads it (docs/view.md): the telemetry (telemetry.csv or
// telemetry.npy, every row whole), summary.json and geometry.json. Any problem is a ViewInputError
// whose message names the file and what is wrong with it.
#include <filesystem>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "sim/telemetry.hpp"

namespace chaser::view {

class ViewInputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct RunFiles {
  std::filesystem::path telemetry_path;
  sim::TelemetryRows telemetry;
  nlohmann::json summary;
  nlohmann::json geometry;
};

// telemetry.csv (as sim/telemetry.cpp writes it: a header, then rows of as many numbers, each line
// ended by a newline) or telemetry.npy (a float64 structured array whose data fills the rows its
// header declares). A file cut short, a row with too few or too many fields, a number that does
// not read, or no row at all is an error.
sim::TelemetryRows read_telemetry_csv(const std::filesystem::path& path);
sim::TelemetryRows read_telemetry_npy(const std::filesystem::path& path);

// The folder: telemetry.npy if present, else telemetry.csv; summary.json; geometry.json.
RunFiles read_run_files(const std::filesystem::path& run_dir);

}  // namespace chaser::view
