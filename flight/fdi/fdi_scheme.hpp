#pragma once
// One on-board FDI scheme of Fonod 2015 (IV, Fig. 5): residual generator (eq. 30), GLR decision
// (eqs. 40-41) and isolation (eqs. 42-45), run once per control period for one model (position
// or attitude) and the watched thrusters (flight/fdi/watched_set.hpp).
//
// Latching: the alarm latches at the first period with S > J_th (the fault is persistent,
// II.D); from that period on the isolation criterion is evaluated every period and its candidate
// reported; the confirmed thruster latches at the first period eq. 45 holds and is never revised.
// The residual generator and the GLR keep running after the alarm (their outputs stay observable).
#include <cstdint>
#include <string>
#include <vector>

#include "flight/fdi/glr.hpp"
#include "flight/fdi/isolation.hpp"
#include "flight/fdi/residual_generator.hpp"
#include "flight/fdi/watched_set.hpp"

namespace chaser::flight::fdi {

struct FdiSchemeParams {
  ResidualGeneratorParams residual;
  GlrParams glr;
  IsolationParams isolation;
  bool isolate = true;    // false: the scheme only detects; the FDIR supervisor names the thruster
  double period_s = 0.1;  // [s] T, for the alarm time
};

struct FdiSchemeState {
  ResidualGeneratorState residual;
  GlrState glr;
  IsolationState isolation;
  std::int64_t period = 0;         // periods since the scheme started (the next one's index)
  bool alarm = false;              // latched
  std::int64_t alarm_period = -1;  // period of the first alarm, -1 before
  int confirmed = -1;              // latched confirmed thruster: its lane in the watched set
};

struct FdiSchemeOutput {
  Vec3 residual = Vec3::Zero();  // r(k) [m or rad], entries >= n_r zero
  GlrStatistic glr;              // S^{N_d}(k) [-]: glr.value()
  bool alarm = false;            // latched H_1 decision (eq. 40)
  int candidate = -1;            // sigma^N(k) (eq. 42), -1 before the alarm or with no candidate
  int confirmed = -1;            // latched confirmed thruster (eq. 45), -1 if none
  double alarm_time_s = -1.0;    // [s] time of the first alarm since the scheme started, -1 before
};

// Every problem with the parameters (empty when valid), with consistency between the parts.
std::vector<std::string> validate(const FdiSchemeParams& params);

// One period. y: measurement [m or rad]; u_c: model input [N in LVLH or N m] (residual_generator.hpp);
// ton: commanded scaled on-times of the watched lanes this period; over_consumption: the event
// resolution's flag (event_resolution.hpp), read by the paper's isolation criterion.
// The result is written into `out` (every field): the FDIR supervisor passes its own output, which
// saves copying a returned struct through the stack every period (a store-forwarding stall).
void step_fdi_scheme(const FdiSchemeParams& params, FdiSchemeState& state, const Vec3& y, const Vec3& u_c,
                     const SchemeTon& ton, bool over_consumption, FdiSchemeOutput& out);
// A period without its measurement (a LIDAR gap): the scheme pauses. Its observer is set again from
// the next measurement (its estimate has drifted on no data), its GLR window and latches are kept,
// the period count runs on (alarm times stay run times). `out`: the latches, no residual.
void pause_fdi_scheme(const FdiSchemeParams& params, FdiSchemeState& state, FdiSchemeOutput& out);

inline FdiSchemeOutput step_fdi_scheme(const FdiSchemeParams& params, FdiSchemeState& state, const Vec3& y,
                                       const Vec3& u_c, const SchemeTon& ton, bool over_consumption) {
  FdiSchemeOutput out;
  step_fdi_scheme(params, state, y, u_c, ton, over_consumption, out);
  return out;
}

}  // namespace chaser::flight::fdi
