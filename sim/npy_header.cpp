#include "sim/npy_header.hpp"

#include <stdexcept>

#include <fmt/format.h>

namespace chaser::sim {

namespace {
constexpr std::size_t kAlignment = 64;   // the data starts on a 64-byte boundary (format 1.0+)
constexpr std::size_t kCountRoom = 20;   // digits an int64 row count may need beyond "0"
}  // namespace

std::string npy_header(const std::vector<std::string>& fields, std::int64_t rows, std::size_t min_bytes) {
  std::string dict = "{'descr': [";
  for (std::size_t i = 0; i < fields.size(); ++i) dict += fmt::format("{}('{}', '<f8')", i ? ", " : "", fields[i]);
  dict += fmt::format("], 'fortran_order': False, 'shape': ({},), }}", rows);
  const std::size_t v1_prefix = 10, v2_prefix = 12;  // magic 6 + version 2 + length 2 or 4
  const bool v2 = v1_prefix + dict.size() + kCountRoom + kAlignment > 65535;
  const std::size_t prefix = v2 ? v2_prefix : v1_prefix;
  std::size_t total = prefix + dict.size() + 1;  // + the closing newline
  if (min_bytes == 0) total += kCountRoom;      // room for the final count when rewritten
  total = std::max(total, min_bytes);
  total = (total + kAlignment - 1) / kAlignment * kAlignment;
  if (min_bytes != 0 && total != min_bytes) throw std::logic_error("npy header outgrew its first length");
  const std::size_t header_len = total - prefix;
  std::string out("\x93NUMPY", 6);
  out += static_cast<char>(v2 ? 2 : 1);
  out += '\0';
  for (std::size_t b = 0; b < (v2 ? 4u : 2u); ++b) out += static_cast<char>((header_len >> (8 * b)) & 0xFF);
  out += dict;
  out.append(total - out.size() - 1, ' ');
  out += '\n';
  return out;
}

}  // namespace chaser::sim
