#pragma once
// Thruster fault isolation by cross-correlation of the residual with the commanded on-times
// (Fonod 2015, eqs. 42-45), and a signature-correlation variant.
//
// Paper criterion (IsolationCriterion::kPaper), on the last N samples, i = the lanes of the watched set:
//   case 2 or 4 (no over-consumption), eq. 43:  argmax_i |1/(N+1) sum_j r(j) T_on,i(j)|
//   case 1 or 3 (over-consumption),    eq. 44:  argmin_i |1/(N + Omega_i) sum_j r(j) T_on,i(j)|,
//   Omega_i = 1 - sum_j phi_i(j), phi_i(j) = 1 when T_on,i(j) = 0;   eq. 42 picks by the flag of
//   the event resolution (Remark 2). For n_r > 1, |.| is the 2-norm of the correlation vector.
// Eq. 44 read critically: with a full window N + Omega_i = 1 + n_i, n_i the number of samples in
// which thruster i was commanded, so the denominator is never below 1 (with c < N samples since
// the start it is N + 1 - c + n_i >= 1; it would reach 0 only if the "1 -" were dropped and the
// thruster unused). But an unused thruster has a numerator of exactly 0, so no finite penalty keeps
// it from winning the argmin, contrary to the stated intent ("if the i-th thruster is not used...
// the minimum will possibly result in i; this is taken into account by the penalty"). The intent is
// implemented by excluding thrusters with n_i = 0 from the argmin (infinite penalty); the printed
// 1/(1 + n_i) normalisation is kept for the others (a mean per firing). Same reading if phi's two
// cases were swapped (then N + Omega_i = N + 1 - n_i, also >= 1).
//
// Signature criterion (kSignature, ours): the lag-0 correlation of eqs. 43-44 cannot see the fault
// itself, because r(j) responds to T_on,i only from j + 1 on, through the observer error dynamics.
// The signature s_i(k) = Q C z_i(k), z_i(k+1) = A_c z_i(k) + B_bar d_i T_on,i(k) (d_i thruster i's
// input direction: M_F e_i, or M_C e_i) is what a blocked thruster i would add to the residual
// (eq. 31, per unit lost on-time, with the opposite sign). For every fault case the realised minus
// commanded on-time falls with T_on,i (stuck open 1 - T_on, blocked -T_on, loss -m T_on, leak
// max(T_on, m) - T_on), so r - rbar ~ -a (s_i - sbar_i), a > 0, about its window mean rbar. The
// score is the GLR for that hypothesis with unknown offset and scale,
//   score_i = (sum_j (r - rbar).(s_i - sbar_i))^2 / sum_j |s_i - sbar_i|^2   if the sum is < 0, else 0,
// and the candidate is argmax_i; no case flag is needed. Thrusters not commanded in the window score 0
// (a decayed old signature would otherwise fit a trend by its shape alone).
//
// The window must not hold the onset of the fault: its step transient (the residual rising to its
// DC value through the slow observer modes, 0.95^k) is not in the signature model and fits some
// other thruster's signature by its shape. `settle` delays the first evaluation after the alarm;
// with settle >= N + the transient (~40 periods for eigenvalues up to 0.95) the window starts after
// it. The paper's N_c plays a similar role ("to avoid initial transition phenomena").
//
// Common rules: the buffers are filled every period from the start; the criterion is evaluated
// only when `evaluate` (the GLR alarm) has held for more than `settle` periods; otherwise the
// candidate is -1 and the confirmation count is 0. Ties go to the lowest index; when no thruster
// qualifies (none commanded in the window, or every score 0 for an argmax) the candidate is -1.
// Eq. 45: confirmed when the same candidate (>= 0) has come N_c consecutive periods.
#include <array>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "core/zero_array.hpp"
#include "flight/fdi/residual_generator.hpp"
#include "flight/fdi/watched_set.hpp"

namespace chaser::flight::fdi {

inline constexpr int kMaxIsolationWindow = 128;  // largest N the fixed ring buffers hold

using Mat6W = Eigen::Matrix<double, kFdiStateDim, kSchemeThrusters>;

enum class IsolationCriterion {
  kPaper,      // eqs. 42-44 with the exclusion of unused thrusters from eq. 44
  kSignature,  // correlation with each thruster's residual signature
};

// The error dynamics that shape the signatures (from the residual generator and the thrusters).
struct SignatureFilterParams {
  Mat6 A_c = Mat6::Zero();        // [-] A_bar - L C
  Mat36 QC = Mat36::Zero();       // [-] Q C, rows >= n_r zero
  Mat6W B_thr = Mat6W::Zero();    // [state unit per unit on-time] B_bar d_i, one column per thruster
};

struct IsolationParams {
  IsolationCriterion criterion = IsolationCriterion::kPaper;
  int window = 10;        // N, 1..kMaxIsolationWindow (the paper: 10)
  int confirmation = 15;  // N_c >= 1 (the paper: 15)
  int settle = 0;         // periods after the alarm before the first evaluation (0: the paper)
  SignatureFilterParams signature;  // used by kSignature only
};

struct IsolationState {
  std::array<Vec3, kMaxIsolationWindow> residual = zero_array<Vec3, kMaxIsolationWindow>();  // r(j)
  std::array<VecW, kMaxIsolationWindow> ton = zero_array<VecW, kMaxIsolationWindow>();     // T_on,i(j) [-]
  std::array<Mat3W, kMaxIsolationWindow> signature = zero_array<Mat3W, kMaxIsolationWindow>();  // s_i(j), kSignature only
  int next = 0;                     // ring slot of the next sample
  int count = 0;                    // samples stored, up to the window
  Mat6W signature_state = Mat6W::Zero();  // z_i(k), one column per thruster
  int evaluated = 0;                // consecutive periods with `evaluate`, counted up to settle + 1
  int last_candidate = -1;          // sigma^N(k - 1)
  int run_length = 0;               // consecutive periods with the same candidate
};

struct IsolationOutput {
  int candidate = -1;   // sigma^N(k), a lane of the watched set, -1 for none
  int run_length = 0;   // periods the candidate has held, eq. 45
  int confirmed = -1;   // the candidate once run_length >= N_c, else -1
  VecW score = VecW::Zero();  // the criterion per thruster (eq. 43, 44 or the signature score)
};

// Problems with the parameters (empty when valid), each naming the field.
std::vector<std::string> validate(const IsolationParams& params);

// Signature filter from the runtime observer and the thrusters' input directions (3 x 8: M_F, the
// LVLH force per unit on-time with the attitude taken as in the design, or M_C).
SignatureFilterParams make_signature_filter(const ResidualGeneratorParams& residual,
                                            const Mat3W& thruster_inputs);

// One period: stores r(k), T_on(k) (and s(k)), and when `evaluate` computes eq. 42 (43 or 44 by
// `over_consumption`) or the signature criterion, then eq. 45.
IsolationOutput step_isolation(const IsolationParams& params, IsolationState& state, const Vec3& r,
                               const SchemeTon& ton, bool evaluate, bool over_consumption);

}  // namespace chaser::flight::fdi
