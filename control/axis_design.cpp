#include "control/axis_design.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "control/frequency_response.hpp"

namespace chaser::control {
namespace {

using Eigen::MatrixXd;

void check_spec(const AxisDesignSpec& s) {
  std::vector<std::string> problems;
  const auto need = [&](bool ok, const std::string& what) {
    if (!ok) problems.push_back(what);
  };
  need(std::isfinite(s.authority) && s.authority > 0.0, fmt::format("authority must be > 0 (got {})", s.authority));
  need(std::isfinite(s.delay_s) && s.delay_s >= 0.0, fmt::format("delay_s must be >= 0 (got {})", s.delay_s));
  need(std::isfinite(s.bandwidth_radps) && s.bandwidth_radps > 0.0,
       fmt::format("bandwidth_radps must be > 0 (got {})", s.bandwidth_radps));
  need(std::isfinite(s.peak_sensitivity) && s.peak_sensitivity > 1.0,
       fmt::format("peak_sensitivity must be > 1 (got {})", s.peak_sensitivity));
  need(s.low_frequency_gain > 0.0 && s.low_frequency_gain < 1.0,
       fmt::format("low_frequency_gain must be in (0, 1) (got {})", s.low_frequency_gain));
  need(std::isfinite(s.error_scale) && s.error_scale > 0.0,
       fmt::format("error_scale must be > 0 (got {})", s.error_scale));
  need(s.input_disturbance >= 0.0 && s.input_disturbance <= 10.0,
       fmt::format("input_disturbance must be in [0, 10] (got {})", s.input_disturbance));
  need(s.pole_shift_fraction > 0.0 && s.pole_shift_fraction <= 0.1,
       fmt::format("pole_shift_fraction must be in (0, 0.1] (got {})", s.pole_shift_fraction));
  if (problems.empty()) return;
  std::string text = fmt::format("design_axis '{}':", s.name);
  for (const std::string& p : problems) text += "\n  " + p;
  throw std::invalid_argument(text);
}

// Coarse then fine gamma bisection, then the central controller at kAxisGammaBackoff times the
// threshold found (the header); `threshold` gets the fine bisection's gamma.
HinfResult synthesise_three_pass(const GeneralisedPlant& gp, double& threshold) {
  const HinfResult coarse = synthesise(gp.p, gp.n_meas, gp.n_ctrl, kAxisGammaMax, kAxisGammaMax * 1e-4);
  if (!coarse.ok()) return coarse;
  const HinfResult fine =
      synthesise(gp.p, gp.n_meas, gp.n_ctrl, 2.0 * coarse.gamma, kAxisGammaRelTol * coarse.gamma);
  if (!fine.ok()) return fine;
  threshold = fine.gamma;
  return synthesise_at(gp.p, gp.n_meas, gp.n_ctrl, kAxisGammaBackoff * fine.gamma);
}

}  // namespace

double margin_band_top_radps(double bandwidth_radps, double delay_s) {
  return delay_s > 0.0 ? std::max(1e3 * bandwidth_radps, 20.0 / delay_s) : 1e3 * bandwidth_radps;
}

StateSpace pade_delay(double delay_s) {
  if (delay_s == 0.0) return static_gain(MatrixXd::Ones(1, 1));
  // (1 - s tau/2) / (1 + s tau/2) = -1 + (4 / tau) / (s + 2 / tau)
  return StateSpace{MatrixXd::Constant(1, 1, -2.0 / delay_s), MatrixXd::Ones(1, 1),
                    MatrixXd::Constant(1, 1, 4.0 / delay_s), MatrixXd::Constant(1, 1, -1.0)};
}

StateSpace delayed_double_integrator(double delay_s, double pole_shift_radps) {
  const StateSpace pade = pade_delay(delay_s);
  const Eigen::Index k = pade.states();  // 0 or 1
  // [x_pade; x_rate; x_pos]: x_rate' = -eps x_rate + v, x_pos' = -eps x_pos + x_rate, v = Pade(u).
  StateSpace g;
  g.a = MatrixXd::Zero(k + 2, k + 2);
  g.b = MatrixXd::Zero(k + 2, 1);
  g.c = MatrixXd::Zero(1, k + 2);
  g.d = MatrixXd::Zero(1, 1);
  if (k == 1) {
    g.a(0, 0) = pade.a(0, 0);
    g.b(0, 0) = pade.b(0, 0);
    g.a(1, 0) = pade.c(0, 0);
  }
  g.a(k, k) = -pole_shift_radps;
  g.b(k, 0) = pade.d(0, 0);
  g.a(k + 1, k) = 1.0;
  g.a(k + 1, k + 1) = -pole_shift_radps;
  g.c(0, k + 1) = 1.0;
  return g;
}

AxisDesign design_axis(const AxisDesignSpec& spec) {
  check_spec(spec);
  AxisDesign d;
  d.spec = spec;
  d.design_plant = delayed_double_integrator(spec.delay_s, spec.pole_shift_fraction * spec.bandwidth_radps);
  d.plant = delayed_double_integrator(spec.delay_s, 0.0);
  d.weights.w_s = performance_weight(spec.peak_sensitivity, spec.bandwidth_radps, spec.low_frequency_gain);
  d.weights.w_ks = static_gain(MatrixXd::Constant(1, 1, spec.error_scale / spec.authority));
  if (spec.input_disturbance > 0.0)
    d.weights.w_d = static_gain(MatrixXd::Constant(1, 1, spec.input_disturbance * spec.authority / spec.error_scale));
  const GeneralisedPlant design = mixed_sensitivity_plant(d.design_plant, d.weights);
  d.synthesis = synthesise_three_pass(design, d.gamma_threshold);
  if (!d.synthesis.ok()) return d;

  const StateSpace closed_design = lower_lft(design.p, design.n_meas, design.n_ctrl, d.synthesis.controller);
  const HinfNormEstimate norm = hinf_norm_estimate(closed_design);
  d.closed_loop_norm = norm.norm;
  d.closed_loop_norm_radps = norm.omega_peak_radps;
  d.max_real_pole_design = max_real_pole(closed_design);

  const GeneralisedPlant truth = mixed_sensitivity_plant(d.plant, d.weights);
  d.max_real_pole = max_real_pole(lower_lft(truth.p, truth.n_meas, truth.n_ctrl, d.synthesis.controller));

  // Margins on the undelayed double integrator with the exact delay e^{-s tau}.
  const SisoLoop loop{delayed_double_integrator(0.0, 0.0), d.synthesis.controller, spec.delay_s};
  d.margins = loop_margins(loop, 1e-4 * spec.bandwidth_radps, margin_band_top_radps(spec.bandwidth_radps, spec.delay_s));
  return d;
}

}  // namespace chaser::control
