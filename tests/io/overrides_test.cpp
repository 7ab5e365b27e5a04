#include "io/overrides.hpp"

#include <gtest/gtest.h>

namespace chaser::io {
namespace {

YAML::Node doc() { return YAML::Load("a: {b: 1, c: [10, 20]}\nl: [{x: 1}, {x: 2}]\n"); }

// Overrides act on the document: the value is parsed as YAML and replaces the node in place,
// leaving every other node as it was.
TEST(Overrides, ReplaceScalarListAndMapping) {
  YAML::Node root = doc();
  Diagnostics d;
  apply_override(root, "a.b=2", d);
  apply_override(root, "a.c=[1, 2, 3]", d);
  apply_override(root, "l.1.x=5", d);
  apply_override(root, "a.c.0=7", d);
  EXPECT_TRUE(d.errors().empty());
  EXPECT_EQ(root["a"]["b"].as<int>(), 2);
  EXPECT_EQ(root["a"]["c"].size(), 3u);
  EXPECT_EQ(root["a"]["c"][0].as<int>(), 7);
  EXPECT_EQ(root["l"][0]["x"].as<int>(), 1);
  EXPECT_EQ(root["l"][1]["x"].as<int>(), 5);
}

TEST(Overrides, NewLastKeyIsCreatedButNotIntermediateOnes) {
  YAML::Node root = doc();
  Diagnostics d;
  apply_override(root, "a.new=3", d);
  EXPECT_TRUE(d.errors().empty());
  EXPECT_EQ(root["a"]["new"].as<int>(), 3);
  apply_override(root, "z.new=3", d);
  ASSERT_EQ(d.errors().size(), 1u);
  EXPECT_EQ(d.errors()[0].key_path, "z.new");
  EXPECT_FALSE(root["z"].IsDefined());
}

// A failed override leaves the document untouched; a list is never turned into a mapping.
TEST(Overrides, ErrorsLeaveTheDocumentUnchanged) {
  YAML::Node root = doc();
  Diagnostics d;
  apply_override(root, "l.x=1", d);
  apply_override(root, "l.2.x=1", d);
  apply_override(root, "a.b.c=1", d);
  apply_override(root, "a.b=[", d);
  apply_override(root, "=1", d);
  apply_override(root, "novalue", d);
  EXPECT_EQ(d.errors().size(), 6u);
  EXPECT_TRUE(root["l"].IsSequence());
  EXPECT_EQ(root["l"].size(), 2u);
  EXPECT_EQ(root["a"]["b"].as<int>(), 1);
}

TEST(Overrides, ValueMayContainEqualsAndSpaces) {
  YAML::Node root = doc();
  Diagnostics d;
  apply_override(root, " a.b = x=y z", d);
  EXPECT_TRUE(d.errors().empty());
  EXPECT_EQ(root["a"]["b"].as<std::string>(), "x=y z");
}

}  // namespace
}  // namespace chaser::io
