#include "sim/telemetry.hpp"

#include <bit>
#include <cstring>
#include <system_error>

#include "core/shortest_double.hpp"
#include "sim/npy_header.hpp"

namespace chaser::sim {

namespace {

static_assert(std::endian::native == std::endian::little, "the .npy records are the doubles' bytes, '<f8'");

constexpr std::size_t kRowsPerBlock = 256;    // ~0.2 MB for MSR's 100 channels
constexpr std::size_t kBlocksInFlight = 4;    // the run waits beyond this: flat memory
constexpr std::size_t kTextFlushBytes = 1 << 20;
constexpr std::size_t kNumberRoom = kShortestDoubleRoom;  // what write_shortest_double may touch

}  // namespace

bool telemetry_format_of(const std::filesystem::path& path, TelemetryFormat& format) {
  const std::string ext = path.extension().string();
  if (ext == ".csv") format = TelemetryFormat::kCsv;
  else if (ext == ".npy") format = TelemetryFormat::kNpy;
  else return false;
  return true;
}

TelemetryWriter::TelemetryWriter(std::filesystem::path path, std::vector<std::string> channels)
    : path_(std::move(path)), channels_(std::move(channels)) {
  partial_path_ = path_;
  partial_path_ += ".partial";
  if (!telemetry_format_of(path_, format_) || channels_.empty()) return;
  file_ = std::fopen(partial_path_.c_str(), "wb");
  if (!file_) return;
  if (format_ == TelemetryFormat::kNpy) {
    const std::string header = npy_header(channels_, 0);
    npy_header_bytes_ = header.size();
    write_bytes(header.data(), header.size());
  } else {
    std::string header;
    for (std::size_t i = 0; i < channels_.size(); ++i) header += (i ? "," : "") + channels_[i];
    header += '\n';
    write_bytes(header.data(), header.size());
  }
  block_.resize(kRowsPerBlock * channels_.size());
  thread_ = std::thread(&TelemetryWriter::writer_loop, this);
}

TelemetryWriter::~TelemetryWriter() {
  if (finished_) return;
  stop_thread();
  if (file_) {
    std::fclose(file_);
    std::error_code ec;
    std::filesystem::remove(partial_path_, ec);
  }
}

std::span<double> TelemetryWriter::new_row() {
  if (block_rows_ == kRowsPerBlock) hand_over_block();
  ++rows_;
  return {block_.data() + block_rows_++ * channels_.size(), channels_.size()};
}

void TelemetryWriter::hand_over_block() {
  std::vector<double> next;
  {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return full_.size() < kBlocksInFlight; });
    block_.resize(block_rows_ * channels_.size());
    full_.push_back(std::move(block_));
    if (!free_.empty()) {
      next = std::move(free_.back());
      free_.pop_back();
    }
  }
  changed_.notify_all();
  next.resize(kRowsPerBlock * channels_.size());
  block_ = std::move(next);
  block_rows_ = 0;
}

void TelemetryWriter::writer_loop() {
  for (;;) {
    std::vector<double> block;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [&] { return !full_.empty() || closing_; });
      if (full_.empty()) return;
      block = std::move(full_.front());
      full_.pop_front();
    }
    changed_.notify_all();
    write_block(block);
    std::lock_guard lock(mutex_);
    free_.push_back(std::move(block));
  }
}

void TelemetryWriter::write_block(const std::vector<double>& block) {
  if (format_ == TelemetryFormat::kNpy) {  // little-endian hosts: the doubles' bytes are the records
    write_bytes(reinterpret_cast<const char*>(block.data()), block.size() * sizeof(double));
    return;
  }
  const std::size_t n = channels_.size();
  // Room for a whole flush and one more row at the widest, allocated once and never cleared: a
  // row's text is written over whatever the last flush left.
  if (text_.empty()) text_.resize(kTextFlushBytes + n * (kNumberRoom + 1));
  for (std::size_t r = 0; r * n < block.size(); ++r) {
    char* p = text_.data() + text_used_;
    for (std::size_t c = 0; c < n; ++c) {
      p = write_shortest_double(p, block[r * n + c]);
      *p++ = c + 1 < n ? ',' : '\n';
    }
    text_used_ = static_cast<std::size_t>(p - text_.data());
    if (text_used_ > kTextFlushBytes) {
      write_bytes(text_.data(), text_used_);
      text_used_ = 0;
    }
  }
}

void TelemetryWriter::write_bytes(const char* data, std::size_t size) {
  if (size > 0 && std::fwrite(data, 1, size, file_) != size) failed_ = true;
}

void TelemetryWriter::stop_thread() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard lock(mutex_);
    closing_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

bool TelemetryWriter::finish() {
  if (finished_ || !file_) return false;
  if (block_rows_ > 0) hand_over_block();
  stop_thread();  // the thread drains every queued block before it returns
  finished_ = true;
  write_bytes(text_.data(), text_used_);
  if (format_ == TelemetryFormat::kNpy) {  // the real row count, in the header's first length
    const std::string header = npy_header(channels_, rows_, npy_header_bytes_);
    if (std::fseek(file_, 0, SEEK_SET) != 0) failed_ = true;
    write_bytes(header.data(), header.size());
  }
  if (std::fclose(file_) != 0) failed_ = true;
  file_ = nullptr;
  std::error_code ec;
  if (!failed_) std::filesystem::rename(partial_path_, path_, ec);
  if (failed_ || ec) {
    std::filesystem::remove(partial_path_, ec);
    return false;
  }
  return true;
}

}  // namespace chaser::sim
