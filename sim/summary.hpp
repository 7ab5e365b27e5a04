#pragma once
// summary.json of a run: metadata (scenario, hash, seed, version) and the run's figures.
#include <string>

#include <nlohmann/json.hpp>

#include "model/scenario.hpp"
#include "sim/run.hpp"

namespace chaser::sim {

inline constexpr const char* kChaserVersion = CHASER_VERSION;

nlohmann::json run_summary(const model::Scenario& scenario, const std::string& scenario_hash, const RunResult& result);

// The short human-readable summary printed by `chaser run`.
std::string summary_text(const model::Scenario& scenario, const RunResult& result);

}  // namespace chaser::sim
