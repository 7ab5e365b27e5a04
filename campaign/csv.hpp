#pragma once
// Reading back the campaign's own CSV files: split a line, parse the numbers it wrote.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace chaser::campaign {

// The fields of one line. A field in double quotes (optimize.csv's candidate names hold commas;
// the campaign's files quote nothing) is given without them and holds no quote itself; a missing
// closing quote or text after it throws std::runtime_error.
std::vector<std::string_view> split_fields(std::string_view line);

// A number as append_number writes it ({:.17g} or "nan"), the whole field; nullopt otherwise.
std::optional<double> parse_number(std::string_view field);
std::optional<std::int64_t> parse_integer(std::string_view field);

// Column index of `name` in a header's fields, -1 if absent.
int column_index(const std::vector<std::string_view>& header, std::string_view name);

// A campaign's CSV file read whole (runs.csv for the presets' tables): the header's fields and each
// row's, every row with as many as the header.
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  // The index of each named column, in order; nullopt with `error` set ("PATH: no column NAME
  // WHY") at the first that is missing.
  std::optional<std::vector<int>> columns(const std::vector<std::string>& names, const std::string& path,
                                          std::string_view why_missing, std::string& error) const;
};
// nullopt with `error` set when the file cannot be read ("PATH: cannot be read") or a row's field
// count differs from the header's ("PATH: row N has F fields, the header H").
std::optional<CsvTable> read_csv_table(const std::string& path, std::string& error);

}  // namespace chaser::campaign
