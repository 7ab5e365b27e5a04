// chaser control design: the scenario's loops. Where it flies the LQR loops (control.law lqr), their
// gains and closed-loop poles (control/discrete_poles.hpp). Where it has an H-infinity design
// (control.hinf), the six loops after the computed-torque precompensation
// (control/six_axis_design.hpp), each checked independently of SLICOT: the closed loop's norm by
// sweep, its poles on the true plant, the classical margins with the exact delay. Prints tables;
// --out writes every figure, the controllers and the frequency responses as JSON for
// python/plot_control.py.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <iostream>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/output_file.hpp"
#include "cli/scenario_input.hpp"
#include "control/frequency_response.hpp"
#include "control/composite_design.hpp"
#include "control/loop_mu.hpp"
#include "control/robustness.hpp"
#include "control/six_axis_design.hpp"
#include "control/discrete_poles.hpp"
#include "core/linear_models.hpp"
#include "flight/attitude_control.hpp"
#include "flight/position_control.hpp"

namespace chaser::cli {

namespace {

constexpr int kResponsePointsPerDecade = 50;

double db(double gain) { return 20.0 * std::log10(gain); }

std::string unit_of(std::size_t axis, const char* translation, const char* rotation) {
  return axis < 3 ? translation : rotation;
}

nlohmann::json matrix_json(const Eigen::MatrixXd& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index r = 0; r < m.rows(); ++r) {
    std::vector<double> row(static_cast<std::size_t>(m.cols()));
    for (Eigen::Index c = 0; c < m.cols(); ++c) row[static_cast<std::size_t>(c)] = m(r, c);
    rows.push_back(row);
  }
  return rows;
}

// JSON cannot hold inf or NaN: an unbounded margin is null.
nlohmann::json finite_or_null(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

// |S|, |T|, |K S|, |L|, arg L and the bounds gamma / |W_S|, gamma / |W_KS| on a log grid, for the plots.
nlohmann::json response_json(const control::AxisDesign& d) {
  const double w_lo = 1e-4 * d.spec.bandwidth_radps;
  const double w_hi = control::margin_band_top_radps(d.spec.bandwidth_radps, d.spec.delay_s);
  const int count = static_cast<int>(std::ceil(std::log10(w_hi / w_lo) * kResponsePointsPerDecade)) + 1;
  const control::SisoLoop loop{control::delayed_double_integrator(0.0, 0.0), d.synthesis.controller, d.spec.delay_s};
  const double gamma = d.synthesis.gamma;
  const double w_ks = d.weights.w_ks->d(0, 0);
  nlohmann::json r;
  for (const double w : control::log_grid(w_lo, w_hi, count)) {
    const std::complex<double> l = control::loop_response(loop, w);
    const std::complex<double> k = control::frequency_response(d.synthesis.controller, w)(0, 0);
    const std::complex<double> s = 1.0 / (1.0 + l);
    r["omega_radps"].push_back(w);
    r["L_mag"].push_back(std::abs(l));
    r["L_phase_deg"].push_back(std::arg(l) * 180.0 / std::numbers::pi);
    r["S_mag"].push_back(std::abs(s));
    r["T_mag"].push_back(std::abs(l * s));
    r["KS_mag"].push_back(std::abs(k * s));
    r["S_bound"].push_back(gamma / std::abs(control::frequency_response(*d.weights.w_s, w)(0, 0)));
    r["KS_bound"].push_back(gamma / w_ks);
  }
  return r;
}

// A loop's units: its authority's and its error scale's.
struct LoopUnits {
  std::string authority, error;
};
LoopUnits six_axis_units(std::size_t axis) { return {unit_of(axis, "m/s^2", "rad/s^2"), unit_of(axis, "m", "rad")}; }
const LoopUnits kCompositeUnits{"N m", "N m s^2"};  // the angular impulse's loops: Phi'' = T

nlohmann::json axis_json(const LoopUnits& units, const control::AxisDesign& d) {
  const control::LoopMargins& m = d.margins;
  nlohmann::json j{
      {"axis", d.spec.name},
      {"authority", d.spec.authority},
      {"authority_unit", units.authority},
      {"weights",
       {{"bandwidth_radps", d.spec.bandwidth_radps},
        {"peak_sensitivity", d.spec.peak_sensitivity},
        {"low_frequency_gain", d.spec.low_frequency_gain},
        {"error_scale", d.spec.error_scale},
        {"error_scale_unit", units.error},
        {"w_ks", d.weights.w_ks->d(0, 0)},
        {"design_pole_shift_radps", d.spec.pole_shift_fraction * d.spec.bandwidth_radps}}},
      {"status", control::to_string(d.synthesis.status)},
      {"message", d.synthesis.message},
  };
  if (!d.synthesis.ok()) return j;
  j["gamma"] = d.synthesis.gamma;
  j["closed_loop_norm"] = d.closed_loop_norm;
  j["closed_loop_norm_radps"] = finite_or_null(d.closed_loop_norm_radps);
  j["max_real_pole_design"] = d.max_real_pole_design;
  j["max_real_pole"] = d.max_real_pole;
  j["stable"] = d.max_real_pole < 0.0;
  j["margins"] = {{"gain_margin_up", finite_or_null(m.gain_margin_up)},
                  {"gain_margin_up_db", finite_or_null(db(m.gain_margin_up))},
                  {"phase_crossover_radps", finite_or_null(m.phase_crossover_radps)},
                  {"gain_margin_down", m.gain_margin_down},
                  {"phase_margin_deg", finite_or_null(m.phase_margin_deg)},
                  {"gain_crossover_radps", finite_or_null(m.gain_crossover_radps)},
                  {"delay_margin_s", finite_or_null(m.delay_margin_s)},
                  {"sensitivity_peak", m.sensitivity_peak},
                  {"sensitivity_peak_radps", m.sensitivity_peak_radps},
                  {"complementary_peak", m.complementary_peak},
                  {"complementary_peak_radps", m.complementary_peak_radps},
                  {"bandwidth_radps", finite_or_null(m.bandwidth_radps)}};
  const control::StateSpace& k = d.synthesis.controller;
  j["controller"] = {{"a", matrix_json(k.a)}, {"b", matrix_json(k.b)}, {"c", matrix_json(k.c)}, {"d", matrix_json(k.d)}};
  j["frequency_response"] = response_json(d);
  return j;
}

nlohmann::json grid_point_json(const control::GridPoint& p, const control::AxisUncertainty& box) {
  nlohmann::json j{{"gain", p.gain}, {"delay_s", p.delay_s}, {"modes", nlohmann::json::object()}};
  for (std::size_t i = 0; i < box.modes.size(); ++i) j["modes"][box.modes[i].name] = p.mode_frequency_radps[i];
  return j;
}

nlohmann::json robustness_json(const control::AxisUncertainty& box, const control::RobustnessResult& r) {
  nlohmann::json modes = nlohmann::json::array();
  for (const control::UncertainMode& m : box.modes)
    modes.push_back({{"name", m.name},
                     {"frequency_radps", {m.frequency_lo_radps, m.frequency_hi_radps}},
                     {"modal_fraction", m.modal_fraction},
                     {"damping", m.damping}});
  return {{"box",
           {{"gain", {box.gain_lo, box.gain_hi}}, {"delay_s", {box.delay_lo_s, box.delay_hi_s}}, {"modes", modes},
            {"points_per_range", box.points_per_range}}},
          {"points", r.points},
          {"unstable", r.unstable},
          {"robustly_stable", r.robustly_stable()},
          {"worst_max_real_pole", r.worst_max_real_pole},
          {"worst_pole_point", grid_point_json(r.worst_pole_point, box)},
          {"min_phase_margin_deg", finite_or_null(r.min_phase_margin_deg)},
          {"min_phase_margin_point", grid_point_json(r.min_phase_margin_point, box)},
          {"min_gain_margin_up", finite_or_null(r.min_gain_margin_up)},
          {"max_gain_margin_down", r.max_gain_margin_down}};
}

// AB13MD's bounds on the loop's gain x delay LFT (control/loop_mu.hpp), with their curves.
nlohmann::json mu_json(const control::LoopMu& r) {
  return {{"lft",
           {{"gain_nominal", r.lft.gain_nominal},
            {"gain_radius", r.lft.gain_radius},
            {"delay_nominal_s", r.lft.delay_nominal_s},
            {"delay_radius_s", r.lft.delay_radius_s}}},
          {"blocks", "delta_tau complex (delay, covering disk 2 sin(w Delta/2)); delta_k complex or real (gain)"},
          {"note", "AB13MD upper bound. complex: both blocks complex, conservative for the real gain; mixed: gain "
                   "real. The modes are left to the grid check."},
          {"nominal_stable", r.nominal_stable},
          {"nominal_max_real_pole", r.nominal_max_real_pole},
          {"status", control::to_string(r.status)},
          {"message", r.message},
          {"peak_complex", r.peak_complex},
          {"peak_complex_radps", r.peak_complex_radps},
          {"margin_complex", finite_or_null(r.margin_complex())},
          {"peak_mixed", r.peak_mixed},
          {"peak_mixed_radps", r.peak_mixed_radps},
          {"margin_mixed", finite_or_null(r.margin_mixed())},
          {"omega_radps", r.omega_radps},
          {"mu_complex", r.mu_complex},
          {"mu_mixed", r.mu_mixed}};
}

std::string factor_text(double x) {
  if (!std::isfinite(x)) return "inf";
  return x < 1e3 ? fmt::format("{:.2f}", x) : fmt::format("{:.3g}", x);
}

void print_mu_table(const control::SixAxisDesign& design) {
  std::cout << "\nStructured singular value (SLICOT AB13MD upper bound) of each loop's gain x delay LFT; the modes are "
               "left to the grid.\n"
               "complex: both blocks complex, conservative for the real gain; mixed: the gain real. margin = 1 / peak, "
               "the factor the box may grow by.\n";
  std::cout << fmt::format("{:<4} {:>17} {:>17} {:>8} {:>9} {:>9} {:>8} {:>9} {:>9} {:>8}\n", "loop", "gain k0 +- r_k",
                           "delay s t0 +- D", "nominal", "mu cplx", "at rad/s", "margin", "mu mixed", "at rad/s",
                           "margin");
  for (std::size_t k = 0; k < design.axes.size(); ++k) {
    const control::LoopMu& r = design.mu[k];
    std::cout << fmt::format("{:<4} {:>7.4f} +- {:<6.4f} {:>7.4f} +- {:<6.4f} {:>8} {:>9.4f} {:>9.3g} {:>8} {:>9.4f} "
                             "{:>9.3g} {:>8}{}\n",
                             design.axes[k].spec.name, r.lft.gain_nominal, r.lft.gain_radius, r.lft.delay_nominal_s,
                             r.lft.delay_radius_s, r.nominal_stable ? "stable" : "UNSTABLE", r.peak_complex,
                             r.peak_complex_radps, factor_text(r.margin_complex()), r.peak_mixed, r.peak_mixed_radps,
                             factor_text(r.margin_mixed()),
                             r.status == control::MuStatus::kOk ? "" : "  " + r.message);
  }
}

std::string margin_text(double gain) { return std::isfinite(gain) ? fmt::format("{:.1f} dB", db(gain)) : "inf"; }

std::string axis_row(const LoopUnits& units, const control::AxisDesign& d) {
  const std::string head = fmt::format("{:<4} {:>9.4g} {:<7} {:>7.3g} {:>4.2g} {:>7.1e} {:>6.3g} {:<3}", d.spec.name,
                                       d.spec.authority, units.authority, d.spec.bandwidth_radps,
                                       d.spec.peak_sensitivity, d.spec.low_frequency_gain, d.spec.error_scale,
                                       units.error);
  if (!d.synthesis.ok()) return head + "  " + control::to_string(d.synthesis.status) + ": " + d.synthesis.message;
  const control::LoopMargins& m = d.margins;
  return head + fmt::format(" {:>8.5f} {:>8.5f} {:>8.3g} {:>6.3f} {:>6.3f} {:>9} {:>9} {:>7.1f} {:>8.3g} {:>10.2e}",
                            d.synthesis.gamma, d.closed_loop_norm, m.bandwidth_radps, m.sensitivity_peak,
                            m.complementary_peak, margin_text(m.gain_margin_up),
                            m.gain_margin_down > 0.0 ? margin_text(m.gain_margin_down) : "-", m.phase_margin_deg,
                            m.delay_margin_s, d.max_real_pole);
}

struct LqrLoopText {
  const char* name;
  const char* weights_format;  // fmt pattern of the three weights
  const char* error_unit;
  const char* rate_unit;
};

std::string range_text(double lo, double hi, const char* format) {
  const std::string a = fmt::format(fmt::runtime(format), lo), b = fmt::format(fmt::runtime(format), hi);
  return a == b ? a : a + "-" + b;
}

// One flown LQR loop: its gain, and the poles of the discrete model it was designed on closed by it.
struct LqrLoop {
  Mat36 K;
  control::DiscreteLoopPoles closed;
  bool converged = false;
};

LqrLoop position_loop(const model::Scenario& s) {
  const flight::PositionControlParams p = flight::make_position_control(s);
  const DiscreteLinear6 m = discrete_hcw(p.mean_motion_radps, p.period_s);
  // The design's input is force: the model's acceleration input over the nominal mass.
  return {p.K, control::discrete_loop_poles(m.Ad, m.Bd / p.mass_kg, p.K, p.period_s), p.design_converged};
}

LqrLoop attitude_loop(const model::Scenario& s) {
  const flight::AttitudeControlParams p = flight::make_attitude_control(s);
  const DiscreteLinear6 m = discrete_attitude(p.inertia_kgm2, s.control_period_s);
  return {p.K, control::discrete_loop_poles(m.Ad, m.Bd, p.K, s.control_period_s), p.design_converged};
}

bool lqr_ok(const LqrLoop& loop) { return loop.converged && loop.closed.stable(); }

// One loop's row: its weights, the gain's diagonal on the error and on its rate, and the range of
// its poles' w_n, zeta and 1/(zeta w_n).
std::string lqr_row(const LqrLoopText& text, const std::array<double, 3>& weights, const LqrLoop& loop) {
  const Eigen::Vector3d k_error = loop.K.leftCols<3>().diagonal(), k_rate = loop.K.rightCols<3>().diagonal();
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double wn_lo = kInf, wn_hi = 0, zeta_lo = kInf, zeta_hi = 0, tau_lo = kInf, tau_hi = 0;
  for (const control::LoopPole& p : loop.closed.poles) {
    wn_lo = std::min(wn_lo, p.natural_radps), wn_hi = std::max(wn_hi, p.natural_radps);
    zeta_lo = std::min(zeta_lo, p.damping), zeta_hi = std::max(zeta_hi, p.damping);
    tau_lo = std::min(tau_lo, p.time_constant_s), tau_hi = std::max(tau_hi, p.time_constant_s);
  }
  return fmt::format("{:<9} {:<40} {:>15} {:<8} {:>15} {:<10} {:>13} {:>11} {:>15}  {}", text.name,
                     fmt::format(fmt::runtime(text.weights_format), weights[0], weights[1], weights[2]),
                     range_text(k_error.minCoeff(), k_error.maxCoeff(), "{:.4g}"), text.error_unit,
                     range_text(k_rate.minCoeff(), k_rate.maxCoeff(), "{:.4g}"), text.rate_unit,
                     range_text(wn_lo, wn_hi, "{:.4f}"), range_text(zeta_lo, zeta_hi, "{:.3f}"),
                     range_text(tau_lo, tau_hi, "{:.1f}"),
                     !loop.converged ? "RICCATI NOT CONVERGED" : (loop.closed.stable() ? "stable" : "UNSTABLE"));
}

nlohmann::json lqr_json(const std::array<double, 3>& weights, const LqrLoop& loop, double period_s) {
  nlohmann::json poles = nlohmann::json::array();
  for (const control::LoopPole& p : loop.closed.poles)
    poles.push_back({{"re", p.s.real()},
                     {"im", p.s.imag()},
                     {"natural_radps", p.natural_radps},
                     {"damping", p.damping},
                     {"time_constant_s", finite_or_null(p.time_constant_s)}});
  return {{"weights", weights},
          {"K", matrix_json(loop.K)},
          {"period_s", period_s},
          {"converged", loop.converged},
          {"stable", loop.closed.stable()},
          {"poles", poles}};
}

// The LQR loops the scenario flies: printed, and added to the report as "lqr". False where a
// design did not converge or a loop is unstable.
bool report_lqr_loops(const model::Scenario& s, nlohmann::json& report) {
  const model::ControlParams& c = s.control;
  const LqrLoop position = position_loop(s);
  const LqrLoop attitude = attitude_loop(s);
  const std::array<double, 3> w_position{c.position_q_pos, c.position_q_vel, c.position_r_force};
  const std::array<double, 3> w_attitude{c.attitude_q_angle, c.attitude_q_rate, c.attitude_r_torque};
  std::cout << fmt::format(
      "{}: the LQR loops flown (control.law lqr; docs/gnc.md): discrete LQR on the ZOH model, mass {:g} kg, inertia\n"
      "diag({:g}, {:g}, {:g}) kg m^2, T = {:g} s; closed-loop poles z read as s = ln z / T, w_n = |s|, zeta = -Re s / "
      "|s|.\n\n",
      s.name, s.chaser.mass_kg, s.chaser.inertia_kgm2(0, 0), s.chaser.inertia_kgm2(1, 1), s.chaser.inertia_kgm2(2, 2),
      s.control_period_s);
  std::cout << fmt::format("{:<9} {:<40} {:>15} {:<8} {:>15} {:<10} {:>13} {:>11} {:>15}\n", "loop", "weights",
                           "gain on error", "", "on rate", "", "w_n rad/s", "zeta", "1/(zeta w_n) s");
  std::cout << lqr_row({"position", "q_pos {:g}, q_vel {:g}, r_force {:g}", "N/m", "N s/m"}, w_position, position)
            << "\n";
  std::cout << lqr_row({"attitude", "q_angle {:g}, q_rate {:g}, r_torque {:g}", "N m/rad", "N m s/rad"}, w_attitude,
                       attitude)
            << "\n";
  report["lqr"] = {{"mass_kg", s.chaser.mass_kg},
                   {"inertia_kgm2", matrix_json(s.chaser.inertia_kgm2)},
                   {"position", lqr_json(w_position, position, s.control_period_s)},
                   {"attitude", lqr_json(w_attitude, attitude, s.control_period_s)}};
  return lqr_ok(position) && lqr_ok(attitude);
}

}  // namespace

int control_design_command(const ControlDesignArgs& args) {
  const auto loaded = load_or_report(args.scenario_path, args.overrides);
  if (!loaded) return kExitBadInput;
  const model::Scenario& s = *loaded->scenario;
  nlohmann::json report{{"scenario", s.name}};
  if (s.control.law == model::ControlLaw::kLqr) {
    if (!report_lqr_loops(s, report)) {
      std::cerr << "chaser control design: an LQR loop did not converge or is unstable (see its row): change its "
                   "weights in control\n";
      return kExitFailure;
    }
    if (!s.control.hinf) {
      if (!args.json_path.empty()) {
        if (!write_output_file(args.json_path, report.dump(1) + "\n")) return kExitFailure;
        std::cout << fmt::format("\nwrote {}\n", args.json_path);
      }
      return kExitOk;
    }
    std::cout << "\n";
  }
  control::SixAxisDesign design;
  try {
    design = control::design_six_axes(s);
  } catch (const std::invalid_argument& e) {
    std::cerr << fmt::format("chaser control design: {}: {}\n", args.scenario_path, e.what());
    return kExitBadInput;
  }
  std::cout << fmt::format(
      "{}: H-infinity S/KS design of the six loops after the computed-torque precompensation (SLICOT SB10AD;\n"
      "docs/control.md). Plant per axis e^(-s tau)/s^2 in commanded acceleration, tau = T/2 + delay_max/2 + "
      "rise/2 = {:.4g} s.\n"
      "gamma: SB10AD's; norm: ||F_l(P, K)||_inf by an independent sweep; margins on the true double integrator "
      "with the exact delay.\n\n",
      s.name, design.delay_s);
  std::cout << fmt::format("{:<4} {:>9} {:<7} {:>7} {:>4} {:>7} {:>6} {:<3} {:>8} {:>8} {:>8} {:>6} {:>6} {:>9} {:>9} "
                           "{:>7} {:>8} {:>10}\n",
                           "loop", "authority", "", "w_B", "M", "A", "scale", "", "gamma", "norm", "bw rad/s", "|S|pk",
                           "|T|pk", "GM up", "GM down", "PM deg", "DM s", "max Re(p)");
  report["delay_s"] = design.delay_s;
  report["axes"] = nlohmann::json::array();
  for (std::size_t k = 0; k < design.axes.size(); ++k) {
    std::cout << axis_row(six_axis_units(k), design.axes[k]) << "\n";
    report["axes"].push_back(axis_json(six_axis_units(k), design.axes[k]));
  }
  report["ok"] = design.ok();
  if (design.checked_robustness) {
    std::cout << "\nRobust stability over control.hinf.robustness (closed-loop poles at every grid point, Pade "
                 "delay; margins with the exact delay):\n";
    std::cout << fmt::format("{:<4} {:>15} {:>17} {:<28} {:>7} {:>8} {:>12} {:>9} {:>9}\n", "loop", "gain", "delay s",
                             "modes", "points", "unstable", "max Re(p)", "min PM", "min GM");
    for (std::size_t k = 0; k < design.axes.size(); ++k) {
      const control::AxisUncertainty& box = design.boxes[k];
      const control::RobustnessResult& r = design.robustness[k];
      std::string modes;
      for (const control::UncertainMode& m : box.modes)
        modes += fmt::format("{}{} {:.3g}-{:.3g}", modes.empty() ? "" : ", ", m.name, m.frequency_lo_radps,
                             m.frequency_hi_radps);
      std::cout << fmt::format("{:<4} {:>6.3f} - {:<6.3f} {:>7.4f} - {:<7.4f} {:<28} {:>7} {:>8} {:>12.3e} {:>9.1f} {:>9}\n",
                               design.axes[k].spec.name, box.gain_lo, box.gain_hi, box.delay_lo_s, box.delay_hi_s,
                               modes.empty() ? "-" : modes, r.points, r.unstable, r.worst_max_real_pole,
                               r.min_phase_margin_deg, margin_text(r.min_gain_margin_up));
      report["axes"][k]["robustness"] = robustness_json(box, r);
      report["axes"][k]["mu"] = mu_json(design.mu[k]);
    }
    print_mu_table(design);
    report["robust"] = design.robust();
  }
  // The stabilisation's loops (capture.stabilise; COMRADE 2018 sec. 6.1.4), whichever law the scenario
  // flies: designed as the flight software designs them for law hinf, and checked as the six are,
  // over the composite inertia's uncertainty and the valves' delays.
  bool stabilisation_robust = true;
  if (s.capture && s.capture->stabilise) {
    std::array<control::AxisDesignSpec, 3> specs;
    try {
      specs = control::composite_specs(s);
    } catch (const std::invalid_argument& e) {
      std::cerr << fmt::format("chaser control design: {}: capture.stabilise: {}\n", args.scenario_path, e.what());
      return kExitBadInput;
    }
    const double inertia = s.capture->stabilise->inertia_uncertainty;
    const control::AxisUncertainty box = control::composite_uncertainty(s, inertia);
    std::cout << fmt::format(
        "\nThe stabilisation's loops (capture.stabilise.hinf; control/composite_design.hpp): the composite's angular "
        "impulse per inertial axis,\nPhi'' = T in N m. Checked over a measurement gain {:.3f} - {:.3f} (the inertia "
        "{:g} % off, capture.stabilise.inertia_uncertainty,\ntimes the thrust's) and the delay {:.4f} - {:.4f} s: the "
        "grid's unstable points and least PM, and the mixed mu bound's margin.\n",
        box.gain_lo, box.gain_hi, 100.0 * inertia, box.delay_lo_s, box.delay_hi_s);
    report["stabilisation"] = nlohmann::json::array();
    for (const control::AxisDesignSpec& spec : specs) {
      const control::AxisDesign d = control::design_axis(spec);
      std::string row = axis_row(kCompositeUnits, d);
      nlohmann::json j = axis_json(kCompositeUnits, d);
      if (d.ok()) {
        const control::RobustnessResult grid = control::robust_stability_grid(d, box);
        const control::LoopMu mu = control::loop_mu(d, box);
        row += fmt::format("  grid {} of {} unstable, least PM {:.1f} deg; mu margin {}", grid.unstable, grid.points,
                           grid.min_phase_margin_deg, factor_text(mu.margin_mixed()));
        j["robustness"] = robustness_json(box, grid);
        j["mu"] = mu_json(mu);
        stabilisation_robust = stabilisation_robust && grid.robustly_stable() && mu.ok() && mu.margin_mixed() > 1.0;
      } else {
        stabilisation_robust = false;
      }
      std::cout << row << "\n";
      report["stabilisation"].push_back(j);
    }
    report["stabilisation_robust"] = stabilisation_robust;
  }
  if (!args.json_path.empty()) {
    if (!write_output_file(args.json_path, report.dump(1) + "\n")) return kExitFailure;
    std::cout << fmt::format("\nwrote {} (plots: /usr/bin/python3 python/plot_control.py {})\n", args.json_path,
                             args.json_path);
  }
  if (!design.ok()) {
    std::cerr << "chaser control design: a loop has no stabilising design (see its row): change its weights in "
                 "control.hinf\n";
    return kExitFailure;
  }
  if (!design.robust()) {
    std::cerr << "chaser control design: a loop loses stability inside control.hinf.robustness (see its row): "
                 "lower its bandwidth or raise its peak_sensitivity\n";
    return kExitFailure;
  }
  if (!stabilisation_robust) {
    std::cerr << "chaser control design: a stabilisation loop has no design, or loses stability inside the inertia's "
                 "uncertainty (see its row): change capture.stabilise.hinf\n";
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace chaser::cli
