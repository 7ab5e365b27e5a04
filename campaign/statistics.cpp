#include "campaign/statistics.hpp"

#include <cmath>
#include <limits>

namespace chaser::campaign {

void RunningStats::add(double x) {
  ++n_;
  const double delta = x - mean_;
  mean_ += delta / static_cast<double>(n_);
  m2_ += delta * (x - mean_);
}

double RunningStats::mean() const { return n_ > 0 ? mean_ : std::numeric_limits<double>::quiet_NaN(); }

double RunningStats::sample_std() const {
  return n_ > 1 ? std::sqrt(m2_ / static_cast<double>(n_ - 1)) : std::numeric_limits<double>::quiet_NaN();
}

const std::vector<std::string>& statistics_schemes() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const flight::DiagnosisScheme& s : flight::diagnosis_schemes()) n.push_back(s.name);
    n.emplace_back("fdir");
    return n;
  }();
  return names;
}

CampaignStats::CampaignStats(std::vector<FaultCase> cases)
    : cases_(std::move(cases)), stats_(cases_.size()), diverged_(cases_.size(), 0), errors_(cases_.size(), 0) {}

void CampaignStats::add(const RowFacts& row) {
  std::size_t c = 0;
  while (c < cases_.size() && cases_[c] != row.fault_case) ++c;
  if (c == cases_.size()) return;
  diverged_[c] += row.diverged;
  errors_[c] += row.error;
  if (!row.counted) return;
  for (std::size_t k = 0; k < statistics_schemes().size(); ++k) {
    const SchemeFacts& f = row.schemes[k];
    SchemeCaseStats& s = stats_[c][k];
    ++s.runs;
    s.missed += f.missed;
    s.false_alarms += f.false_alarm;
    s.captures += row.capture;
    s.corridors_kept += row.corridor_kept;
    s.propellant_kg.add(row.propellant_kg);
    if (!std::isnan(f.detection_s)) {
      ++s.detected;
      s.detection_s.add(f.detection_s);
    }
    // A right isolation: the faulty thruster confirmed after the onset (Fonod 2015, P_i).
    if (row.fault_thruster != model::kNoThruster && f.isolated == row.fault_thruster && !std::isnan(f.isolation_s)) {
      ++s.right_isolations;
      s.isolation_s.add(f.isolation_s);
    }
  }
}

std::string_view to_string(RateIndex index) { return kRateNames[static_cast<std::size_t>(index)]; }

std::optional<Proportion> proportion_of(const SchemeCaseStats& s, RateIndex index, FaultCase fault_case) {
  const bool fault = fault_case != FaultCase::kNone;
  switch (index) {
    case RateIndex::kPNd: return fault ? std::optional(Proportion{s.missed, s.runs}) : std::nullopt;
    case RateIndex::kPF: return Proportion{s.false_alarms, s.runs};
    case RateIndex::kPI: return fault ? std::optional(Proportion{s.right_isolations, s.runs}) : std::nullopt;
    case RateIndex::kCaptureRate: return Proportion{s.captures, s.runs};
    case RateIndex::kCorridorRate: return Proportion{s.corridors_kept, s.runs};
  }
  return std::nullopt;
}

}  // namespace chaser::campaign
