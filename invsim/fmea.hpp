#pragma once
// Failure-mode and effects analysis of the manually controlled approach (Zhou 2018, sections 3-4):
// the nominal run, the fault modes of Tables 2 and 5 and the scenario's own fault set, each run
// by inverse simulation, then judged and ranked by risk (Table 6's classes).
//
// Risk classes (Zhou 2018, section 4.1: controllable small deviation, controllable large deviation,
// uncontrollable). The paper names them but gives no numeric boundary; ours:
//  - controllable: docked, the target in view at every attitude period (the paper: out of view,
//    "the mission would fail without other sensors"), and the run did not diverge;
//  - deviation ratio: the larger of peak |az| / az limit and peak |el| / el limit (the line of
//    sight; the paper's Class II is "a large deviation of the yaw and the azimuth");
//  - large deviation (Class II): controllable with the ratio above kLargeDeviationFraction (half
//    the az/el limits), or with the attitude beyond its +-1 deg limit at some time (the yaw
//    deviation of Class II); small deviation (Class I): the other controllable modes;
//    Class III: not controllable.
// Ranking, most severe first: class, then the operational amount k_p (the paper's risk is the
// pilot's compensatory workload, section 3.2), then the deviation ratio, then the mode order.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "invsim/fault_modes.hpp"
#include "invsim/inverse_simulation.hpp"
#include "model/invsim.hpp"

namespace chaser::invsim {

inline constexpr double kLargeDeviationFraction = 0.5;  // [-] of the azimuth / elevation limits

enum class FmeaTable { kNominal, kSingleAxis, kMultiAxis, kThreeAxis, kScenario };  // Table 4 / 2, 5, ours, user
enum class RiskClass { kSmallDeviation, kLargeDeviation, kUncontrollable };  // Class I, II, III

struct FmeaCase {
  FaultMode mode;
  FmeaTable table = FmeaTable::kNominal;
};

struct FmeaRow {
  FmeaCase fmea_case;
  InvSimResult result;
  double deviation_ratio = 0.0;  // [-] see above
  bool controllable = false;
  RiskClass risk = RiskClass::kSmallDeviation;
  int rank = 0;                  // 1 = most severe
};

// The per-step history of a row. With several noise draws it is the draw the row's class comes
// from (worst_draw), flown again with the same seed: the row's counts are the draws' means, its
// peaks their maxima, so no single history is the row; this one is its worst case.
struct FmeaHistory {
  std::uint64_t draws = 1;             // noise draws the row combines
  std::optional<std::uint64_t> seed;   // the measurement-noise seed of the draw shown; empty without noise
  std::vector<InvSimSample> samples;
};

// Nominal ("nominal"), Table 2, Table 5, with `three_axis` the 64 three-axis modes, then the
// scenario's faults ("scenario") when not empty.
std::vector<FmeaCase> fmea_cases(const model::InvSimParams& p, const model::InvSimFaultSet& scenario_faults,
                                 bool three_axis = false);

// Runs every case on `threads` workers (>= 1); rows in case order whatever `threads`.
std::vector<FmeaRow> run_fmea(const model::InvSimParams& p, const std::vector<FmeaCase>& cases, int threads);

// Every case on every layout (one InvSimParams per thruster configuration), all pairs shared by
// `threads` workers; result[l] holds layout l's rows in case order, ranked within the layout.
// With `histories`, (*histories)[l][i] receives the history of case i on layout l (FmeaHistory).
std::vector<std::vector<FmeaRow>> run_fmea(const std::vector<model::InvSimParams>& layouts,
                                           const std::vector<FmeaCase>& cases, int threads,
                                           std::vector<std::vector<FmeaHistory>>* histories = nullptr);

// run_fmea's rows, bit for bit, for layouts that differ only in their thrusters (configurations of
// one scenario: model::apply_configuration): a (layout, case) pair whose thruster signature
// (invsim/inverse_simulation.hpp) an earlier pair has is not flown again but copied. In `chaser fmea
// --optimize` the shipped choices leave 939 distinct flights of 1,968 (48 layouts x 41 modes).
// `flights`, when given, receives the number flown.
std::vector<std::vector<FmeaRow>> run_fmea_of_configurations(const std::vector<model::InvSimParams>& layouts,
                                                             const std::vector<FmeaCase>& cases, int threads,
                                                             std::size_t* flights = nullptr);

// Judging one result, and the ranking of all rows (sets FmeaRow::rank).
double deviation_ratio(const model::InvSimSensorParams& limits, const InvSimResult& r);
bool is_controllable(const InvSimResult& r);
RiskClass classify_risk(const model::InvSimSensorParams& limits, const InvSimResult& r);
void rank_by_risk(std::vector<FmeaRow>& rows);

// Index of the draw that decides a row (the first of equals): the most severe class, then the
// largest deviation ratio, then the largest attitude peak.
std::size_t worst_draw(const model::InvSimSensorParams& limits, const std::vector<InvSimResult>& draws);

// Row indices, most severe first.
std::vector<std::size_t> risk_order(const std::vector<FmeaRow>& rows);

// Failed thrusters' names, space separated ("" for none), in thruster order.
std::string failed_names(const model::InvSimParams& p, const model::InvSimFaultSet& faults);

std::string_view risk_class_name(RiskClass c);  // "controllable, small deviation", ...
std::string_view risk_class_roman(RiskClass c); // "I", "II", "III"
std::string_view table_name(FmeaTable t);       // "nominal", "table2", "table5", "three_axis", "scenario"

}  // namespace chaser::invsim
