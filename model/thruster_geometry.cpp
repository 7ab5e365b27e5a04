#include "model/thruster_geometry.hpp"

namespace chaser::model {

Vec6 thruster_wrench(const ThrusterParams& thruster, const Vec3& com_body_m) {
  const Vec3 force_N = thruster.max_thrust_N * thruster.direction_body;
  Vec6 wrench;
  wrench << force_N, (thruster.position_body_m - com_body_m).cross(force_N);
  return wrench;
}

ConfigMatrix configuration_matrix(const ThrusterSetParams& set, ThrusterMask mask, const Vec3& com_body_m) {
  ConfigMatrix m = ConfigMatrix::Zero();
  const ThrusterList list = thruster_list(mask & all_thrusters(set));
  for (int k = 0; k < list.count; ++k)
    m.col(k) = thruster_wrench(set.thrusters[static_cast<std::size_t>(list.index[k])], com_body_m);
  return m;
}

Eigen::Matrix<double, 6, Eigen::Dynamic> configuration_columns(const ThrusterSetParams& set, ThrusterMask mask,
                                                              const Vec3& com_body_m) {
  const ThrusterMask used = mask & all_thrusters(set);
  return configuration_matrix(set, used, com_body_m).leftCols(thruster_count(used));
}

}  // namespace chaser::model
