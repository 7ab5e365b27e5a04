#include "flight/hinf_control.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "control/six_axis_design.hpp"
#include "control/tustin.hpp"
#include "core/linear_models.hpp"

namespace chaser::flight {

DiscreteLoop discrete_loop(const control::AxisDesign& design, double period_s) {
  const control::StateSpace discrete = control::discretise_tustin(design.synthesis.controller, period_s);
  const auto n = static_cast<int>(discrete.states());
  if (n > kMaxLoopStates || discrete.inputs() != 1 || discrete.outputs() != 1)
    throw std::runtime_error(fmt::format("control.law: hinf: the {} loop's controller has {} states, {} inputs and {} "
                                         "outputs (at most {} states, one input and one output fly)",
                                         design.spec.name, n, discrete.inputs(), discrete.outputs(), kMaxLoopStates));
  DiscreteLoop loop;
  loop.states = n;
  loop.a.topLeftCorner(n, n) = discrete.a;
  loop.b.head(n) = discrete.b.col(0);
  loop.c.head(n) = discrete.c.row(0);
  loop.d = discrete.d(0, 0);
  loop.authority = design.spec.authority;
  return loop;
}

HinfControlParams make_hinf_control(const model::Scenario& scenario) {
  HinfControlParams params;
  if (scenario.control.law != model::ControlLaw::kHinf) return params;
  const std::array<control::AxisDesignSpec, 6> specs = control::six_axis_specs(scenario);
  for (std::size_t k = 0; k < specs.size(); ++k) {
    const control::AxisDesign design = control::design_axis(specs[k]);
    if (!design.ok())
      throw std::runtime_error(fmt::format("control.law: hinf: the {} loop's design failed ({}); `chaser control design` "
                                           "shows the loops",
                                           specs[k].name, design.synthesis.message));
    params.loops[k] = discrete_loop(design, scenario.control_period_s);
  }
  params.enabled = true;
  return params;
}

double step_loop(const DiscreteLoop& loop, LoopState& x, double error) {
  const double u = loop.c.dot(x) + loop.d * error;
  x = loop.a * x + loop.b * error;
  return std::clamp(u, -loop.authority, loop.authority);
}

HinfDemand hinf_control(const HinfControlParams& params, HinfControlState& state, const PositionControlParams& position,
                        const AttitudeControlParams& attitude, const NavEstimate& nav, const GuidanceRef& ref,
                        const model::LvlhFrame& lvlh) {
  HinfDemand out;
  // The error in the reference's body axes (header): R = R_body_from_lvlh of the reference, w its
  // rate relative to LVLH in those axes, e~ = r - r_ref (LVLH) and e~_B = R e~, e~_B' = R e~' - w x e~_B.
  const Quat q_ref_body_from_lvlh = ref.q_inertial_from_body.conjugate() * lvlh.q_inertial_from_lvlh;
  const Vec3 omega_lvlh_in_body = q_ref_body_from_lvlh * lvlh.omega_lvlh_radps;
  const Vec3 w_B = ref.omega_body_radps - omega_lvlh_in_body;
  const Vec3 error_B = q_ref_body_from_lvlh * (nav.r_lvlh_m - ref.r_lvlh_m);
  const Vec3 error_rate_B = q_ref_body_from_lvlh * (nav.v_lvlh_mps - ref.v_lvlh_mps) - w_B.cross(error_B);
  Vec3 u_B;
  for (int i = 0; i < 3; ++i) u_B[i] = step_loop(params.loops[i], state.x[i], -error_B[i]);  // e = r_ref - y
  // e~_B'' = R e~'' - 2 w x e~_B' - w x (w x e~_B) (w' x e~_B left out: w' ~ 1e-5 rad/s^2 for the
  // tumbling cases, e~_B ~ 0.1 m): commanding e~'' = R^T (u_B + those terms) leaves e~_B'' = u_B,
  // the double integrator each loop was designed on.
  const Vec3 frame_terms_B = 2.0 * w_B.cross(error_rate_B) + w_B.cross(w_B.cross(error_B));
  const Vec3 hcw_on_error = hcw_acceleration(position.mean_motion_radps, nav.r_lvlh_m - ref.r_lvlh_m,
                                             nav.v_lvlh_mps - ref.v_lvlh_mps);
  out.force_lvlh_N = position_feedforward(position, ref) +
                     position.mass_kg * (q_ref_body_from_lvlh.conjugate() * (u_B + frame_terms_B) - hcw_on_error);

  const AttitudeError att = attitude_error(nav, ref);
  Vec3 u_rotation;
  for (int i = 0; i < 3; ++i) u_rotation[i] = step_loop(params.loops[3 + i], state.x[3 + i], -att.theta_rad[i]);
  out.torque_body_Nm = attitude_feedforward(attitude.inertia_kgm2, nav.omega_body_radps, att.omega_ref_body_radps) +
                       attitude.inertia_kgm2 * u_rotation;
  return out;
}

}  // namespace chaser::flight
