#pragma once
// H-infinity (sub)optimal output-feedback synthesis with gamma iteration, by SLICOT's SB10AD
// (SLICOT 5.0, Debian's libslicot; the interface is unchanged up to SLICOT-Reference 5.7).
//
// For the generalised plant P (inputs [w; u], outputs [z; y]; see control/state_space.hpp)
// SB10AD computes the central controller of Glover & Doyle (1988), "State-space formulae for all
// stabilizing controllers that satisfy an H-infinity norm bound and relations to risk
// sensitivity", Systems & Control Letters 11, pp. 167-172, in the form of Petkov, Gu, Konstantinov
// (1998), Leicester Univ. report 98-14, for the smallest gamma its iteration finds:
// JOB = 1, bisection on gamma from gamma_max down towards max(sigma[D1111, D1112],
// sigma[D1111', D1121']), keeping a gamma when both Riccati equations are solved, the controller
// formula is admissible, and the closed loop's poles all have real part below ACTOL = 0. It stops
// when the bisection step is below GTOL = tol (absolute, in units of gamma), so the reported
// gamma is within about tol above the threshold SB10AD's test finds.
//
// That test is closed-loop stability, not the full existence conditions (X >= 0, Y >= 0,
// rho(XY) < gamma^2 are not all checked), so the threshold can lie a little below the true optimum:
// with tol down to ~1e-6 gamma the controller may not achieve the reported gamma. Measured on
// S&P's SISO S/KS example (docs/control.md): tol = 1e-4 gives gamma 1.3659719, closed-loop norm
// 2e-9 below it; tol = 1e-8 gives a norm 3e-6 above gamma, tol = 1e-10 6e-4 above. Keep
// tol >= 1e-5 gamma and check the result with hinf_norm_estimate (control/frequency_response.hpp).
//
// SB10AD assumes (it does not test A1 itself: a violation shows as a Riccati failure or as no
// stabilising controller):
//   (A1) (A, B2) stabilisable and (C2, A) detectable;
//   (A2) D12 full column rank, D21 full row rank;
//   (A3) [A - j w I, B2; C1, D12] full column rank for all w;
//   (A4) [A - j w I, B1; C2, D21] full row rank for all w.
// SLICOT 5.0 tests A3 and A4 at omega = 0 only (SB10PD), and (A2) is also checked here first
// (see hinf_synthesis.cpp: SLICOT's test misses an all-zero D12). Every INFO code comes back as
// a status with a message; nothing aborts. Sizes are validated
// here first, because an illegal argument makes SB10AD call XERBLA, whose reference version in
// LAPACK prints a line and STOPs the whole process.
//
// Design-time code: allocates; one SB10AD call per synthesise.
#include <array>
#include <string>

#include "control/state_space.hpp"

namespace chaser::control {

enum class HinfStatus {
  kOk,
  kInvalidInput,             // rejected before SLICOT: sizes, finiteness, SB10AD's dimension rules
  kA3RankDeficient,          // INFO 1: [A - jwI, B2; C1, D12] not of full column rank
  kA4RankDeficient,          // INFO 2: [A - jwI, B1; C2, D21] not of full row rank
  kD12RankDeficient,         // INFO 3: D12 not of full column rank (tolerance sqrt(eps))
  kD21RankDeficient,         // INFO 4: D21 not of full row rank (tolerance sqrt(eps))
  kSvdFailed,                // INFO 5: an SVD did not converge
  kGammaTooSmall,            // INFO 6: gamma_max not admissible (at or below the D11 bound)
  kXRiccatiFailed,           // INFO 7: the X-Riccati equation could not be solved
  kYRiccatiFailed,           // INFO 8: the Y-Riccati equation could not be solved
  kSingularTransform,        // INFO 9: Im2 + Tu D11hat Ty D22 singular
  kD11SingularValuesFailed,  // INFO 10: SVD of D1111, D1112, D1111', D1121' failed
  kIllPosedLoop,             // INFO 11: Inp2 - D22 DK or Im2 - DK D22 singular
  kNoStabilisingController,  // INFO 12: no gamma in (bound, gamma_max] gave a stable closed loop
  kSlicotArgumentError,      // INFO < 0: an argument SB10AD refused (validation should prevent it)
};

const char* to_string(HinfStatus status);

struct HinfResult {
  HinfStatus status = HinfStatus::kInvalidInput;
  std::string message;          // what went wrong and what to change; "" when ok
  int slicot_info = 0;          // SB10AD's INFO (0 unless SLICOT was called and failed)
  double gamma = 0.0;           // achieved gamma (the last one SB10AD's iteration accepted)
  StateSpace controller;        // K: n states, n_meas inputs (y), n_ctrl outputs (u); u = K y
  StateSpace closed_loop;       // SB10AD's own F_l(P, K) (AC, BC, CC, DC): 2n states, w -> z
  std::array<double, 4> rcond{};  // SB10AD's RCOND: Tu, Ty, X-Riccati, Y-Riccati (last good step)

  bool ok() const { return status == HinfStatus::kOk; }
};

// p: the generalised plant; its last n_meas outputs are y and its last n_ctrl inputs are u.
// gamma_max > 0: the starting (largest) gamma; tol > 0: the absolute tolerance on gamma (GTOL).
HinfResult synthesise(const StateSpace& p, int n_meas, int n_ctrl, double gamma_max, double tol);

// The central (suboptimal) controller at `gamma` itself (SB10AD JOB = 4): no iteration. Where the
// existence conditions hold at gamma, it achieves ||F_l(P, K)||_inf < gamma; pick gamma a little
// above what synthesise's bisection found, whose own controller may not meet its gamma (above).
HinfResult synthesise_at(const StateSpace& p, int n_meas, int n_ctrl, double gamma);

}  // namespace chaser::control
