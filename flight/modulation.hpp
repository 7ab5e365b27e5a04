#pragma once
// Thruster modulation unit, TMU (Fonod 2015, section II.C): integrates the commanded wrench impulse
// that is too small to fire and releases it as one pulse when it reaches a momentum threshold.
//
//   release:  a += W_d T;  if |a_j| >= a_th_j for any axis j: W~ = a / T (all six axes), else 0
//   account:  a -= W_realised T        (what the allocator actually commanded)
//
// So sum(W_realised T) = sum(W_d T) - a at every period: no impulse is lost or invented, only
// delayed (a first-order delta-sigma modulator). The accumulator is clamped to +-a_max per axis
// (anti-windup): when the thrusters saturate, the unrealised impulse would otherwise pile up while
// the controller itself keeps asking for the same correction, and the debt would be paid later as an
// overshoot. a_max = max(windup_periods * authority_j * T, 2 a_th_j), with authority_j the larger
// one-sided sum of row j of the configuration matrix over both branches: a few periods of full
// thrust, so ordinary pulses never touch the clamp. Wrenches are [F_body; C_body] in N and N m.
#include "core/types.hpp"
#include "model/scenario.hpp"

namespace chaser::flight {

struct TmuParams {
  Vec6 threshold = Vec6::Constant(0.1);  // [N s, N m s] release threshold a_th per axis
  Vec6 limit = Vec6::Constant(10.0);     // [N s, N m s] accumulator clamp a_max per axis
  double period_s = 0.1;                 // [s] T
};

TmuParams make_tmu_params(const model::Scenario& scenario);

struct TmuState {
  Vec6 accumulated = Vec6::Zero();  // [N s, N m s] impulse demanded but not yet realised
};

// Wrench [F_body; C_body] to hand to the allocator this period (zero while below threshold).
Vec6 tmu_release(const TmuParams& params, TmuState& state, const Vec6& demand_wrench);

// Remove what the allocator commanded this period (may be less than released when saturated).
void tmu_account(const TmuParams& params, TmuState& state, const Vec6& realised_wrench);

}  // namespace chaser::flight
