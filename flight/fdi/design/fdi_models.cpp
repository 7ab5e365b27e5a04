#include "flight/fdi/design/fdi_models.hpp"

#include "core/linear_models.hpp"

#include "core/rotation.hpp"

namespace chaser::flight::fdi {

using Eigen::MatrixXd;

LinearModel hcw_position_model(double mean_motion_radps, double mass_kg) {
  const double n = mean_motion_radps;
  LinearModel model{hcw_state_matrix(n), hcw_input_matrix() / mass_kg, MatrixXd::Zero(3, 6)};
  model.C.leftCols(3).setIdentity();
  return model;
}

LinearModel linear_attitude_model(const Mat3& inertia_kgm2, const Vec3& omega_ref_body_radps) {
  const Mat3 inertia_inv = inertia_kgm2.inverse();
  const Vec3& w0 = omega_ref_body_radps;
  LinearModel model{MatrixXd::Zero(6, 6), MatrixXd::Zero(6, 3), MatrixXd::Zero(3, 6)};
  model.A.topLeftCorner(3, 3) = -skew(w0);
  model.A.topRightCorner(3, 3).setIdentity();
  model.A.bottomRightCorner(3, 3) = inertia_inv * (skew(inertia_kgm2 * w0) - skew(w0) * inertia_kgm2);
  model.B.bottomRows(3) = inertia_inv;
  model.C.leftCols(3).setIdentity();
  return model;
}

}  // namespace chaser::flight::fdi
