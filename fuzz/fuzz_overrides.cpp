// libFuzzer harness: the --set parser. Each line of the input is one "key.path=value" override,
// applied in order to the shipped scenario (scenarios/msr_terminal.yaml) and validated like the
// file. Findings as in fuzz_scenario.cpp.
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "io/scenario_loader.hpp"

namespace {

const std::string& msr_text() {
  static const std::string text = [] {
    std::ifstream file(CHASER_SOURCE_DIR "/scenarios/msr_terminal.yaml");
    std::ostringstream out;
    out << file.rdbuf();
    if (out.str().empty()) __builtin_trap();  // the harness must fuzz the shipped scenario
    return out.str();
  }();
  return text;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> overrides;
  std::string line;
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] == '\n') {
      overrides.push_back(line);
      line.clear();
    } else {
      line.push_back(static_cast<char>(data[i]));
    }
  }
  if (!line.empty()) overrides.push_back(line);
  const chaser::io::LoadResult r = chaser::io::load_scenario_text(msr_text(), overrides);
  if (r.scenario.has_value() == !r.errors.empty()) __builtin_trap();
  return 0;
}
