#pragma once
// Running a command line from a test, as a user would: its exit code and everything it printed.
// Shared by the CLI suites (tests/cli).
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace chaser::testing {

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

// Runs `command` through the shell with stderr joined to stdout.
inline CommandResult run_shell(const std::string& command) {
  CommandResult result;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), buffer.size(), pipe)) result.output += buffer.data();
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

// Starts `binary args...` as a child process that becomes the program itself (so a signal sent to
// the returned pid hits it), its output sent to /dev/null. For the tests that kill a run mid-way.
inline pid_t start_process(const std::string& binary, std::vector<std::string> args) {
  const pid_t pid = fork();
  if (pid != 0) return pid;
  std::vector<char*> argv{const_cast<char*>(binary.c_str())};
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const int null = open("/dev/null", O_WRONLY);
  dup2(null, STDOUT_FILENO);
  dup2(null, STDERR_FILENO);
  execv(binary.c_str(), argv.data());
  _exit(127);
}

// A path in this test process's own temporary folder, so that suites run side by side (two build
// trees' `ctest` at once) never share one; the folder goes when the process exits.
struct ScratchRoot {
  std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("chaser_tests_" + std::to_string(::getpid()));
  ScratchRoot() { std::filesystem::create_directories(path); }
  ~ScratchRoot() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};
inline std::filesystem::path scratch_path(const std::string& name) {
  static const ScratchRoot root;
  return root.path / name;
}

// The whole file as bytes (empty if it cannot be read).
inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace chaser::testing
