#pragma once
// Writing a command's output file whole: to "<path>.partial", then renamed, so that a file under
// its real name is never half-written (a killed command leaves only the .partial).
#include <filesystem>
#include <string>

namespace chaser::cli {

// Writes `text` to `path`; on failure prints "chaser: cannot write PATH" and returns false.
bool write_output_file(const std::filesystem::path& path, const std::string& text);

}  // namespace chaser::cli
