#include "flight/fdi/design/design_inputs.hpp"

#include <utility>

#include "flight/fdi/design/fdi_models.hpp"

namespace chaser::flight::fdi {

namespace {

DesignInputs from_model(std::string name, std::string unit, const LinearModel& model,
                        const Eigen::MatrixXd& fault_inputs, double period_s) {
  DesignInputs in;
  in.name = std::move(name);
  in.residual_unit = std::move(unit);
  in.A = model.A;
  in.B = model.B;
  in.C = model.C;
  in.fault_inputs = fault_inputs;
  in.E_f = model.B * fault_inputs;  // eqs. 11 and 17: the fault enters where the input does
  in.period_s = period_s;
  in.delta_max_s = period_s;
  return in;
}

}  // namespace

DesignInputs position_design_inputs(const model::Scenario& scenario, const SchemeConfig& M) {
  const LinearModel model =
      hcw_position_model(scenario.orbit.mean_motion_radps(), scenario.chaser.mass_kg);
  return from_model("position", "m", model, M.topRows(3), scenario.control_period_s);
}

DesignInputs attitude_design_inputs(const model::Scenario& scenario, const SchemeConfig& M,
                                    const Vec3& omega_ref_body_radps) {
  const LinearModel model = linear_attitude_model(scenario.chaser.inertia_kgm2, omega_ref_body_radps);
  return from_model("attitude", "rad", model, M.bottomRows(3), scenario.control_period_s);
}

}  // namespace chaser::flight::fdi
