#include "io/scenario_hash.hpp"

#include <gtest/gtest.h>

namespace chaser::io {
namespace {

std::string hash_of(const std::string& yaml) { return hash_text(canonical_yaml(YAML::Load(yaml))); }

// FNV-1a 64 reference values (Fowler-Noll-Vo test vectors): "" -> cbf29ce484222325,
// "a" -> af63dc4c8601ec8c.
TEST(ScenarioHash, IsFnv1a64InHex) {
  EXPECT_EQ(hash_text(""), "cbf29ce484222325");
  EXPECT_EQ(hash_text("a"), "af63dc4c8601ec8c");
}

// Layout, comments and key order are not content; values, list order and quoting are.
TEST(ScenarioHash, CanonicalTextIgnoresLayoutOnly) {
  const std::string base = hash_of("a: 1\nb: {c: [1, 2], d: x}\n");
  EXPECT_EQ(hash_of("# comment\nb:\n  d: x   # why\n  c:\n    - 1\n    - 2\na: 1\n"), base);
  EXPECT_NE(hash_of("a: 2\nb: {c: [1, 2], d: x}\n"), base);
  EXPECT_NE(hash_of("a: 1\nb: {c: [2, 1], d: x}\n"), base);
  EXPECT_NE(hash_of("a: '1'\nb: {c: [1, 2], d: x}\n"), base);
}

TEST(ScenarioHash, CanonicalTextRoundTrips) {
  const YAML::Node root = YAML::Load("z: [1, {y: 2}]\na: \"quoted\"\nn: ~\n");
  const std::string text = canonical_yaml(root);
  EXPECT_EQ(canonical_yaml(YAML::Load(text)), text);
  EXPECT_LT(text.find("a:"), text.find("z:"));
}

}  // namespace
}  // namespace chaser::io
