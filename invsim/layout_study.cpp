#include "invsim/layout_study.hpp"

#include <algorithm>
#include <bit>
#include <numeric>
#include <utility>

namespace chaser::invsim {

LayoutSummary summarize_layout(const std::vector<FmeaRow>& rows) {
  LayoutSummary s;
  for (const FmeaRow& row : rows) {
    const InvSimResult& r = row.result;
    s.propellant_kg += r.propellant_kg;
    s.attitude_propellant_kg += r.attitude_propellant_kg;
    s.yaw_on_time_s += r.attitude_on_time_s.z();
    s.mean_k_p += r.k_p;
    if (row.controllable) {
      s.peak_azimuth_rad = std::max(s.peak_azimuth_rad, r.peak_azimuth_rad);
      s.peak_yaw_rad = std::max(s.peak_yaw_rad, r.peak_attitude_rad.z());
    }
    const int failed = std::popcount(row.fmea_case.mode.faults.failed_mask);
    if (failed == 0) {
      s.nominal_controllable = s.nominal_controllable || row.controllable;
      continue;
    }
    ++s.fault_modes;
    ++s.per_class[static_cast<std::size_t>(row.risk)];
    if (row.controllable) {
      ++s.controllable;
      s.most_failed_tolerated = std::max(s.most_failed_tolerated, failed);
    } else if (s.fewest_failed_lost == 0 || failed < s.fewest_failed_lost) {
      s.fewest_failed_lost = failed;
    }
  }
  if (!rows.empty()) s.mean_k_p /= static_cast<double>(rows.size());
  return s;
}

bool better_layout(const LayoutSummary& a, const LayoutSummary& b) {
  if (a.nominal_controllable != b.nominal_controllable) return a.nominal_controllable;
  if (a.controllable != b.controllable) return a.controllable > b.controllable;
  if (a.per_class[1] != b.per_class[1]) return a.per_class[1] < b.per_class[1];
  if (a.propellant_kg != b.propellant_kg) return a.propellant_kg < b.propellant_kg;
  return a.mean_k_p < b.mean_k_p;
}

std::vector<std::size_t> layout_order(const std::vector<LayoutSummary>& summaries) {
  std::vector<std::size_t> order(summaries.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return better_layout(summaries[a], summaries[b]); });
  return order;
}

std::vector<LayoutCandidate> search_layouts(const model::InvSimParams& base,
                                            const std::vector<model::InvSimFreeChoice>& choices,
                                            const std::vector<FmeaCase>& cases, int threads,
                                            std::size_t* flights) {
  const std::size_t n = model::candidate_count(choices);
  std::vector<model::InvSimConfiguration> configurations;
  std::vector<model::InvSimParams> layouts;
  for (std::size_t i = 0; i < n && n <= model::kMaxOptimizeCandidates; ++i) {
    configurations.push_back(model::candidate(choices, i));
    layouts.push_back(model::apply_configuration(base, configurations.back()));
  }
  const std::vector<std::vector<FmeaRow>> rows = run_fmea_of_configurations(layouts, cases, threads, flights);
  std::vector<LayoutSummary> summaries;
  for (const auto& layout_rows : rows) summaries.push_back(summarize_layout(layout_rows));
  std::vector<LayoutCandidate> ranked;
  for (std::size_t i : layout_order(summaries)) ranked.push_back({std::move(configurations[i]), summaries[i]});
  return ranked;
}

}  // namespace chaser::invsim
