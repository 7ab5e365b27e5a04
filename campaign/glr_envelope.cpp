#include "campaign/glr_envelope.hpp"

#include <algorithm>
#include <charconv>
#include <fstream>

#include <fmt/format.h>

#include "campaign/csv.hpp"
#include "campaign/run_row.hpp"

namespace chaser::campaign {

std::string format_glr_line(std::int64_t run, const std::vector<std::array<float, 2>>& glr_max_per_s) {
  std::string out = fmt::format("{}", run);
  for (const auto& s : glr_max_per_s) fmt::format_to(std::back_inserter(out), ",{:.9g},{:.9g}", s[0], s[1]);
  return out;
}

std::optional<GlrLine> parse_glr_line(std::string_view line) {
  const std::vector<std::string_view> fields = split_fields(line);
  if (fields.size() % 2 != 1) return std::nullopt;
  const auto run = parse_integer(fields[0]);
  if (!run) return std::nullopt;
  GlrLine out{*run, std::vector<std::array<float, 2>>((fields.size() - 1) / 2)};
  for (std::size_t i = 1; i < fields.size(); ++i) {
    float value = 0;
    const std::string_view f = fields[i];
    const auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), value);
    if (f.empty() || ec != std::errc() || end != f.data() + f.size()) return std::nullopt;
    out.per_second[(i - 1) / 2][(i - 1) % 2] = value;
  }
  return out;
}

void GlrEnvelope::add(const std::vector<std::array<float, 2>>& per_second) {
  if (per_second.size() > max_.size()) max_.resize(per_second.size(), {0.0f, 0.0f});
  for (std::size_t t = 0; t < per_second.size(); ++t)
    for (int k = 0; k < 2; ++k) max_[t][k] = std::max(max_[t][k], per_second[t][k]);
  ++runs_;
}

std::array<double, 2> GlrEnvelope::overall_max() const {
  std::array<double, 2> best{0.0, 0.0};
  for (const auto& s : max_)
    for (int k = 0; k < 2; ++k) best[k] = std::max(best[k], static_cast<double>(s[k]));
  return best;
}

std::optional<GlrEnvelope> read_glr_envelope(const std::string& glr_runs_path) {
  std::ifstream in(glr_runs_path);
  if (!in) return std::nullopt;
  std::string line;
  std::getline(in, line);  // header
  GlrEnvelope envelope;
  while (std::getline(in, line)) {
    const auto parsed = parse_glr_line(line);
    if (!parsed) return std::nullopt;
    envelope.add(parsed->per_second);
  }
  return envelope;
}

bool write_glr_envelope(const GlrEnvelope& envelope, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  out << "t_s,position_max,attitude_max\n";
  std::string row;
  for (std::size_t t = 0; t < envelope.per_second().size(); ++t) {
    row = fmt::format("{}", t);
    for (int k = 0; k < 2; ++k) {
      row += ',';
      append_number(row, static_cast<double>(envelope.per_second()[t][k]));
    }
    out << row << '\n';
  }
  return static_cast<bool>(out);
}

}  // namespace chaser::campaign
