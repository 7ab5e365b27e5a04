#include "flight/supervision.hpp"

#include <vector>

#include "flight/fdi/design/uio_bank.hpp"

namespace chaser::flight {

std::optional<fdi::SupervisorParams> make_flight_supervisor(const model::Scenario& s) {
  const model::SupervisorParams& v = s.fdi.supervisor;
  if (!v.enabled) return std::nullopt;
  fdi::UioBankParams design = fdi::uio_bank_params(s);
  design.figures = false;
  design.decoupled = false;  // the estimators share the nominal observer
  // The rate model's columns are the starting active set's thrusters, in thruster order (as the bank's).
  const model::ThrusterList active = model::thruster_list(model::initial_configuration(s.thrusters).active);
  std::vector<int> column_thruster, monitored;
  for (int k = 0; k < active.count; ++k) column_thruster.push_back(active.index[static_cast<std::size_t>(k)]);
  for (int t = 0; t < model::kMaxThrusters; ++t)
    if (v.thrusters >> t & 1U) monitored.push_back(t);
  return fdi::make_supervisor(fdi::design_uio_bank(fdi::rate_model(s), design), column_thruster, monitored,
                              s.chaser.inertia_kgm2,
                              {.period_s = s.control_period_s,
                               .forgetting_s = v.forgetting_s,
                               .bias_s = v.bias_s,
                               .settle_s = v.settle_s,
                               .dwell_s = v.dwell_s,
                               .hysteresis = v.hysteresis,
                               .floor_radps = v.floor_radps});
}

void fly_supervisor_mode(const fdi::SupervisorParams& supervisor, int mode, const ThrusterManagementParams& management,
                         ThrusterManagementState& state, model::ThrusterConfiguration& thrusters) {
  const fdi::SupervisorMode& m = supervisor.modes[static_cast<std::size_t>(mode)];
  const model::ThrusterMask start = model::initial_configuration(management.thrusters).active;
  thrusters.active = m.thruster == model::kNoThruster ? start : start & ~model::thruster_bit(m.thruster);
  set_active_thrusters(management, state, thrusters.active);
  set_uncommanded_thrust(management, state, m.thruster, m.on_fraction);
}

}  // namespace chaser::flight
