#include "campaign/progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <utility>

#include <fmt/format.h>

#include "core/wall_clock.hpp"

namespace chaser::campaign {

namespace {

constexpr std::chrono::milliseconds kRedrawInterval{250};

std::string clock_text(double seconds) {
  const auto s = static_cast<std::int64_t>(seconds + 0.5);
  return s >= 3600 ? fmt::format("{}h{:02}m", s / 3600, s / 60 % 60) : fmt::format("{}m{:02}s", s / 60, s % 60);
}

}  // namespace

bool stderr_is_terminal() { return isatty(STDERR_FILENO) == 1; }

std::string progress_line(const ProgressCounts& c) {
  const double rate = c.elapsed_s > 0 ? static_cast<double>(c.done) / c.elapsed_s : 0.0;
  const std::string eta = rate > 0 ? clock_text(static_cast<double>(c.total - c.done) / rate) : "?";
  return fmt::format("campaign: {}/{} runs, {:.1f} runs/s, ETA {}, {} diverged   ", c.done, c.total, rate, eta,
                     c.diverged);
}

Progress::Progress(std::int64_t total, bool enabled, ProgressCallback show)
    : total_(total), enabled_(enabled), show_(std::move(show)), start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

double Progress::elapsed_s() const { return seconds_since(start_); }

void Progress::draw(std::int64_t done, std::int64_t diverged, bool final) {
  const ProgressCounts counts{done, total_, diverged, elapsed_s(), final};
  if (show_) {
    show_(counts);
    return;
  }
  std::fputs(("\r" + progress_line(counts) + (final ? "\n" : "")).c_str(), stderr);
  std::fflush(stderr);
}

void Progress::update(std::int64_t done, std::int64_t diverged) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_draw_ < kRedrawInterval) return;
  last_draw_ = now;
  draw(done, diverged, false);
}

void Progress::finish(std::int64_t done, std::int64_t diverged) {
  if (enabled_) draw(done, diverged, true);
}

}  // namespace chaser::campaign
