// chaser fdi design: the offline design of the delay-robust residual generator (Fonod 2015, IV.A)
// for the position or the attitude model of a scenario, with the figures a user judges it by; or,
// with --model rate, the body-rate model with the tanks' slosh a diagnosis designs from (COMRADE
// 2018, sec. 6.3; flight/fdi/design/rate_model.hpp).
#include <fstream>
#include <iostream>
#include <stdexcept>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/output_file.hpp"
#include "core/constants.hpp"
#include "cli/scenario_input.hpp"
#include "flight/fdir.hpp"
#include "flight/fdi/design/residual_design.hpp"
#include "flight/fdi/design/residual_design_json.hpp"
#include "model/fdi.hpp"
#include "model/thrusters.hpp"

namespace chaser::cli {

namespace {

void print_design(const flight::fdi::ResidualDesign& d) {
  const auto& f = d.figures;
  const auto& a = d.assignment;
  std::cout << fmt::format("{} model: T = {} s, delay in [{}, {}] s, Taylor order {}, n_r = {}\n", d.inputs.name,
                           d.inputs.period_s, d.inputs.delta_min_s, d.inputs.delta_max_s, d.inputs.taylor_order,
                           d.inputs.residual_dim);
  std::cout << fmt::format("  unknown-input matrix E_d: {} columns; eq. 39 discards {:.1f} % of it (Frobenius)\n",
                           d.E_d.cols(), 100.0 * d.low_rank_error / d.E_d.norm());
  std::string eigenvalues;
  for (const auto& lambda : f.achieved_eigenvalues)
    eigenvalues += fmt::format(" {:.4f}{}", lambda.real(),
                               std::abs(lambda.imag()) > 1e-12 ? fmt::format("{:+.4f}i", lambda.imag()) : "");
  std::cout << "  achieved eigenvalues:" << eigenvalues << "\n";
  std::string misses;
  for (const double miss : a.relative_miss) misses += fmt::format(" {:.4f}", miss);
  std::cout << fmt::format("  assignability error of the assigned eigenvectors:{}; cond(P) = {:.2f}\n", misses,
                           a.p_condition);
  std::cout << fmt::format("  worst gain unknown input -> residual: {:.3e} (after decoupling of E_d*: {:.3e})\n",
                           f.unknown_input_gain_max, f.designed_input_gain_max);
  std::cout << fmt::format("  worst gain command-through-delay -> residual: {:.3e} [{}]\n", f.delay_gain_max,
                           d.inputs.residual_unit);
  std::cout << "  DC gain fault -> residual per thruster [" << d.inputs.residual_unit << " per unit on-time]:\n   ";
  for (int i = 0; i < f.fault_gain_dc.size(); ++i) std::cout << fmt::format(" T{}={:.3e}", i + 1, f.fault_gain_dc[i]);
  std::cout << "\n";
}

void print_rate_model(const flight::fdi::RateModel& m) {
  std::cout << fmt::format("rate model: thruster on-times ({}) to the gyro's rates, Euler's equation with {} tanks' "
                           "first slosh modes, linearised at rest\n",
                           m.thrusters, m.modes.size() / 2);
  std::cout << fmt::format("  order {} (3 rates, {} slosh states); reduced to {}: the modes the thrusters can "
                           "drive and the gyro can see\n",
                           m.A.rows(), m.A.rows() - 3, m.A_reduced.rows());
  for (std::size_t i = 0; i < m.modes.size(); ++i) {
    const flight::fdi::SloshModeFigures& f = m.modes[i];
    std::cout << fmt::format("  slosh mode {}: {:.4f} rad/s (period {:.1f} s), damping {:.4f}; controllability "
                             "{:.2e}, observability {:.2e}: {}\n",
                             i + 1, f.frequency_radps, 2.0 * kPi / f.frequency_radps, f.damping_ratio,
                             f.controllability, f.observability, f.kept ? "kept" : "dropped");
  }
}

void print_uio_bank(const flight::fdi::UioBank& b) {
  std::cout << fmt::format("observer bank: {} discrete H-infinity unknown-input observers on the reduced rate model "
                           "(order {}), each blind to one thruster\n",
                           b.observers.size(), b.Ad.rows());
  std::cout << "  observer  gamma_min  gamma      sweep      rho(N)   noise rms  | its thruster: also blind     "
               "least moved  SNR\n";
  for (const flight::fdi::UioObserver& o : b.observers) {
    const auto j = static_cast<std::size_t>(o.thruster);
    std::string blind;
    for (const int other : b.blind[j]) blind += fmt::format("{}T{}", blind.empty() ? "" : ",", other + 1);
    std::cout << fmt::format("  T{:<7d} {:.3e}  {:.3e}  {:.3e}  {:.5f}  {:.2e}   | {:<22} T{:<10d} {:.0f}\n",
                             o.thruster + 1, o.gamma_min, o.gamma, o.gamma_sweep, o.spectral_radius,
                             o.residual_noise_rms, blind.empty() ? "none" : blind, b.closest[j] + 1,
                             b.isolation_snr[j]);
  }
  std::cout << "  gamma: rate error [rad/s] per unit normalised disturbance and gyro noise (sweep: the achieved); "
               "also blind: the other observers\n  that do not see the thruster's fault at steady state (the "
               "smallest residual names that group); least moved: the\n  other observer its fault moves least, "
               "SNR its steady residual per unit on-time over its noise rms\n";
}

// Makes the design (its std::invalid_argument is the command's exit 2), prints it and, with --out,
// writes its JSON.
template <class Make, class Print>
int design_and_report(const FdiDesignArgs& args, const Make& make, const Print& print) {
  decltype(make()) design;
  try {
    design = make();
  } catch (const std::invalid_argument& e) {
    std::cerr << "chaser fdi design: " << e.what() << "\n";
    return kExitBadInput;
  }
  print(design);
  if (!args.out_path.empty()) {
    if (!write_output_file(args.out_path, flight::fdi::to_json(design).dump(2) + "\n")) return kExitFailure;
    std::cout << fmt::format("  wrote {}\n", args.out_path);
  }
  return kExitOk;
}

}  // namespace

int fdi_design_command(const FdiDesignArgs& args) {
  const auto loaded = load_or_report(args.scenario_path, args.overrides);
  if (!loaded) return kExitBadInput;
  const model::Scenario& scenario = *loaded->scenario;
  if (args.model == "rate")
    return design_and_report(args, [&] { return flight::fdi::rate_model(scenario); }, print_rate_model);
  if (args.model == "uio-bank")
    return design_and_report(args, [&] { return flight::fdi::design_uio_bank(scenario); }, print_uio_bank);
  // Fonod 2015's residual generators have a fault column per thruster of MSR's branch of eight; on
  // another set a design of "the first eight" would describe no scheme that flies.
  const int active = model::thruster_count(model::initial_active_set(scenario.thrusters));
  if (active != model::kFdiSchemeThrusters) {
    std::cerr << fmt::format("chaser fdi design: Fonod 2015's residual generators watch exactly {} active "
                             "thrusters; {} starts with {} (thrusters.list, thrusters.standby_groups). Chaser's "
                             "deficit scheme watches any set and needs no offline design (docs/fdi.md, \"Any "
                             "thruster set\")\n",
                             model::kFdiSchemeThrusters, args.scenario_path, active);
    return kExitBadInput;
  }
  const flight::fdi::DesignInputs inputs = flight::scheme_design_inputs(
      scenario, args.model == "position" ? flight::FdiModel::kPosition : flight::FdiModel::kAttitude);
  return design_and_report(args, [&] { return flight::fdi::design_residual_generator(inputs); }, print_design);
}

}  // namespace chaser::cli
