#include "model/thruster_geometry.hpp"

namespace chaser::model {

Vec6 thruster_wrench(const ThrusterParams& thruster, const Vec3& com_body_m) {
  const Vec3 force_N = thruster.max_thrust_N * thruster.direction_body;
  Vec6 wrench;
  wrench << force_N, (thruster.position_body_m - com_body_m).cross(force_N);
  return wrench;
}

ConfigMatrix configuration_matrix(const ThrusterSetParams& set, int branch, const Vec3& com_body_m) {
  ConfigMatrix m;
  for (int i = 0; i < kThrustersPerBranch; ++i)
    m.col(i) = thruster_wrench(set.thrusters[branch_first(branch) + i], com_body_m);
  return m;
}

}  // namespace chaser::model
