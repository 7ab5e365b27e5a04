#pragma once
// The progress line on stderr: runs done, rate, ETA. Shown only when stderr is a terminal, so logs
// and pipes stay clean; never written to a result file.
#include <chrono>
#include <cstdint>

namespace chaser::campaign {

class Progress {
 public:
  // enabled: draw at all (callers pass stderr_is_terminal() unless told otherwise).
  Progress(std::int64_t total, bool enabled);
  void update(std::int64_t done, std::int64_t diverged);  // redraws at most every 0.25 s
  void finish(std::int64_t done, std::int64_t diverged);  // final line and newline
  double elapsed_s() const;

 private:
  void draw(std::int64_t done, std::int64_t diverged);
  std::int64_t total_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

bool stderr_is_terminal();

}  // namespace chaser::campaign
