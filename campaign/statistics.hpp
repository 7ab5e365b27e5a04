#pragma once
// One-pass statistics of a campaign (Fonod 2015, section V, Table 2): per scheme and case, the mean
// and sample standard deviation of detection and isolation times (Welford's update: numerically
// stable, constant memory, nothing quadratic in N) and the counts behind P_nd, P_f, P_i.
// Fed in run-index order, the result is bit-identical however the runs were executed.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "campaign/cases.hpp"
#include "flight/diagnosis_schemes.hpp"
#include "model/thrusters.hpp"

namespace chaser::campaign {

// Welford's running mean and sum of squared deviations.
class RunningStats {
 public:
  void add(double x);
  std::int64_t count() const { return n_; }
  double mean() const;      // NaN when empty
  double sample_std() const;  // (n - 1) normalisation; NaN when n < 2

 private:
  std::int64_t n_ = 0;
  double mean_ = 0.0;
  double m2_ = 0.0;
};

// The schemes a campaign reports, in order: every diagnosis scheme (flight/diagnosis_schemes.hpp),
// then "fdir", the FDIR as a whole.
inline constexpr std::size_t kMaxStatisticsSchemes = flight::kMaxDiagnosisSchemes + 1;
const std::vector<std::string>& statistics_schemes();

// What the summary reads of one scheme in one runs.csv row.
struct SchemeFacts {
  double detection_s;  // NaN: not detected after the onset
  double isolation_s;  // NaN: no confirmation after the onset
  int isolated;        // thruster index, model::kNoThruster: none
  bool false_alarm, missed;
};

struct RowFacts {
  FaultCase fault_case;
  bool counted;        // status ok or diverged; error runs carry no figures
  bool diverged, error;
  int fault_thruster;  // thruster index, model::kNoThruster: case none
  std::array<SchemeFacts, kMaxStatisticsSchemes> schemes;  // statistics_schemes() order
  bool capture, corridor_kept;
  double propellant_kg;
};

struct SchemeCaseStats {
  std::int64_t runs = 0, detected = 0, missed = 0, false_alarms = 0, right_isolations = 0;
  std::int64_t captures = 0, corridors_kept = 0;
  RunningStats detection_s, isolation_s, propellant_kg;  // isolation: right isolations only
};

// Per case (in the campaign's case order) and scheme.
class CampaignStats {
 public:
  explicit CampaignStats(std::vector<FaultCase> cases);
  void add(const RowFacts& row);
  const std::vector<FaultCase>& cases() const { return cases_; }
  const SchemeCaseStats& at(std::size_t case_index, std::size_t scheme) const { return stats_[case_index][scheme]; }
  std::int64_t diverged(std::size_t case_index) const { return diverged_[case_index]; }
  std::int64_t errors(std::size_t case_index) const { return errors_[case_index]; }

 private:
  std::vector<FaultCase> cases_;
  std::vector<std::array<SchemeCaseStats, kMaxStatisticsSchemes>> stats_;
  std::vector<std::int64_t> diverged_, errors_;
};

// The proportions a campaign reports, in the order of summary.csv's columns: the FDI indices of
// Fonod 2015, section V (P_nd = missed / runs, P_f = false alarms / runs, P_i = right isolations /
// runs) and the mission rates (captures / runs, corridors kept / runs).
enum class RateIndex { kPNd, kPF, kPI, kCaptureRate, kCorridorRate };
inline constexpr std::array<std::string_view, 5> kRateNames = {"P_nd", "P_f", "P_i", "capture_rate", "corridor_rate"};
inline constexpr std::array<RateIndex, 5> kRateIndices = {RateIndex::kPNd, RateIndex::kPF, RateIndex::kPI,
                                                          RateIndex::kCaptureRate, RateIndex::kCorridorRate};
std::string_view to_string(RateIndex index);

// events of runs; the proportion is events / runs.
struct Proportion {
  std::int64_t events = 0, runs = 0;
};

// The counts behind one index; nullopt where the index means nothing: P_nd and P_i of case none
// (there is no fault to miss or isolate).
std::optional<Proportion> proportion_of(const SchemeCaseStats& stats, RateIndex index, FaultCase fault_case);

}  // namespace chaser::campaign
