#include "invsim/fmea.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <thread>
#include <tuple>
#include <utility>

#include "invsim/noise_draws.hpp"
#include "invsim/paper_reading.hpp"

namespace chaser::invsim {

std::vector<FmeaCase> fmea_cases(const model::InvSimParams& p, const model::InvSimFaultSet& scenario_faults,
                                 bool three_axis) {
  std::vector<FmeaCase> cases;
  cases.push_back({FaultMode{"nominal", {}}, FmeaTable::kNominal});
  for (auto& m : single_axis_fault_modes(p)) cases.push_back({std::move(m), FmeaTable::kSingleAxis});
  for (auto& m : multi_axis_fault_modes(p)) cases.push_back({std::move(m), FmeaTable::kMultiAxis});
  if (three_axis)
    for (auto& m : three_axis_fault_modes(p)) cases.push_back({std::move(m), FmeaTable::kThreeAxis});
  if (scenario_faults.failed_mask != 0)
    cases.push_back({FaultMode{"scenario", scenario_faults}, FmeaTable::kScenario});
  return cases;
}

std::vector<FmeaRow> run_fmea(const model::InvSimParams& p, const std::vector<FmeaCase>& cases, int threads) {
  return std::move(run_fmea(std::vector<model::InvSimParams>{p}, cases, threads).front());
}

namespace {

// Runs job(k) for k = 0 .. total - 1 on `threads` workers, each taking the next k.
template <typename Job>
void parallel_for(std::size_t total, int threads, const Job& job) {
  std::atomic<std::size_t> next{0};
  auto work = [&]() {
    for (std::size_t k = next++; k < total; k = next++) job(k);
  };
  const std::size_t workers =
      std::clamp<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), 1, std::max<std::size_t>(total, 1));
  std::vector<std::thread> pool;
  for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
}

FmeaRow judged_row(const model::InvSimParams& p, const FmeaCase& c, InvSimResult result) {
  FmeaRow row;
  row.fmea_case = c;
  row.result = std::move(result);
  row.deviation_ratio = deviation_ratio(p.sensor, row.result);
  row.controllable = is_controllable(row.result);
  row.risk = classify_risk(p.sensor, row.result);
  return row;
}

// The row's result; with `history`, also the history of the draw the row's class comes from: a
// single draw is recorded as it flies, of several the worst is flown once more to record it.
InvSimResult fly_row(const model::InvSimParams& p, const model::InvSimFaultSet& faults, FmeaHistory* history) {
  if (history == nullptr) return run_over_noise_draws(p, faults);
  history->draws = noise_draws_per_mode(p);
  std::uint64_t shown = 0;
  InvSimResult result;
  if (history->draws <= 1) {
    result = run_inverse_simulation(p, faults, &history->samples);
  } else {
    const std::vector<InvSimResult> draws = fly_noise_draws(p, faults);
    shown = worst_draw(p.sensor, draws);
    run_inverse_simulation(noise_draw(p, shown), faults, &history->samples);
    result = combine_draws(draws, p.pulses.basic_pulse_amount);
  }
  history->seed.reset();
  if (flight_choices(p).measurement_noise.enabled()) history->seed = noise_draw_seed(p, shown);
  return result;
}

}  // namespace

std::vector<std::vector<FmeaRow>> run_fmea(const std::vector<model::InvSimParams>& layouts,
                                           const std::vector<FmeaCase>& cases, int threads,
                                           std::vector<std::vector<FmeaHistory>>* histories) {
  std::vector<std::vector<FmeaRow>> rows(layouts.size(), std::vector<FmeaRow>(cases.size()));
  if (histories != nullptr) histories->assign(layouts.size(), std::vector<FmeaHistory>(cases.size()));
  // Each worker takes the next (layout, case) pair; every run is independent of the others and of
  // the order, so the rows do not depend on the number of workers.
  parallel_for(layouts.size() * cases.size(), threads, [&](std::size_t k) {
    const std::size_t l = k / cases.size(), i = k % cases.size();
    FmeaHistory* history = histories != nullptr ? &(*histories)[l][i] : nullptr;
    rows[l][i] = judged_row(layouts[l], cases[i], fly_row(layouts[l], cases[i].mode.faults, history));
  });
  for (auto& layout_rows : rows) rank_by_risk(layout_rows);
  return rows;
}

