#include "model/run_timing.hpp"

namespace chaser::model {

RunTiming run_timing(const Scenario& scenario) {
  RunTiming t;
  t.control_period_ns = from_seconds(scenario.control_period_s);
  t.periods = from_seconds(scenario.duration_s) / t.control_period_ns;
  t.duration_ns = t.periods * t.control_period_ns;
  return t;
}

std::vector<std::string> check(const RunTiming& timing) {
  std::vector<std::string> broken;
  if (timing.control_period_ns < 1) broken.emplace_back("control_period_ns < 1");
  if (timing.periods < 1) broken.emplace_back("periods < 1");
  if (timing.control_period_ns >= 1 && timing.duration_ns != timing.periods * timing.control_period_ns)
    broken.emplace_back("duration_ns != periods * control_period_ns");
  return broken;
}

}  // namespace chaser::model
