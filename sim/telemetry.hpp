#pragma once
// Telemetry recorder: one row of doubles per control period, written to a file on a background
// thread while the run goes on, so a run with telemetry costs the loop little more than one
// without (docs/performance.md). Two formats, chosen by the file's extension:
//  - ".csv": a header of channel names, then one line per row; every number in the shortest text
//    that reads back to the same double (as std::to_chars writes it, by core/shortest_double),
//    so the file round-trips exactly;
//  - ".npy": a NumPy structured array, one float64 field per channel (sim/npy_header.hpp): the
//    bytes of the doubles, read without a parser by np.load (MATLAB, Julia: readNPY, NPZ.jl).
// Nothing lost, nothing half-written: the file is "<path>.partial" until finish() has written and
// closed it and renamed it to <path>. A run killed before that leaves only the .partial file.
//
// Rows are handed over in blocks; at most a few blocks are in flight (the loop waits if the disk is
// slower), so memory stays flat whatever the run's length. The bytes do not depend on the timing.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <mutex>
#include <span>
#include <string>
#include <thread>
#include <vector>

namespace chaser::sim {

enum class TelemetryFormat { kCsv, kNpy };

// Telemetry kept in memory (the Python module's RunResult.telemetry): the same rows as the file's,
// row-major, channels() values per row. It grows by one row per period; nothing is written.
struct TelemetryRows {
  std::vector<std::string> channels;
  std::vector<double> values;  // row r, channel c at values[r * channels.size() + c]

  std::size_t rows() const { return channels.empty() ? 0 : values.size() / channels.size(); }
  std::span<double> new_row() {
    values.resize(values.size() + channels.size());
    return {values.data() + values.size() - channels.size(), channels.size()};
  }
};

// The format a path asks for by its extension (".csv" or ".npy"); false for any other.
bool telemetry_format_of(const std::filesystem::path& path, TelemetryFormat& format);

class TelemetryWriter {
 public:
  // Opens "<path>.partial" and starts the writer thread; ok() tells whether it worked.
  TelemetryWriter(std::filesystem::path path, std::vector<std::string> channels);
  ~TelemetryWriter();  // without finish(): stops the thread, removes the partial file
  TelemetryWriter(const TelemetryWriter&) = delete;
  TelemetryWriter& operator=(const TelemetryWriter&) = delete;

  bool ok() const { return file_ != nullptr && !failed_; }
  std::size_t channels() const { return channels_.size(); }

  // Storage for the next row: the caller fills all channels() values before the next call.
  std::span<double> new_row();
  // Writes what is left, closes the file and renames it into place. False if anything failed.
  bool finish();

 private:
  void hand_over_block();  // queues the current block for the writer thread
  void writer_loop();
  void write_block(const std::vector<double>& block);
  void write_bytes(const char* data, std::size_t size);
  void stop_thread();

  std::filesystem::path path_, partial_path_;
  std::vector<std::string> channels_;
  TelemetryFormat format_ = TelemetryFormat::kCsv;
  std::FILE* file_ = nullptr;
  std::size_t npy_header_bytes_ = 0;
  std::int64_t rows_ = 0;
  bool finished_ = false;

  std::vector<double> block_;  // rows being filled by the run, row-major
  std::size_t block_rows_ = 0;
  std::vector<char> text_;     // the writer thread's CSV text buffer
  std::size_t text_used_ = 0;  // its bytes not yet written

  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::vector<double>> full_;   // blocks waiting for the writer thread, in order
  std::vector<std::vector<double>> free_;  // blocks to reuse
  bool closing_ = false;
  std::atomic<bool> failed_ = false;  // an I/O error, on either thread
  std::thread thread_;
};

}  // namespace chaser::sim
