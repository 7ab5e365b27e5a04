#pragma once
// The progress of a campaign's runs: runs done, rate, ETA. By default a line on stderr, shown only
// when stderr is a terminal, so logs and pipes stay clean; a caller (the Python module) may take the
// counts instead and show them its own way. Never written to a result file.
#include <chrono>
#include <cstdint>
#include <functional>
#include <string>

namespace chaser::campaign {

// What one redraw shows.
struct ProgressCounts {
  std::int64_t done = 0;      // rows written
  std::int64_t total = 0;     // rows to write
  std::int64_t diverged = 0;  // of the rows written, status diverged or error
  double elapsed_s = 0;       // [s] since the first run started
  bool final = false;         // the last call, after every run
};

// Called at most every kRedrawInterval, then once with final set; from a worker thread, with the
// campaign's schedule locked (a slow display holds up the writing of rows, never their values).
using ProgressCallback = std::function<void(const ProgressCounts&)>;

// The line the terminal shows, without the leading '\r'.
std::string progress_line(const ProgressCounts& counts);

class Progress {
 public:
  // enabled: show progress at all (callers pass stderr_is_terminal() unless told otherwise);
  // show: where to, instead of the stderr line.
  Progress(std::int64_t total, bool enabled, ProgressCallback show = {});
  void update(std::int64_t done, std::int64_t diverged);  // redraws at most every 0.25 s
  void finish(std::int64_t done, std::int64_t diverged);  // final line and newline
  double elapsed_s() const;

 private:
  void draw(std::int64_t done, std::int64_t diverged, bool final);
  std::int64_t total_;
  bool enabled_;
  ProgressCallback show_;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

bool stderr_is_terminal();

}  // namespace chaser::campaign
