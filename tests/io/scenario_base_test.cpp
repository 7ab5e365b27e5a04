// A scenario built on another (`base: FILE`, docs/scenario.md "A scenario built on another"): the
// base's document with the file's own keys laid over it, mapping into mapping, a scalar or a list
// replacing the base's whole; bases chain, never in a cycle; every problem names the key `base`.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "io/scenario_loader.hpp"
#include "scenario_test_util.hpp"

namespace chaser::io {
namespace scenario_base_test {

using testing::has_error;

// A folder of scenario files for one test, removed after it.
class Folder {
 public:
  explicit Folder(const std::string& name)
      : path_(std::filesystem::temp_directory_path() / ("chaser_base_" + name)) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~Folder() { std::filesystem::remove_all(path_); }
  std::string write(const std::string& file, const std::string& text) const {
    std::ofstream(path_ / file) << text;
    return (path_ / file).string();
  }

 private:
  std::filesystem::path path_;
};

std::string msr_absolute() { return std::filesystem::absolute(testing::kMsrPath).string(); }

TEST(ScenarioBase, TheMissionIsTheCaptureWithTheEscapeArmed) {
  const LoadResult mission = load_scenario_file("scenarios/comrade_mission.yaml");
  ASSERT_TRUE(mission.scenario) << format_errors(mission.errors);
  const LoadResult capture = load_scenario_file(
      "scenarios/comrade_capture.yaml", {"name=comrade_mission", "capture.escape={on_failed_grasp: true}"});
  ASSERT_TRUE(capture.scenario) << format_errors(capture.errors);
  EXPECT_EQ(mission.canonical_yaml, capture.canonical_yaml);
  EXPECT_EQ(mission.hash, capture.hash);
  // The abort: a chain of two bases, the escape's mapping merged key by key.
  const LoadResult abort = load_scenario_file("scenarios/comrade_mission_abort.yaml");
  ASSERT_TRUE(abort.scenario) << format_errors(abort.errors);
  ASSERT_TRUE(abort.scenario->capture->escape);
  EXPECT_TRUE(abort.scenario->capture->escape->on_failed_grasp);
  EXPECT_EQ(abort.scenario->capture->escape->command_s, 2870.0);
  EXPECT_EQ(abort.scenario->duration_s, 3900.0);
}

TEST(ScenarioBase, MappingsMergeScalarsAndListsReplace) {
  const Folder folder("merge");
  const std::string path = folder.write("derived.yaml", "base: " + msr_absolute() +
                                                            "\nname: derived\nduration_s: 100.0\n"
                                                            "initial: {r_lvlh_m: [0.0, -200.0, 0.0]}\n"
                                                            "faults: [{thruster: T8, kind: stuck_open, onset_s: 50}]\n");
  const LoadResult derived = load_scenario_file(path);
  ASSERT_TRUE(derived.scenario) << format_errors(derived.errors);
  const LoadResult msr = testing::load_msr();
  ASSERT_TRUE(msr.scenario);
  EXPECT_EQ(derived.scenario->name, "derived");
  EXPECT_EQ(derived.scenario->duration_s, 100.0);
  EXPECT_EQ(derived.scenario->initial.r_lvlh_m, Vec3(0.0, -200.0, 0.0));
  // The rest of `initial` is the base's.
  EXPECT_EQ(derived.scenario->initial.v_lvlh_mps, msr.scenario->initial.v_lvlh_mps);
  EXPECT_EQ(derived.scenario->initial.use_guidance_start, msr.scenario->initial.use_guidance_start);
  ASSERT_EQ(derived.scenario->faults.size(), 1u);
  EXPECT_EQ(derived.scenario->thrusters.count, msr.scenario->thrusters.count);
  // --set still applies over the merged document.
  const LoadResult set = load_scenario_file(path, {"duration_s=200"});
  ASSERT_TRUE(set.scenario) << format_errors(set.errors);
  EXPECT_EQ(set.scenario->duration_s, 200.0);
}

TEST(ScenarioBase, EveryProblemNamesTheKeyBase) {
  const Folder folder("errors");
  const LoadResult missing = load_scenario_file(folder.write("missing.yaml", "base: nowhere.yaml\nname: x\n"));
  EXPECT_TRUE(has_error(missing, "base", "cannot read"));
  const LoadResult not_a_name = load_scenario_file(folder.write("list.yaml", "base: [a, b]\n"));
  EXPECT_TRUE(has_error(not_a_name, "base", "must name a scenario file"));
  folder.write("a.yaml", "base: b.yaml\nname: a\n");
  const LoadResult cycle = load_scenario_file(folder.write("b.yaml", "base: a.yaml\nname: b\n"));
  EXPECT_TRUE(has_error(cycle, "base", "a cycle"));
  const LoadResult self = load_scenario_file(folder.write("self.yaml", "base: self.yaml\n"));
  EXPECT_TRUE(has_error(self, "base", "a cycle"));
  // The base's own problems name its file; the merged document's, their keys.
  folder.write("broken.yaml", "name: [unclosed\n");
  const LoadResult broken = load_scenario_file(folder.write("on_broken.yaml", "base: broken.yaml\n"));
  ASSERT_FALSE(broken.errors.empty());
  EXPECT_NE(broken.errors.front().key_path.find("broken.yaml"), std::string::npos) << format_errors(broken.errors);
  // A key that is not a name (a list as a key) merges without a throw and is refused by the reader.
  const LoadResult list_key =
      load_scenario_file(folder.write("list_key.yaml", "base: " + msr_absolute() + "\n? [a, b]\n: 1\n"));
  EXPECT_FALSE(list_key.scenario);
  EXPECT_FALSE(list_key.errors.empty());
  const LoadResult bad_key = load_scenario_file(folder.write("bad.yaml", "base: " + msr_absolute() + "\nduration_s: -1\n"));
  EXPECT_TRUE(has_error(bad_key, "duration_s", "must be"));
}

}  // namespace scenario_base_test
}  // namespace chaser::io
