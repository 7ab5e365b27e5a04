#include "view/run_files.hpp"

#include <charconv>
#include <cstring>
#include <fstream>
#include <iterator>

#include <fmt/format.h>

namespace chaser::view {

namespace {

std::string read_whole(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ViewInputError(fmt::format("{}: cannot read (missing?)", path.string()));
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::string> split_header(std::string_view line) {
  std::vector<std::string> names;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    names.emplace_back(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) return names;
    start = comma + 1;
  }
}

// One CSV row into `out` (exactly out.size() numbers), or an error message.
std::string parse_row(std::string_view line, std::span<double> out) {
  const char* p = line.data();
  const char* end = line.data() + line.size();
  for (std::size_t c = 0; c < out.size(); ++c) {
    if (c > 0) {
      if (p == end || *p != ',') return fmt::format("{} fields, expected {}", c, out.size());
      ++p;
    }
    // std::from_chars does not read "nan" with a sign or "inf" in every form the writer may use:
    // the writer's NaN is "nan", which it does read.
    const auto [next, ec] = std::from_chars(p, end, out[c]);
    if (ec != std::errc() && ec != std::errc::result_out_of_range)
      return fmt::format("field {} is not a number", c + 1);
    p = next;
  }
  if (p != end) return fmt::format("more than {} fields", out.size());
  return {};
}

}  // namespace

sim::TelemetryRows read_telemetry_csv(const std::filesystem::path& path) {
  const std::string text = read_whole(path);
  const std::string name = path.string();
  const std::size_t header_end = text.find('\n');
  if (header_end == std::string::npos) throw ViewInputError(fmt::format("{}: no header line (empty or cut short)", name));
  sim::TelemetryRows rows;
  rows.channels = split_header(std::string_view(text).substr(0, header_end));
  if (rows.channels.empty() || rows.channels[0] != "t_s")
    throw ViewInputError(fmt::format("{}: the header does not start with t_s: not a Chaser telemetry file", name));
  if (text.back() != '\n')
    throw ViewInputError(fmt::format("{}: truncated (its last row has no end of line)", name));
  std::size_t line_no = 1;
  for (std::size_t start = header_end + 1; start < text.size();) {
    const std::size_t end = text.find('\n', start);
    ++line_no;
    const std::string problem = parse_row(std::string_view(text).substr(start, end - start), rows.new_row());
    if (!problem.empty()) throw ViewInputError(fmt::format("{}: line {}: {} (truncated or damaged)", name, line_no, problem));
    start = end + 1;
  }
  if (rows.rows() == 0) throw ViewInputError(fmt::format("{}: no rows (the run wrote its header only)", name));
  return rows;
}

sim::TelemetryRows read_telemetry_npy(const std::filesystem::path& path) {
  const std::string bytes = read_whole(path);
  const std::string name = path.string();
  if (bytes.size() < 10 || bytes.compare(0, 6, "\x93NUMPY") != 0)
    throw ViewInputError(fmt::format("{}: not a NumPy .npy file", name));
  const int major = static_cast<unsigned char>(bytes[6]);
  const std::size_t len_bytes = major == 1 ? 2 : 4;
  std::size_t header_len = 0;
  for (std::size_t i = 0; i < len_bytes; ++i) header_len |= static_cast<std::size_t>(static_cast<unsigned char>(bytes[8 + i])) << (8 * i);
  const std::size_t data_start = 8 + len_bytes + header_len;
  if (bytes.size() < data_start) throw ViewInputError(fmt::format("{}: truncated inside its header", name));
  const std::string header = bytes.substr(8 + len_bytes, header_len);
  sim::TelemetryRows rows;
  // The fields, as sim/npy_header.cpp writes them: ('name', '<f8'), ...
  for (std::size_t at = header.find("('"); at != std::string::npos; at = header.find("('", at + 2)) {
    const std::size_t close = header.find('\'', at + 2);
    if (close == std::string::npos) break;
    rows.channels.push_back(header.substr(at + 2, close - at - 2));
  }
  const std::size_t shape_at = header.find("'shape': (");
  if (rows.channels.empty() || rows.channels[0] != "t_s" || shape_at == std::string::npos ||
      header.find("<f8") == std::string::npos)
    throw ViewInputError(fmt::format("{}: not a Chaser telemetry file (float64 fields from t_s)", name));
  const long long declared = std::strtoll(header.c_str() + shape_at + 10, nullptr, 10);
  const std::size_t row_bytes = rows.channels.size() * sizeof(double);
  const std::size_t data_bytes = bytes.size() - data_start;
  if (declared <= 0) throw ViewInputError(fmt::format("{}: no rows", name));
  if (data_bytes != static_cast<std::size_t>(declared) * row_bytes)
    throw ViewInputError(fmt::format("{}: truncated: {} bytes of data for the {} rows its header declares ({} expected)",
                                     name, data_bytes, declared, static_cast<std::size_t>(declared) * row_bytes));
  rows.values.resize(static_cast<std::size_t>(declared) * rows.channels.size());
  std::memcpy(rows.values.data(), bytes.data() + data_start, data_bytes);  // little-endian float64, as written
  return rows;
}

namespace {

nlohmann::json read_json(const std::filesystem::path& path) {
  const std::string text = read_whole(path);
  nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw ViewInputError(fmt::format("{}: not a JSON object (truncated or damaged)", path.string()));
  return j;
}

}  // namespace

RunFiles read_run_files(const std::filesystem::path& run_dir) {
  if (!std::filesystem::is_directory(run_dir)) throw ViewInputError(fmt::format("{}: not a run folder", run_dir.string()));
  RunFiles files;
  const std::filesystem::path npy = run_dir / "telemetry.npy", csv = run_dir / "telemetry.csv";
  if (std::filesystem::exists(npy)) {
    files.telemetry_path = npy;
    files.telemetry = read_telemetry_npy(npy);
  } else if (std::filesystem::exists(csv)) {
    files.telemetry_path = csv;
    files.telemetry = read_telemetry_csv(csv);
  } else {
    throw ViewInputError(fmt::format("{}: missing (and no telemetry.npy): the run was flown with --telemetry none, "
                                     "or did not finish",
                                     csv.string()));
  }
  const std::filesystem::path summary = run_dir / "summary.json", geometry = run_dir / "geometry.json";
  if (!std::filesystem::exists(summary))
    throw ViewInputError(fmt::format("{}: missing: the run did not finish (summary.json is written last)", summary.string()));
  files.summary = read_json(summary);
  if (!std::filesystem::exists(geometry))
    throw ViewInputError(fmt::format("{}: missing: runs write it from this version of chaser on; fly the run again "
                                     "(chaser run SCENARIO --out DIR)",
                                     geometry.string()));
  files.geometry = read_json(geometry);
  return files;
}

}  // namespace chaser::view
