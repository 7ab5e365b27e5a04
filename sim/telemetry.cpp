#include "sim/telemetry.hpp"

namespace chaser::sim {

namespace {
constexpr std::size_t kFlushBytes = 1 << 20;  // write in 1 MiB blocks
}

TelemetryWriter::TelemetryWriter(const std::string& path) : file_(std::fopen(path.c_str(), "w")) {}

TelemetryWriter::~TelemetryWriter() {
  if (!file_) return;
  flush();
  std::fclose(file_);
}

void TelemetryWriter::header(const std::vector<std::string>& channels) {
  for (std::size_t i = 0; i < channels.size(); ++i) {
    if (i > 0) buffer_.push_back(',');
    fmt::format_to(std::back_inserter(buffer_), "{}", channels[i]);
  }
  buffer_.push_back('\n');
}

void TelemetryWriter::end_row() {
  buffer_.push_back('\n');
  first_ = true;
  if (buffer_.size() > kFlushBytes) flush();
}

void TelemetryWriter::flush() {
  if (file_ && buffer_.size() > 0) std::fwrite(buffer_.data(), 1, buffer_.size(), file_);
  buffer_.clear();
}

}  // namespace chaser::sim
