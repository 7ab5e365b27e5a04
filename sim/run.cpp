#include "sim/run.hpp"

#include <chrono>

#include "core/wall_clock.hpp"
#include "flight/flight_software.hpp"
#include "sim/simulation.hpp"

namespace chaser::sim {

const SchemeResult& scheme_result(const FdirResult& fdir, std::string_view name) {
  const std::vector<flight::DiagnosisScheme>& schemes = flight::diagnosis_schemes();
  std::size_t i = 0;
  while (i < schemes.size() && schemes[i].name != name) ++i;
  return fdir.schemes.at(i);  // a name not in the table: out of range, a programming error
}

RunResult run_scenario(const model::Scenario& scenario, const RunOptions& options) {
  const auto wall_start = std::chrono::steady_clock::now();
  const flight::FlightParams flight_params = flight::make_flight_params(scenario);
  const double design_s = seconds_since(wall_start);
  RunResult result = run_scenario(scenario, flight_params, options);
  result.wall_design_s = design_s;
  result.wall_s = seconds_since(wall_start);
  return result;
}

RunResult run_scenario(const model::Scenario& scenario, const flight::FlightParams& flight_params,
                       const RunOptions& options) {
  Simulation simulation(scenario, flight_params, options);
  while (!simulation.done()) simulation.step();
  return simulation.finish();
}

}  // namespace chaser::sim
