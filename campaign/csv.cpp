#include "campaign/csv.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace chaser::campaign {

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  for (;;) {
    std::size_t end = 0;  // where the field's separator (or the line's end) is
    if (start < line.size() && line[start] == '"') {
      const std::size_t close = line.find('"', start + 1);
      if (close == std::string_view::npos) throw std::runtime_error("a CSV field with no closing quote: " + std::string(line));
      fields.push_back(line.substr(start + 1, close - start - 1));
      end = close + 1;
      if (end < line.size() && line[end] != ',')
        throw std::runtime_error("a CSV field with text after its closing quote: " + std::string(line));
    } else {
      end = std::min(line.find(',', start), line.size());
      fields.push_back(line.substr(start, end - start));
    }
    if (end >= line.size()) return fields;
    start = end + 1;
  }
}

std::optional<double> parse_number(std::string_view field) {
  if (field == "nan") return std::numeric_limits<double>::quiet_NaN();
  if (field.empty()) return std::nullopt;
  double value = 0;
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (ec != std::errc() || end != field.data() + field.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<std::int64_t> parse_integer(std::string_view field) {
  std::int64_t value = 0;
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (field.empty() || ec != std::errc() || end != field.data() + field.size()) return std::nullopt;
  return value;
}

int column_index(const std::vector<std::string_view>& header, std::string_view name) {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return static_cast<int>(i);
  return -1;
}

std::optional<std::vector<int>> CsvTable::columns(const std::vector<std::string>& names, const std::string& path,
                                                  std::string_view why_missing, std::string& error) const {
  std::vector<int> out;
  for (const std::string& name : names) {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) {
      error = fmt::format("{}: no column {} {}", path, name, why_missing);
      return std::nullopt;
    }
    out.push_back(static_cast<int>(it - header.begin()));
  }
  return out;
}

std::optional<CsvTable> read_csv_table(const std::string& path, std::string& error) {
  std::ifstream in(path);
  std::string line;
  if (!in || !std::getline(in, line)) {
    error = fmt::format("{}: cannot be read", path);
    return std::nullopt;
  }
  CsvTable t;
  for (const std::string_view f : split_fields(line)) t.header.emplace_back(f);
  while (std::getline(in, line)) {
    const std::vector<std::string_view> f = split_fields(line);
    if (f.size() != t.header.size()) {
      error = fmt::format("{}: row {} has {} fields, the header {}", path, t.rows.size() + 1, f.size(), t.header.size());
      return std::nullopt;
    }
    t.rows.emplace_back(f.begin(), f.end());
  }
  return t;
}

}  // namespace chaser::campaign
