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

}  // namespace chaser::campaign
