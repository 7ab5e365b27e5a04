// The telemetry writer against what it promises: every double reads back bit for bit (CSV text
// parsed by strtod, .npy bytes), the file exists under its name only once finished, and the .npy
// header is what NumPy's format specification asks.
#include "sim/telemetry.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/random.hpp"
#include "sim/npy_header.hpp"

namespace chaser::sim {
namespace {

namespace fs = std::filesystem;

std::string read_all(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Values that defeat short formats: 10 significant digits (the old writer) lose the last bits of
// 0.1 + 0.2 and of most doubles; subnormals, extremes and both zeros need care; plus 20,000
// doubles of random bits (any exponent), NaN and infinities left out (the loop never writes them).
std::vector<double> hard_values() {
  std::vector<double> v = {0.0, -0.0, 1.0, 0.1 + 0.2, 1.0 / 3.0, -2.5e-7, 123456.789012345678, 1e-320,
                           std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::min(),
                           std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
                           4294967295.0, 9007199254740993.0, std::nextafter(1.0, 2.0)};
  RandomStream rng(7, "test/telemetry_writer");
  while (v.size() < 20000) {
    const std::uint64_t bits = static_cast<std::uint64_t>(rng.uniform() * 0x1p32) << 32 |
                               static_cast<std::uint64_t>(rng.uniform() * 0x1p32);
    const double x = std::bit_cast<double>(bits);
    if (std::isfinite(x)) v.push_back(x);
  }
  return v;
}

constexpr int kChannels = 7;

std::vector<std::string> names() {
  std::vector<std::string> n;
  for (int c = 0; c < kChannels; ++c) n.push_back(fmt::format("c{}", c));
  return n;
}

void write(const fs::path& path, const std::vector<double>& values) {
  TelemetryWriter w(path, names());
  ASSERT_TRUE(w.ok());
  for (std::size_t i = 0; i < values.size(); i += kChannels) {
    const std::span<double> row = w.new_row();
    for (int c = 0; c < kChannels; ++c) row[c] = values[i + c];
  }
  ASSERT_TRUE(w.finish());
}

TEST(TelemetryWriter, CsvTextReadsBackToTheSameDoubles) {
  const fs::path path = fs::temp_directory_path() / "chaser_writer_roundtrip.csv";
  std::vector<double> values = hard_values();
  values.resize(values.size() / kChannels * kChannels);
  write(path, values);
  std::istringstream text(read_all(path));
  std::string line;
  ASSERT_TRUE(std::getline(text, line));
  EXPECT_EQ(line, "c0,c1,c2,c3,c4,c5,c6");
  std::size_t i = 0;
  while (std::getline(text, line)) {
    std::istringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) {
      ASSERT_LT(i, values.size());
      const double back = std::strtod(field.c_str(), nullptr);
      ASSERT_EQ(std::bit_cast<std::uint64_t>(back), std::bit_cast<std::uint64_t>(values[i])) << field;
      ++i;
    }
  }
  EXPECT_EQ(i, values.size());
  EXPECT_NE(read_all(path).find("\n0,-0,1,0.30000000000000004,"), std::string::npos);  // shortest, exact
  fs::remove(path);
}

TEST(TelemetryWriter, NpyHoldsTheDoublesAfterAHeaderNumpyReads) {
  const fs::path path = fs::temp_directory_path() / "chaser_writer_roundtrip.npy";
  std::vector<double> values = hard_values();
  values.resize(values.size() / kChannels * kChannels);
  write(path, values);
  const std::string bytes = read_all(path);
  ASSERT_EQ(bytes.substr(0, 8), std::string("\x93NUMPY\x01\x00", 8));
  const std::size_t header_len = static_cast<unsigned char>(bytes[8]) | static_cast<unsigned char>(bytes[9]) << 8;
  EXPECT_EQ((10 + header_len) % 64, 0u);  // the data is aligned
  const std::string dict = bytes.substr(10, header_len);
  EXPECT_EQ(dict.back(), '\n');
  EXPECT_EQ(dict.rfind(fmt::format("{{'descr': [('c0', '<f8'), ('c1', '<f8')", 0)), 0u) << dict;
  EXPECT_NE(dict.find(fmt::format("'fortran_order': False, 'shape': ({},), }}", values.size() / kChannels)),
            std::string::npos) << dict;
  ASSERT_EQ(bytes.size(), 10 + header_len + values.size() * sizeof(double));
  EXPECT_EQ(std::memcmp(bytes.data() + 10 + header_len, values.data(), values.size() * sizeof(double)), 0);
  fs::remove(path);
}

// The header keeps its length when the count is written in at the end (up to an int64 count), and
// a header too long for format 1.0's 16-bit length switches to 2.0.
TEST(NpyHeader, KeepsItsLengthAndGrowsToVersionTwo) {
  const std::vector<std::string> fields = {"t_s", "x_m"};
  const std::string first = npy_header(fields, 0);
  EXPECT_EQ(npy_header(fields, std::numeric_limits<std::int64_t>::max(), first.size()).size(), first.size());
  std::vector<std::string> many(5000, "a_long_channel_name_m");
  const std::string big = npy_header(many, 12000);
  EXPECT_EQ(big[6], '\x02');
  EXPECT_EQ(big.size() % 64, 0u);
}

// Until finish() the file is "<name>.partial"; dropped unfinished (an exception in the run), the
// partial file is removed: nothing under the real name ever looks complete when it is not.
TEST(TelemetryWriter, TheFileAppearsOnlyWhenFinished) {
  const fs::path path = fs::temp_directory_path() / "chaser_writer_partial.csv";
  fs::path partial = path;
  partial += ".partial";
  fs::remove(path);
  {
    TelemetryWriter w(path, names());
    for (int r = 0; r < 1000; ++r) std::fill_n(w.new_row().begin(), kChannels, 1.5);
    EXPECT_TRUE(fs::exists(partial));
    EXPECT_FALSE(fs::exists(path));
  }
  EXPECT_FALSE(fs::exists(partial));
  EXPECT_FALSE(fs::exists(path));
  {
    TelemetryWriter w(path, names());
    for (int r = 0; r < 1000; ++r) std::fill_n(w.new_row().begin(), kChannels, 1.5);
    ASSERT_TRUE(w.finish());
  }
  EXPECT_TRUE(fs::exists(path));
  EXPECT_FALSE(fs::exists(partial));
  fs::remove(path);
}

TEST(TelemetryWriter, RefusesAnUnknownExtensionOrAnUnwritablePlace) {
  EXPECT_FALSE(TelemetryWriter(fs::temp_directory_path() / "t.txt", names()).ok());
  EXPECT_FALSE(TelemetryWriter(fs::path("/nonexistent_dir/t.csv"), names()).ok());
  TelemetryWriter w(fs::path("/nonexistent_dir/t.csv"), names());
  EXPECT_FALSE(w.finish());
}

}  // namespace
}  // namespace chaser::sim
