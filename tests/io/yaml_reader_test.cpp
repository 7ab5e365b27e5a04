#include "io/yaml_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace chaser::io {
namespace {

// Range descriptions are what users read in error messages: exact text.
TEST(Range, DescribesItselfInMathNotation) {
  EXPECT_EQ(Range::positive().describe(), "> 0");
  EXPECT_EQ(Range::non_negative().describe(), ">= 0");
  EXPECT_EQ(Range::open(0, 90).describe(), "in (0, 90)");
  EXPECT_EQ(Range::left_open(0, 1).describe(), "in (0, 1]");
  EXPECT_EQ(Range::right_open(0, 0.1).describe(), "in [0, 0.1)");
  EXPECT_EQ(Range::closed(-1.5, 2).describe(), "in [-1.5, 2]");
  EXPECT_EQ(Range::any().describe(), "");
}

TEST(Range, OpenAndClosedEnds) {
  EXPECT_FALSE(Range::open(0, 90).contains(0));
  EXPECT_FALSE(Range::open(0, 90).contains(90));
  EXPECT_TRUE(Range::open(0, 90).contains(45));
  EXPECT_TRUE(Range::left_open(0, 1).contains(1));
  EXPECT_FALSE(Range::left_open(0, 1).contains(0));
  EXPECT_TRUE(Range::non_negative().contains(0));
}

// A problem at a path makes that path, its children and its parents unclean, not its siblings.
TEST(Diagnostics, CleanIsPathAware) {
  Diagnostics d;
  d.add("chaser.inertia_kgm2.1", "bad row");
  EXPECT_FALSE(d.clean("chaser.inertia_kgm2"));
  EXPECT_FALSE(d.clean("chaser.inertia_kgm2.1.2"));
  EXPECT_FALSE(d.clean("chaser"));
  EXPECT_TRUE(d.clean("chaser.inertia"));  // a prefix of the name, not a parent
  EXPECT_TRUE(d.clean("chaser.mass_kg"));
}

double read_or_nan(const std::string& yaml) {
  Diagnostics d;
  double out = std::numeric_limits<double>::quiet_NaN();
  read_number(YAML::Load(yaml), "x", Range::any(), d, out);
  return out;
}

// Numbers are plain decimal scalars: YAML's quoted strings, special floats, hex and units are
// rejected rather than guessed.
TEST(ReadNumber, AcceptsDecimalsOnly) {
  EXPECT_EQ(read_or_nan("2500"), 2500.0);
  EXPECT_EQ(read_or_nan("-1.5e-3"), -1.5e-3);
  EXPECT_EQ(read_or_nan("+5"), 5.0);
  EXPECT_EQ(read_or_nan("3389.5e3"), 3389.5e3);
  for (const char* bad : {"'5'", "\"5\"", ".inf", "-.inf", ".nan", "0x10", "5 kg", "1e999", "~", "[1]", "{a: 1}"})
    EXPECT_TRUE(std::isnan(read_or_nan(bad))) << bad;
}

TEST(MapReader, TypedReadsAndMessages) {
  Diagnostics d;
  MapReader r(YAML::Load("n: 1\nb: True\nc: 18446744073709551615\nbig: 18446744073709551616\n"
                         "t: hello\nq: [0.8, 0, 0.6, 0]\nd: [0, 3, 4]\nm: [[1,2,3],[4,5,6],[7,8,9]]\n"
                         "deg: 90\n"),
              "s", d);
  double n = 0, rad = 0;
  bool b = false;
  std::uint64_t c = 0, big = 0;
  std::string t;
  Quat q;
  Vec3 dir;
  Mat3 m;
  EXPECT_TRUE(r.number("n", Range::positive(), n));
  EXPECT_TRUE(r.boolean("b", b));
  EXPECT_TRUE(r.count("c", c));
  EXPECT_FALSE(r.count("big", big));
  EXPECT_TRUE(r.text("t", t));
  EXPECT_TRUE(r.quaternion("q", q));
  EXPECT_TRUE(r.direction("d", dir));
  EXPECT_TRUE(r.mat3("m", m));
  EXPECT_TRUE(r.angle_deg("deg", Range::closed(0, 180), rad));
  EXPECT_FALSE(r.number("absent", Range::positive(), n));
  r.finish();
  EXPECT_EQ(n, 1.0);
  EXPECT_TRUE(b);
  EXPECT_EQ(c, 18446744073709551615ull);
  EXPECT_EQ(t, "hello");
  EXPECT_EQ(q.w(), 0.8);  // [w, x, y, z] order, not Eigen's storage order [x, y, z, w]
  EXPECT_EQ(q.y(), 0.6);
  EXPECT_EQ(dir, Vec3(0, 0.6, 0.8));  // normalised: exact in binary for a 3-4-5 triangle
  EXPECT_EQ(m(1, 0), 4.0);            // rows are rows
  EXPECT_NEAR(rad, M_PI / 2, 1e-15);
  ASSERT_EQ(d.errors().size(), 2u);
  EXPECT_EQ(d.errors()[0].key_path, "s.big");
  EXPECT_EQ(d.errors()[1].key_path, "s.absent");
  EXPECT_EQ(d.errors()[1].message, "missing key (expected a number > 0)");
}

// A section of the wrong type is one error, not one per key it should have held.
TEST(MapReader, WrongTypeSectionGivesOneError) {
  Diagnostics d;
  MapReader r(YAML::Load("[1, 2]"), "orbit", d);
  double x = 0;
  EXPECT_FALSE(r.number("altitude_m", Range::positive(), x));
  r.finish();
  ASSERT_EQ(d.errors().size(), 1u);
  EXPECT_EQ(d.errors()[0].message, "must be a mapping of keys (got a list of 2)");
}

TEST(MapReader, UnknownDuplicateAndNonScalarKeys) {
  Diagnostics d;
  MapReader r(YAML::Load("mass_kg: 1\nmas_kg: 2\nmass_kg: 3\n[1, 2]: 4\n"), "chaser", d);
  double x = 0;
  r.number("mass_kg", Range::positive(), x);
  r.finish();
  ASSERT_EQ(d.errors().size(), 3u);
  EXPECT_EQ(d.errors()[0].key_path, "chaser.mas_kg");
  EXPECT_EQ(d.errors()[0].message, "unknown key (allowed here: mass_kg); did you mean 'mass_kg'?");
  EXPECT_EQ(d.errors()[1].key_path, "chaser.mass_kg");
  EXPECT_EQ(d.errors()[1].message, "duplicate key (first at line 1)");
  EXPECT_EQ(d.errors()[2].key_path, "chaser");
  EXPECT_NE(d.errors()[2].message.find("keys must be plain names"), std::string::npos);
}

}  // namespace
}  // namespace chaser::io