std::vector<std::vector<FmeaRow>> run_fmea_of_configurations(const std::vector<model::InvSimParams>& layouts,
                                                             const std::vector<FmeaCase>& cases, int threads,
                                                             std::size_t* flights) {
  // One flight per distinct thruster signature; flight[l][i] is the one pair (l, i) takes its row from.
  struct Pair {
    std::size_t layout, mode;
  };
  std::map<std::vector<double>, std::size_t> flight_of;  // signature -> index in `flown`
  std::vector<Pair> flown;
  std::vector<std::vector<std::size_t>> flight(layouts.size(), std::vector<std::size_t>(cases.size()));
  for (std::size_t l = 0; l < layouts.size(); ++l)
    for (std::size_t i = 0; i < cases.size(); ++i) {
      std::vector<double> signature = thruster_signature(layouts[l], cases[i].mode.faults);
      // A non-finite value would break the map's order: such a pair is flown on its own.
      if (std::all_of(signature.begin(), signature.end(), [](double v) { return std::isfinite(v); })) {
        const auto [it, added] = flight_of.try_emplace(std::move(signature), flown.size());
        flight[l][i] = it->second;
        if (!added) continue;
      } else {
        flight[l][i] = flown.size();
      }
      flown.push_back({l, i});
    }
  if (flights != nullptr) *flights = flown.size();
  std::vector<InvSimResult> results(flown.size());
  parallel_for(flown.size(), threads, [&](std::size_t f) {
    results[f] = run_over_noise_draws(layouts[flown[f].layout], cases[flown[f].mode].mode.faults);
  });
  std::vector<std::vector<FmeaRow>> rows(layouts.size(), std::vector<FmeaRow>(cases.size()));
  for (std::size_t l = 0; l < layouts.size(); ++l)
    for (std::size_t i = 0; i < cases.size(); ++i) rows[l][i] = judged_row(layouts[l], cases[i], results[flight[l][i]]);
  for (auto& layout_rows : rows) rank_by_risk(layout_rows);
  return rows;
}

double deviation_ratio(const model::InvSimSensorParams& limits, const InvSimResult& r) {
  const double ratio = std::max(r.peak_azimuth_rad / limits.azimuth_limit_rad,
                                r.peak_elevation_rad / limits.elevation_limit_rad);
  // A diverged run may leave non-finite peaks: the worst deviation, and a total order for ranking.
  return std::isfinite(ratio) ? ratio : std::numeric_limits<double>::infinity();
}

bool is_controllable(const InvSimResult& r) { return r.docked && r.target_always_in_view && !r.diverged; }

RiskClass classify_risk(const model::InvSimSensorParams& limits, const InvSimResult& r) {
  if (!is_controllable(r)) return RiskClass::kUncontrollable;
  const bool large = deviation_ratio(limits, r) > kLargeDeviationFraction || !r.attitude_within_limits;
  return large ? RiskClass::kLargeDeviation : RiskClass::kSmallDeviation;
}

std::vector<std::size_t> risk_order(const std::vector<FmeaRow>& rows) {
  std::vector<std::size_t> order(rows.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const FmeaRow& x = rows[a];
    const FmeaRow& y = rows[b];
    if (x.risk != y.risk) return x.risk > y.risk;
    if (x.result.k_p != y.result.k_p) return x.result.k_p > y.result.k_p;
    return x.deviation_ratio > y.deviation_ratio;
  });
  return order;
}

std::size_t worst_draw(const model::InvSimSensorParams& limits, const std::vector<InvSimResult>& draws) {
  // A diverged draw may carry non-finite peaks: they count as the worst.
  auto finite_or_worst = [](double v) { return std::isfinite(v) ? v : std::numeric_limits<double>::infinity(); };
  auto severity = [&](const InvSimResult& r) {
    return std::tuple(classify_risk(limits, r), deviation_ratio(limits, r),
                      finite_or_worst(r.peak_attitude_rad.maxCoeff()));
  };
  std::size_t worst = 0;
  for (std::size_t k = 1; k < draws.size(); ++k)
    if (severity(draws[worst]) < severity(draws[k])) worst = k;
  return worst;
}

void rank_by_risk(std::vector<FmeaRow>& rows) {
  const std::vector<std::size_t> order = risk_order(rows);
  for (std::size_t k = 0; k < order.size(); ++k) rows[order[k]].rank = static_cast<int>(k) + 1;
}

std::string failed_names(const model::InvSimParams& p, const model::InvSimFaultSet& faults) {
  std::string out;
  for (std::size_t i = 0; i < p.thrusters.size(); ++i) {
    if (!faults.failed(i)) continue;
    if (!out.empty()) out += ' ';
    out += p.thrusters[i].name;
  }
  return out;
}

std::string_view risk_class_name(RiskClass c) {
  switch (c) {
    case RiskClass::kSmallDeviation: return "controllable, small deviation";
    case RiskClass::kLargeDeviation: return "controllable, large deviation";
    case RiskClass::kUncontrollable: return "uncontrollable";
  }
  return "";
}

std::string_view risk_class_roman(RiskClass c) {
  switch (c) {
    case RiskClass::kSmallDeviation: return "I";
    case RiskClass::kLargeDeviation: return "II";
    case RiskClass::kUncontrollable: return "III";
  }
  return "";
}

std::string_view table_name(FmeaTable t) {
  switch (t) {
    case FmeaTable::kNominal: return "nominal";
    case FmeaTable::kSingleAxis: return "table2";
    case FmeaTable::kMultiAxis: return "table5";
    case FmeaTable::kThreeAxis: return "three_axis";
    case FmeaTable::kScenario: return "scenario";
  }
  return "";
}

}  // namespace chaser::invsim
