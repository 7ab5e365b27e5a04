#pragma once
// Reading a scenario document from disk, shared by every loader (scenario, inverse simulation).
#include <cstddef>
#include <optional>
#include <string>

namespace chaser::io {

// The file's text up to max_bytes + 1 bytes (a longer result means the file is longer than
// max_bytes), or nothing when it does not exist, is not a regular file or cannot be read.
std::optional<std::string> read_text_file(const std::string& path, std::size_t max_bytes);

// The message every loader gives for a file read_text_file could not read.
inline constexpr const char* kUnreadableScenario =
    "cannot open the scenario file (it does not exist, is not a regular file, or is not readable)";

}  // namespace chaser::io
