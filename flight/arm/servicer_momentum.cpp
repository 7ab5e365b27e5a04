#include "flight/arm/servicer_momentum.hpp"

#include "flight/arm/floating_base_mass_matrix.hpp"

namespace chaser::flight::arm {

ServicerMomentum servicer_momentum(const ServicerArmParams& params, const JointVector& joint_angles_rad,
                                   const JointVector& joint_rates_radps, const Vec3& omega_hub_body_radps) {
  // The hub at the origin in its own axes: world axes are hub axes below.
  const ArmKinematics k = arm_kinematics(params, Vec3::Zero(), Quat::Identity(), joint_angles_rad);
  const ServicerMatrix H = floating_base_mass_matrix(params, k);
  ServicerVector v = ServicerVector::Zero();
  v.segment<3>(3) = omega_hub_body_radps;
  v.tail<model::kArmJoints>() = joint_rates_radps;
  const ServicerVector p = H * v;
  double mass_kg = params.hub_mass_kg;
  Vec3 first_moment = Vec3::Zero();  // the hub's CoM is the origin
  for (std::size_t i = 0; i < params.links.size(); ++i) {
    mass_kg += params.links[i].mass_kg;
    first_moment += params.links[i].mass_kg * k.r_com_world_m[i];
  }
  ServicerMomentum m;
  m.com_hub_m = first_moment / mass_kg;
  const Vec3 P = p.head<3>();
  m.angular_momentum_Nms = p.segment<3>(3) - m.com_hub_m.cross(P);
  const Vec3& c = m.com_hub_m;
  m.locked_inertia_kgm2 = H.block<3, 3>(3, 3) - mass_kg * (c.squaredNorm() * Mat3::Identity() - c * c.transpose());
  return m;
}

}  // namespace chaser::flight::arm
