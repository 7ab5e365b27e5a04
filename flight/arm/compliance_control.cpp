#include "flight/arm/compliance_control.hpp"

#include <cmath>
#include <string>
#include <vector>

#include <Eigen/LU>
#include <fmt/format.h>

#include "flight/arm/coriolis_force.hpp"
#include "flight/arm/floating_base_mass_matrix.hpp"

namespace chaser::flight::arm {

namespace {

// The task's blocks: hub position, hub attitude, tool position, tool attitude (3 rows each), the joint.
constexpr int kAttitudeRows[2] = {3, 9};
bool is_attitude_row(int row) { return (row >= 3 && row < 6) || (row >= 9 && row < 12); }

}  // namespace

ComplianceGains compliance_gains(const ServicerArmParams& params, const ArmKinematics& kinematics,
                                 const ComplianceBandwidths& bandwidths) {
  const ServicerMatrix H = floating_base_mass_matrix(params, kinematics);
  const TaskJacobian J = extended_jacobian(kinematics);
  const ServicerMatrix J_Hinv_Jt = J * H.ldlt().solve(J.transpose());
  const ServicerMatrix lambda = J_Hinv_Jt.inverse();
  ComplianceGains gains;
  const auto set_block = [&](int row, int size, double w_radps) {
    const double mass = lambda.diagonal().segment(row, size).mean();
    for (int k = row; k < row + size; ++k) {
      gains.stiffness(k) = mass * w_radps * w_radps;
      gains.damping(k) = 2.0 * bandwidths.damping_ratio * mass * w_radps;
    }
  };
  // One mass per block of three keeps each attitude's stiffness isotropic.
  set_block(0, 3, bandwidths.hub_radps);
  set_block(3, 3, bandwidths.hub_radps);
  set_block(6, 3, bandwidths.tool_radps);
  set_block(9, 3, bandwidths.tool_radps);
  set_block(12, 1, bandwidths.joint_radps);
  return gains;
}

std::vector<std::string> validate(const ComplianceGains& gains) {
  std::vector<std::string> problems;
  for (int k = 0; k < kTaskDofs; ++k) {
    if (!(gains.stiffness(k) > 0.0 && std::isfinite(gains.stiffness(k))))
      problems.push_back(fmt::format("stiffness[{}]: must be finite and > 0", k));
    if (!(gains.damping(k) > 0.0 && std::isfinite(gains.damping(k))))
      problems.push_back(fmt::format("damping[{}]: must be finite and > 0", k));
  }
  for (const int row : kAttitudeRows) {
    const double k0 = gains.stiffness(row);
    if (gains.stiffness(row + 1) != k0 || gains.stiffness(row + 2) != k0)
      problems.push_back(fmt::format("stiffness[{}..{}]: an attitude's stiffness must be the same on its three axes "
                                     "(the spring's potential 2 k (1 - eta) is isotropic)",
                                     row, row + 2));
  }
  return problems;
}

double compliance_potential(const ComplianceGains& gains, const TaskVector& pose_errors) {
  double u = 0.0;
  for (int k = 0; k < kTaskDofs; ++k)
    if (!is_attitude_row(k)) u += 0.5 * gains.stiffness(k) * pose_errors(k) * pose_errors(k);
  for (const int row : kAttitudeRows) {
    const double eta = std::sqrt(std::max(0.0, 1.0 - pose_errors.segment<3>(row).squaredNorm()));
    u += 2.0 * gains.stiffness(row) * (1.0 - eta);
  }
  return u;
}

ComplianceOutput compliance_control(const ServicerArmParams& params, const ArmKinematics& kinematics,
                                    const JointVector& joint_angles_rad, const ServicerVector& velocity,
                                    const TaskReference& reference, const ComplianceGains& gains) {
  const ServicerMatrix H = floating_base_mass_matrix(params, kinematics);
  const TaskJacobian J = extended_jacobian(kinematics);
  ComplianceOutput out;
  out.errors = task_errors(kinematics, J, joint_angles_rad, velocity, reference);
  const Eigen::PartialPivLU<TaskJacobian> lu(J);
  const ServicerVector nu_ref = lu.solve(out.errors.reference_velocity);
  const ServicerVector nu_ref_rate =
      lu.solve(out.errors.reference_acceleration - extended_jacobian_rate_times(kinematics, velocity, nu_ref));
  const TaskVector task_force = gains.stiffness.cwiseProduct(out.errors.pose) +
                                gains.damping.cwiseProduct(out.errors.velocity);
  out.generalized_force =
      H * nu_ref_rate + coriolis_times(params, kinematics, velocity, nu_ref) - J.transpose() * task_force;
  const ServicerVector s = velocity - nu_ref;
  out.storage_J = 0.5 * s.dot(H * s) + compliance_potential(gains, out.errors.pose);
  return out;
}

}  // namespace chaser::flight::arm
