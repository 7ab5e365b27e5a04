#pragma once
// Telemetry recorder: one CSV row per control period, channels named as in the code with their SI
// unit as a suffix. Rows are formatted into a buffer and written in large blocks, so recording costs
// little; a run without a recorder pays nothing.
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

namespace chaser::sim {

class TelemetryWriter {
 public:
  // Opens `path` for writing; ok() tells whether it worked.
  explicit TelemetryWriter(const std::string& path);
  ~TelemetryWriter();
  TelemetryWriter(const TelemetryWriter&) = delete;
  TelemetryWriter& operator=(const TelemetryWriter&) = delete;

  bool ok() const { return file_ != nullptr; }
  void header(const std::vector<std::string>& channels);
  // A row is a sequence of add() calls followed by end_row(); values are printed with 10
  // significant digits, enough for mm on 1e4 m and for nanosecond-resolved times.
  void add(double value) {
    if (!first_) buffer_.push_back(',');
    // Most channels of a period are exact zeros (idle thrusters' on-times, flags, FDI outputs):
    // written as fmt writes +0.0 with {:.10g}, "0", without the float formatter (tested).
    if (value == 0.0 && !std::signbit(value)) {
      buffer_.push_back('0');
    } else {
      fmt::format_to(std::back_inserter(buffer_), "{:.10g}", value);
    }
    first_ = false;
  }
  void end_row();
  void flush();

 private:
  std::FILE* file_ = nullptr;
  fmt::memory_buffer buffer_;
  bool first_ = true;
};

}  // namespace chaser::sim
