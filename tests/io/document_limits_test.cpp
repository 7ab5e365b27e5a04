// Limits no legitimate scenario reaches (io/document_limits.hpp, docs/scenario.md "Limits"): each is
// a clear error at a key path, found before the document is built or walked.
#include "io/document_limits.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "io/invsim_loader.hpp"
#include "scenario_test_util.hpp"

namespace chaser::io {
namespace document_limits_test {

using testing::has_error;
using testing::load_msr;
using testing::msr_text;

// "a: &a [x, x, ...]" then eight levels "b: &b [*a, *a, ...]": nine lines that stand for 9^9
// (387 million) scalars when walked, as yaml-cpp 0.7 shares an alias with its anchor.
std::string exponential_aliases() {
  std::string text = "a: &a [x, x, x, x, x, x, x, x, x]\n";
  for (char c = 'b'; c <= 'i'; ++c) {
    const char prev = static_cast<char>(c - 1);
    text += fmt::format("{0}: &{0} [*{1}, *{1}, *{1}, *{1}, *{1}, *{1}, *{1}, *{1}, *{1}]\n", c, prev);
  }
  return text;
}

// "head.seg.seg..." with `n` segments after the head.
std::string repeated_path(std::string head, const std::string& seg, int n) {
  for (int i = 0; i < n; ++i) head += "." + seg;
  return head;
}

std::string nested_lists(int depth) { return std::string(static_cast<std::size_t>(depth), '[') + std::string(static_cast<std::size_t>(depth), ']'); }

TEST(DocumentLimits, ExponentialAliasesAreRefusedBeforeAnythingWalksThem) {
  const LoadResult r = load_scenario_text(exponential_aliases());
  EXPECT_TRUE(has_error(r, "a", "anchors are not allowed: write the value out in full"));
  EXPECT_TRUE(has_error(r, "a", "(got '&a' at line 1; 9 in the text)"));
  EXPECT_TRUE(has_error(r, "b.0", "aliases are not allowed"));
  EXPECT_TRUE(has_error(r, "b.0", "(got '*a' at line 2; 72 in the text)"));
  EXPECT_EQ(r.errors.size(), 2u) << format_errors(r.errors);
  EXPECT_TRUE(r.hash.empty());  // the canonical text (which walks every node) was never made
}

// The same nine lines inside the shipped scenario, as an unknown key: refused just the same, and
// the rest of the file is not read (its problems would be judged on a document we refuse).
TEST(DocumentLimits, AliasesInsideAValidScenarioAreRefused) {
  std::string text = msr_text();
  text += "bomb:\n";
  std::string lines = exponential_aliases();
  for (std::size_t at = 0; at < lines.size(); at = lines.find('\n', at) + 1) lines.insert(at, "  ");
  text += lines;
  const LoadResult r = load_scenario_text(text);
  EXPECT_TRUE(has_error(r, "bomb.a", "anchors are not allowed"));
  EXPECT_TRUE(has_error(r, "bomb.b.0", "aliases are not allowed"));
  EXPECT_FALSE(r.scenario.has_value());
}

TEST(DocumentLimits, AnAnchorAloneIsRefused) {
  EXPECT_TRUE(has_error(load_msr({"chaser.com_body_m=&c [0, 0, 0]"}), "chaser.com_body_m", "anchors are not allowed"));
  EXPECT_TRUE(has_error(load_scenario_text("name: &n x\n"), "name", "(got '&n' at line 1)"));
}

TEST(DocumentLimits, OverrideValuesMayNotHoldAliases) {
  const LoadResult r = load_msr({"faults=[&f {thruster: T8, kind: stuck_open, onset_s: 10}, *f]"});
  EXPECT_TRUE(has_error(r, "faults.0", "anchors are not allowed"));
  EXPECT_TRUE(has_error(r, "faults.1", "aliases are not allowed"));
}

TEST(DocumentLimits, NestingDepth) {
  // The root mapping is depth 1, x's list 2, ...: the 33rd is at x and 31 indices.
  const LoadResult r = load_scenario_text("x: " + nested_lists(kMaxNestingDepth) + "\n");
  EXPECT_TRUE(has_error(r, repeated_path("x", "0", 31),
                        "lists and mappings may nest at most 32 deep (got a list at depth 33 at line 1)"));
  EXPECT_FALSE(has_error(load_scenario_text("x: " + nested_lists(kMaxNestingDepth - 1) + "\n"),
                         repeated_path("x", "0", 30), "may nest"));
  // Far past yaml-cpp's own recursion guard (2000): still one clear error, at the key.
  EXPECT_TRUE(has_error(load_scenario_text("name: x\ny: " + nested_lists(5000) + "\n"), repeated_path("y", "0", 31),
                        "may nest at most 32 deep"));
  // Nesting is counted through block mappings as well as flow lists.
  std::string block;
  for (int i = 0; i < 40; ++i) block += std::string(static_cast<std::size_t>(2 * i), ' ') + "k:\n";
  EXPECT_TRUE(has_error(load_scenario_text(block), repeated_path("k", "k", 31), "got a mapping at depth 33"));
}

// A value nested inside a deep --set path is judged on the document after the overrides.
TEST(DocumentLimits, NestingDepthAfterOverrides) {
  const LoadResult r = load_msr({"chaser.com_body_m=" + nested_lists(kMaxNestingDepth - 1)});
  EXPECT_TRUE(has_error(r, testing::kMsrPath, "nests lists and mappings more than 32 deep after the --set overrides"));
}

TEST(DocumentLimits, FileSize) {
  const std::string big = "name: x\n" + std::string(kMaxDocumentBytes, '#');
  EXPECT_TRUE(has_error(load_scenario_text(big), "<text>", "is longer than 1048576 bytes (1 MiB)"));
  // From a file: read_text_file stops one byte past the limit.
  const std::string path = (std::filesystem::temp_directory_path() / "chaser_document_limits_big.yaml").string();
  {
    std::ofstream out(path, std::ios::binary);
    out << big << big;
  }
  EXPECT_TRUE(has_error(load_scenario_file(path), path, "is longer than 1048576 bytes"));
  std::remove(path.c_str());
  EXPECT_TRUE(has_error(load_msr({"name=" + std::string(kMaxDocumentBytes + 1, 'x')}), "name", "is longer than 1048576 bytes"));
}

TEST(DocumentLimits, NodeCount) {
  std::string list = "x: [";
  for (std::size_t i = 0; i < kMaxDocumentNodes; ++i) list += "0,";
  list += "0]\n";
  const LoadResult r = load_scenario_text(list);
  EXPECT_TRUE(has_error(r, "<text>", "has more than 100000 nodes (keys, values and list items; the limit was passed at line 1)"));
  EXPECT_EQ(r.errors.size(), 1u) << format_errors(r.errors);
}

TEST(DocumentLimits, ScalarLength) {
  const std::string long_name(kMaxScalarBytes + 1, 'n');
  EXPECT_TRUE(has_error(load_msr({"name=" + long_name}), "name", "a key or value may be at most 1024 bytes long (got 1025 bytes"));
  EXPECT_FALSE(has_error(load_msr({"name=" + std::string(kMaxScalarBytes, 'n')}), "name", ""));
  // A long key (YAML allows it only as an explicit "? key") is reported at the mapping that holds it.
  const LoadResult r = load_scenario_text("chaser:\n  ? " + long_name + "\n  : 1\n");
  EXPECT_TRUE(has_error(r, "chaser", "at most 1024 bytes long (got 1025 bytes at line 2)"));
}

TEST(DocumentLimits, OverrideKeyPath) {
  std::string deep_path = "a";
  for (int i = 0; i < kMaxNestingDepth; ++i) deep_path += ".a";
  EXPECT_TRUE(has_error(load_msr({deep_path + "=1"}), deep_path, "override key path of 33 parts: a key path may have at most 32"));
  const std::string long_path(kMaxScalarBytes + 1, 'p');
  EXPECT_TRUE(has_error(load_msr({long_path + "=1"}), long_path.substr(0, 40) + "...",
                        "override key path of 1025 bytes: a key path may be at most 1024 bytes long"));
}

TEST(DocumentLimits, ListLengths) {
  std::string faults = "faults=[";
  for (int i = 1; i <= 33; ++i) faults += fmt::format("{}{{thruster: T{}, kind: loss, onset_s: 1, loss_size: 0.5}}", i > 1 ? ", " : "", (i - 1) % 32 + 1);
  faults += "]";
  const LoadResult r = load_msr({faults});
  EXPECT_TRUE(has_error(r, "faults", "must be a list of faults, at most 32 (one per thruster; may be empty: []) (got a list of 33)"));
  EXPECT_EQ(r.errors.size(), 1u) << format_errors(r.errors);

  std::string standby = "thrusters.standby_groups=[";
  for (int i = 0; i < 33; ++i) standby += i ? ", B" : "B";
  EXPECT_TRUE(has_error(load_msr({standby + "]"}), "thrusters.standby_groups", "must be a list of at most 32 group names"));

  std::string thrusters = "thrusters.list=[";
  for (int i = 1; i <= 33; ++i) thrusters += fmt::format("{}{{name: T{}, position_body_m: [1, 0, 0], direction_body: [1, 0, 0], max_thrust_N: 1}}", i > 1 ? ", " : "", i);
  EXPECT_TRUE(has_error(load_msr({thrusters + "]"}), "thrusters.list", "must be a list of 1..32 thrusters T1..TN (got a list of 33)"));
}

// A mapping of many keys, all unknown or repeated: every one reported, in time linear in the keys
// (the duplicate check used to compare each key with every earlier one).
TEST(DocumentLimits, ManyUnknownAndDuplicateKeysAreEachReported) {
  std::string text = "chaser:\n";
  for (int i = 0; i < 5000; ++i) text += fmt::format("  key_number_{}: 1\n  key_number_{}: 2\n", i, i);
  const LoadResult r = load_scenario_text(text);
  EXPECT_TRUE(has_error(r, "chaser.key_number_4999", "duplicate key (first at line 10000)"));
  EXPECT_TRUE(has_error(r, "chaser.key_number_0", "unknown key"));
}

TEST(DocumentLimits, InverseSimulationFilesHaveTheSameLimits) {
  std::ifstream file("scenarios/manual_rvd.yaml");
  std::ostringstream manual;
  manual << file.rdbuf();
  const InvSimLoadResult aliased = load_invsim_text(manual.str() + "\nbomb:\n  a: &a [1, 2]\n  b: [*a, *a]\n");
  auto has = [](const InvSimLoadResult& r, const std::string& path, const std::string& fragment) {
    for (const ScenarioError& e : r.errors)
      if (e.key_path == path && e.message.find(fragment) != std::string::npos) return true;
    return false;
  };
  EXPECT_TRUE(has(aliased, "bomb.a", "anchors are not allowed"));
  EXPECT_TRUE(has(aliased, "bomb.b.0", "aliases are not allowed"));
  std::string faults = "faults=[";
  for (std::size_t i = 0; i <= model::kMaxInvSimThrusters; ++i) faults += i ? ", X" : "X";
  const InvSimLoadResult many = load_invsim_text(manual.str(), {faults + "]"});
  EXPECT_TRUE(has(many, "faults", "must be a list of at most 64 thruster names (got a list of 65)"));
}

// Found by fuzz_invsim (docs/reliability.md): yaml-cpp 0.7 reads a text holding only "," as an
// endless stream of empty documents, so loading it never returned; the scan stops at the second.
TEST(DocumentLimits, ACommaAloneIsNotAnEndlessStreamOfDocuments) {
  EXPECT_TRUE(has_error(load_scenario_text(","), "<text>", "must hold exactly one YAML document (a second begins at line 1, column 1)"));
  EXPECT_EQ(load_scenario_text(",").errors.size(), 1u);
  const InvSimLoadResult r = load_invsim_text("# comment\n, , gg\n");
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].key_path, "<text>");
  EXPECT_EQ(r.errors[0].message, "must hold exactly one YAML document (a second begins at line 2, column 1)");
  // Two real documents are reported the same way.
  EXPECT_TRUE(has_error(load_scenario_text("a: 1\n---\nb: 2\n"), "<text>", "must hold exactly one YAML document (a second begins at line 2"));
}

// The shipped scenarios sit far inside every limit.
TEST(DocumentLimits, ShippedScenariosAreFarInside) {
  Diagnostics d;
  EXPECT_TRUE(check_yaml_text(msr_text(), "msr", "", d));
  EXPECT_LT(msr_text().size(), kMaxDocumentBytes / 50);
  EXPECT_TRUE(d.errors().empty());
}

}  // namespace document_limits_test
}  // namespace chaser::io
