#pragma once
// Thruster fault detection from the gyro's torque rows (Chaser's third scheme; docs/fdi.md,
// "Deficit detector"). The published schemes watch one residual direction each and miss faults on
// thrusters that move it little (T1/T5 thrust loss, body z) or fire rarely (a blocked T4 or T7 is
// missed for the 200 s after the onset): docs/fdi.md, findings 5, 6 and 8. Each rare pulse a
// blocked thruster misses, though, leaves tens of sigmas in Euler's equation, as the gyro sees it.
//
// On a sliding window of the last N torque rows (deficit_isolation.hpp: y(k), weights W(k)), the
// hypothesis "thruster i realises a + b T_on,i(k) more than commanded" (a >= 0, b <= 0) is
// fitted per thruster; its gain (the drop of the weighted RSS, a GLR statistic) is
//   S_i = max over a >= 0, b <= 0 of  2 g'x - x'Hx,   H = sum_k [1 u; u u^2] c' W(k) c,
//   g = sum_k [1; u] c' W(k) y(k),  u = T_on,i(k), c = M_C,i,
// a fit of five sums per thruster. W(k) is diagonal, so the two sums without u are linear in
// sum_k W(k) and sum_k W(k) y(k) (c'Wc = sum over axes c_a^2 w_a): the window keeps those two
// 3-vectors for all the watched thrusters, and per thruster only the three sums with u, to which a row
// adds nothing unless the thruster was commanded. Most periods command none (81 % of the MSR
// approach, 0.26 thrusters a period on average), so a period's row costs its weights and six
// additions. The rows are summed in blocks of `evaluate_every` periods, the gains' cadence: per
// period the row is added to the open block; when the block is complete it enters the window and
// the oldest block leaves it. The window's sums at every evaluation are those of its last N rows,
// as with a ring of single rows, for a fraction of the memory traffic and ring size.
// The alarm is raised when some thruster's S_i exceeds the threshold AND its fitted deficit is
// material (a >= min_a or b <= -min_b). The second test keeps the small systematic errors of a
// healthy thruster set (1 % thrust dispersion, misalignment, a pulse cut by the minimum on-time)
// from raising an alarm however long the window: they are significant but small, the faults
// of Fonod 2015's ranges are 10-100 % of a thruster. Partners (same torque) are alike here; the
// deficit bank's position rows tell them apart after the alarm.
//
// Any watched set of 1..kMaxWatchedThrusters (deficit_isolation.hpp, "Lanes"): the per-thruster
// sums are stored at that capacity and only the set's lanes are touched. A block's bookkeeping
// (entering the window, leaving it, being reset) costs per lane, so a 24-thruster set pays three
// times MSR's there; the rows themselves cost per commanded thruster, whatever the set.
//
// Cost: the weights and six additions per period, ten flops more per commanded thruster, and the
// lanes' gains every `evaluate_every` periods (bench: BM_FdirPeriod/fdi_on less BM_FdirPeriod/fdi_published).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "flight/fdi/deficit_isolation.hpp"

namespace chaser::flight::fdi {

inline constexpr int kMaxDeficitDetectorWindow = model::kMaxDeficitDetectorWindowPeriods;

struct DeficitDetectorParams {
  int window = 100;          // [periods] N
  double threshold = 100.0;  // [-] on S_i
  double min_a = 0.05;       // [-] smallest constant deficit that counts as a fault
  double min_b = 0.3;        // [-] smallest command-proportional deficit that counts (a 20 % inertia error reads as 0.2)
  int evaluate_every = 1;    // [periods] between evaluations of the gains, a divisor of window
};

std::vector<std::string> validate(const DeficitDetectorParams& params);

// Per thruster, the three sums with u, row i for thruster i: [u c'Wc, u^2 c'Wc, u c'Wy] (the
// normal equations' hab, hbb, gb).
using DeficitCommandSums = Eigen::Matrix<double, kMaxWatchedThrusters, 3>;
// Per thruster, the rows in which it was commanded (T_on > 0). Kept exactly (integers) because the
// running sums are not: once a thruster's last pulse has left the window, its command sums are the
// rounding residue of adding and removing that pulse, ~1e-16 of it, not zero, and its b fitted
// from them is arbitrary (it made a "material" b and an alarm in a Table 2 run).
using DeficitCommandedRows = Eigen::Matrix<std::int32_t, kMaxWatchedThrusters, 1>;

// The sums of a run of rows.
struct DeficitDetectorBlock {
  Vec3 weight_sum = Vec3::Zero();          // [1/(N m)^2] sum_k diag W(k)
  Vec3 weighted_row_sum = Vec3::Zero();    // [1/(N m)] sum_k W(k) y(k)
  DeficitCommandSums command = DeficitCommandSums::Zero();  // [-] per thruster, the sums with u
  DeficitCommandedRows commanded = DeficitCommandedRows::Zero();
};

struct DeficitDetectorState {
  std::array<DeficitDetectorBlock, kMaxDeficitDetectorWindow> ring{};  // each block's contribution (window / every used)
  DeficitDetectorBlock sums;   // over the complete blocks in the window; the command sums of a
                               // thruster not commanded in it are exactly zero (its hypothesis: a alone, b = 0)
  DeficitDetectorBlock block;  // the rows of the open block
  std::int64_t rows = 0;          // torque rows added
  int slot = 0;                   // ring slot of the next block: (rows / every) % (window / every)
  int phase = 0;                  // rows % evaluate_every, the rows in `block` (counters: no integer
                                  // division per period)
  bool alarm = false;             // latched
  std::int64_t alarm_sample = -1; // sample index of the first alarm
  double statistic = 0;           // [-] max_i S_i (material or not), last evaluation
  int suspect = -1;               // lane of the largest material gain (else of the largest);
                                  // a partner's twin (same torque) is as likely
  double material_statistic = 0;  // [-] the largest material gain, last evaluation (0: no material fit)
};

// The normal equations [haa, hab, hbb, ga, gb] of the lanes' hypotheses (fit_deficits) on the rows
// summed in `sums`: haa = (M_C o M_C)' sum W, ga = M_C' sum W y, the rest the command sums.
DeficitNormalsW deficit_normals(const DeficitIsolationParams& bank_params, const DeficitDetectorBlock& sums);

// Call after push_deficit_sample: adds the torque row of the previous sample, then evaluates.
void step_deficit_detector(const DeficitDetectorParams& params, const DeficitIsolationParams& bank_params,
                           const DeficitBankState& bank, DeficitDetectorState& state);

}  // namespace chaser::flight::fdi
