#include "campaign/rows_files.hpp"

#include <filesystem>
#include <fstream>
#include <vector>

#include <fmt/format.h>

#include "campaign/csv.hpp"
#include "campaign/glr_envelope.hpp"
#include "campaign/run_row.hpp"
#include "core/random.hpp"

namespace chaser::campaign {

namespace {

namespace fs = std::filesystem;

// Reads one line; false at the end or on a last line without its newline (a torn write).
bool complete_line(std::istream& in, std::string& line) {
  if (!std::getline(in, line)) return false;
  return !in.eof();
}

bool row_is_valid(const std::string& line, std::int64_t run, const RunLayout& layout, std::uint64_t seed,
                  RunColumnSet columns) {
  const std::vector<std::string_view> f = split_fields(line);
  if (f.size() != run_columns(columns).size()) return false;
  if (parse_integer(f[0]) != run || f[1] != fmt::format("{}", run_seed(seed, static_cast<std::uint64_t>(run))) ||
      f[2] != to_string(layout.case_of(run)))
    return false;
  if (f[3] != "ok" && f[3] != "diverged" && f[3] != "error") return false;
  const std::vector<RunColumn>& kinds = run_columns(columns);
  for (std::size_t i = 4; i < f.size(); ++i) {
    // A word (supervisor_fault's none, stuck_open, stuck_closed), else a number.
    const bool ok = kinds[i].kind == ColumnKind::kText
                        ? !f[i].empty() && f[i].find_first_not_of("abcdefghijklmnopqrstuvwxyz_") == std::string_view::npos
                        : parse_number(f[i]).has_value();
    if (!ok) return false;
  }
  return true;
}

// The valid runs.csv prefix: runs done and the byte offset after each row.
void scan_runs(const fs::path& path, const RunRange& range, const RunLayout& layout, std::uint64_t seed,
               RunColumnSet columns, RowsScan& scan, std::vector<std::uint64_t>& ends) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!in || !complete_line(in, line)) return;  // no complete header: start afresh
  if (line != runs_header(columns)) {
    scan.error = fmt::format("{} has other columns than this chaser writes", path.string());
    return;
  }
  std::uint64_t offset = line.size() + 1;
  scan.runs_bytes = offset;
  while (range.begin + scan.runs_done < range.end && complete_line(in, line) &&
         row_is_valid(line, range.begin + scan.runs_done, layout, seed, columns)) {
    offset += line.size() + 1;
    ends.push_back(offset);
    ++scan.runs_done;
    scan.runs_bytes = offset;
  }
}

// The valid glr_runs.csv prefix: one line per fault-free run among the runs done, in order. A
// fault-free run without its line (never expected: the line is written first) is redone.
void scan_glr(const fs::path& path, const RunRange& range, const RunLayout& layout, std::uint64_t header_bytes,
              RowsScan& scan, const std::vector<std::uint64_t>& ends) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  const bool header = in && complete_line(in, line) && line == kGlrRunsHeader;
  std::uint64_t offset = header ? line.size() + 1 : 0;
  scan.glr_bytes = offset;
  for (std::int64_t i = 0; i < scan.runs_done; ++i) {
    const std::int64_t run = range.begin + i;
    if (layout.case_of(run) != FaultCase::kNone) continue;
    const bool found = header && complete_line(in, line) && [&] {
      const auto parsed = parse_glr_line(line);
      return parsed && parsed->run == run;
    }();
    if (!found) {  // keep the runs before this one
      scan.runs_done = i;
      scan.runs_bytes = i == 0 ? header_bytes : ends[static_cast<std::size_t>(i - 1)];
      return;
    }
    offset += line.size() + 1;
    scan.glr_bytes = offset;
  }
}

}  // namespace

RowsScan scan_rows(const std::string& dir, const RunRange& range, const RunLayout& layout, std::uint64_t campaign_seed,
                   RunColumnSet columns) {
  RowsScan scan;
  std::vector<std::uint64_t> ends;
  scan_runs(fs::path(dir) / "runs.csv", range, layout, campaign_seed, columns, scan, ends);
  if (!scan.error.empty() || scan.runs_bytes == 0) return scan;
  scan_glr(fs::path(dir) / "glr_runs.csv", range, layout, runs_header(columns).size() + 1, scan, ends);
  return scan;
}

std::unique_ptr<RowsWriter> RowsWriter::open(const std::string& dir, const RowsScan* resume_from, RunColumnSet columns,
                                             std::string& error) {
  const fs::path runs_path = fs::path(dir) / "runs.csv", glr_path = fs::path(dir) / "glr_runs.csv";
  std::error_code ec;
  const bool keep_runs = resume_from && resume_from->runs_bytes > 0;
  const bool keep_glr = keep_runs && resume_from->glr_bytes > 0;
  if (keep_runs) fs::resize_file(runs_path, resume_from->runs_bytes, ec);
  if (!ec && keep_glr) fs::resize_file(glr_path, resume_from->glr_bytes, ec);
  std::FILE* runs = ec ? nullptr : std::fopen(runs_path.c_str(), keep_runs ? "ab" : "wb");
  std::FILE* glr = ec ? nullptr : std::fopen(glr_path.c_str(), keep_glr ? "ab" : "wb");
  if (!runs || !glr) {
    if (runs) std::fclose(runs);
    if (glr) std::fclose(glr);
    error = fmt::format("cannot open {} and {} for writing", runs_path.string(), glr_path.string());
    return nullptr;
  }
  if (!keep_runs) std::fputs((runs_header(columns) + "\n").c_str(), runs);
  if (!keep_glr) std::fputs((std::string(kGlrRunsHeader) + "\n").c_str(), glr);
  std::fflush(runs);
  std::fflush(glr);
  return std::unique_ptr<RowsWriter>(new RowsWriter(runs, glr));
}

RowsWriter::~RowsWriter() {
  std::fclose(runs_);
  std::fclose(glr_);
}

bool RowsWriter::append(const RunOutput& out) {
  bool ok = true;
  if (!out.glr_line.empty()) {
    ok &= std::fputs(out.glr_line.c_str(), glr_) >= 0 && std::fputc('\n', glr_) != EOF;
    ok &= std::fflush(glr_) == 0;
  }
  ok &= std::fputs(out.row.c_str(), runs_) >= 0 && std::fputc('\n', runs_) != EOF;
  ok &= std::fflush(runs_) == 0;
  return ok;
}

}  // namespace chaser::campaign
