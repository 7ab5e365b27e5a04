#include "flight/fdi/fdi_scheme.hpp"

#include <utility>

namespace chaser::flight::fdi {

std::vector<std::string> validate(const FdiSchemeParams& params) {
  std::vector<std::string> problems = validate(params.residual);
  for (std::string& p : validate(params.glr)) problems.push_back(std::move(p));
  for (std::string& p : validate(params.isolation)) problems.push_back(std::move(p));
  if (params.glr.variant == GlrVariant::kWhitened &&
      params.glr.residual_dim != params.residual.residual_dim)
    problems.push_back("glr.residual_dim: must equal the residual generator's n_r");
  if (params.glr.variant == GlrVariant::kScalar && params.residual.residual_dim != 1)
    problems.push_back("glr.variant: the scalar test (eq. 41) needs n_r = 1; use the whitened one");
  if (!(params.period_s > 0.0)) problems.push_back("period_s: must be > 0");
  return problems;
}

namespace {

// [s] the first alarm's time since the scheme started, -1 before it.
double alarm_time_s(const FdiSchemeParams& params, const FdiSchemeState& state) {
  return state.alarm ? static_cast<double>(state.alarm_period) * params.period_s : -1.0;
}

}  // namespace

void step_fdi_scheme(const FdiSchemeParams& params, FdiSchemeState& state, const Vec3& y, const Vec3& u_c,
                     const SchemeTon& ton, bool over_consumption, FdiSchemeOutput& out) {
  out.residual = step_residual(params.residual, state.residual, y, u_c);
  if (step_glr(params.glr, state.glr, out.residual, out.glr) && !state.alarm) {
    state.alarm = true;
    state.alarm_period = state.period;
  }
  if (params.isolate) {
    const IsolationOutput iso =
        step_isolation(params.isolation, state.isolation, out.residual, ton, state.alarm, over_consumption);
    if (state.confirmed < 0 && iso.confirmed >= 0) state.confirmed = iso.confirmed;
    out.candidate = iso.candidate;
  } else {
    out.candidate = -1;
  }
  out.alarm = state.alarm;
  out.confirmed = state.confirmed;
  out.alarm_time_s = alarm_time_s(params, state);
  ++state.period;
}

void pause_fdi_scheme(const FdiSchemeParams& params, FdiSchemeState& state, FdiSchemeOutput& out) {
  state.residual.started = false;
  out = FdiSchemeOutput{};
  out.alarm = state.alarm;
  out.confirmed = state.confirmed;
  out.alarm_time_s = alarm_time_s(params, state);
  ++state.period;
}

}  // namespace chaser::flight::fdi
