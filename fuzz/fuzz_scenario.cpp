// libFuzzer harness: scenario text -> io::load_scenario_text (limits, parse, hash, read, validate;
// never run). A finding is a crash, a sanitizer report, a leak, an input slower than -timeout, or
// a broken contract of LoadResult (a scenario exactly when there are no errors).
#include <cstddef>
#include <cstdint>
#include <string>

#include "io/scenario_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const chaser::io::LoadResult r = chaser::io::load_scenario_text(text);
  if (r.scenario.has_value() == !r.errors.empty()) __builtin_trap();
  for (const chaser::io::ScenarioError& e : r.errors)
    if (e.message.empty()) __builtin_trap();
  return 0;
}
