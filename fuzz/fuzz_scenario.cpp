// libFuzzer harness: scenario text -> io::load_scenario_text (limits, parse, hash, read, validate)
// and, for an accepted scenario, the run's derived timing (model::run_timing: the clock every
// folder counts periods on); never run. A finding is a crash (an integer division by a period that
// rounded to 0 ns was one), a sanitizer report, a leak, an input slower than -timeout, a broken
// contract of LoadResult (a scenario exactly when there are no errors), or a timing that breaks
// model::check(RunTiming).
#include <cstddef>
#include <cstdint>
#include <string>

#include "io/scenario_loader.hpp"
#include "model/run_timing.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const chaser::io::LoadResult r = chaser::io::load_scenario_text(text);
  if (r.scenario.has_value() == !r.errors.empty()) __builtin_trap();
  for (const chaser::io::ScenarioError& e : r.errors)
    if (e.message.empty()) __builtin_trap();
  if (r.scenario && !chaser::model::check(chaser::model::run_timing(*r.scenario)).empty()) __builtin_trap();
  return 0;
}
