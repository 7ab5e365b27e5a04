#pragma once
// Reading a scenario document from disk, shared by every loader (scenario, inverse simulation).
#include <optional>
#include <string>

namespace chaser::io {

// The whole file, or nothing when it does not exist, is not a regular file or cannot be read.
std::optional<std::string> read_text_file(const std::string& path);

// The message every loader gives for a file read_text_file could not read.
inline constexpr const char* kUnreadableScenario =
    "cannot open the scenario file (it does not exist, is not a regular file, or is not readable)";

}  // namespace chaser::io
