#pragma once
// DIR/runs.csv and DIR/glr_runs.csv of one campaign or shard, written strictly in run-index order
// and flushed row by row, so that a killed campaign leaves a valid prefix plus at most one torn
// line. Resume keeps the longest valid prefix (complete lines, the expected run indices, seeds and
// cases, parseable fields) and cuts the rest: no run lost, none repeated.
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "campaign/cases.hpp"
#include "campaign/run_one.hpp"
#include "campaign/run_row.hpp"

namespace chaser::campaign {

// How much of an existing campaign directory is valid for runs [range.begin, range.end).
struct RowsScan {
  std::int64_t runs_done = 0;   // complete runs: range.begin .. range.begin + runs_done - 1
  std::uint64_t runs_bytes = 0; // length of runs.csv to keep (header included; 0: rewrite)
  std::uint64_t glr_bytes = 0;  // length of glr_runs.csv to keep
  std::string error;            // a file that is not this campaign's
};
// `columns`: the set this campaign writes (run_column_set of its scenario); a file with another header is an error.
RowsScan scan_rows(const std::string& dir, const RunRange& range, const RunLayout& layout, std::uint64_t campaign_seed,
                   RunColumnSet columns);

class RowsWriter {
 public:
  // Fresh: writes both headers. Resume: cuts the files to `scan` and appends after it.
  // Returns nullptr with `error` set when a file cannot be opened.
  static std::unique_ptr<RowsWriter> open(const std::string& dir, const RowsScan* resume_from, RunColumnSet columns,
                                          std::string& error);
  ~RowsWriter();
  RowsWriter(const RowsWriter&) = delete;
  RowsWriter& operator=(const RowsWriter&) = delete;

  // Appends one run (its glr line first, then its row) and flushes both; false on an I/O error.
  bool append(const RunOutput& out);

 private:
  RowsWriter(std::FILE* runs, std::FILE* glr) : runs_(runs), glr_(glr) {}
  std::FILE* runs_;
  std::FILE* glr_;
};

}  // namespace chaser::campaign
