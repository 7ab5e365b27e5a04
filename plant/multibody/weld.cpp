#include "plant/multibody/weld.hpp"

#include <Eigen/Geometry>

namespace chaser::plant::multibody {

void engage_weld_here(MujocoModel& world, int equality) {
  mjModel& m = world.mutable_model();
  mjData& d = world.data();
  mj_kinematics(&m, &d);  // xpos and xquat of the current qpos
  const int b1 = m.eq_obj1id[equality], b2 = m.eq_obj2id[equality];
  const Vec3 x1 = body_position(d, b1), x2 = body_position(d, b2);
  const Quat q1 = body_attitude(d, b1), q2 = body_attitude(d, b2);
  const Vec3 p = q1.conjugate() * (x2 - x1);
  const Quat q_rel = (q1.conjugate() * q2).normalized();
  mjtNum* data = m.eq_data + static_cast<std::ptrdiff_t>(mjNEQDATA) * equality;
  data[0] = data[1] = data[2] = 0.0;  // the anchor: body2's origin
  data[3] = p.x(), data[4] = p.y(), data[5] = p.z();
  data[6] = q_rel.w(), data[7] = q_rel.x(), data[8] = q_rel.y(), data[9] = q_rel.z();
  m.eq_active[equality] = 1;
}

void release_weld(MujocoModel& world, int equality) { world.mutable_model().eq_active[equality] = 0; }

bool weld_engaged(const MujocoModel& world, int equality) { return world.model().eq_active[equality] != 0; }

WeldPose weld_pose(const MujocoModel& world, int equality) {
  const mjtNum* data = world.model().eq_data + static_cast<std::ptrdiff_t>(mjNEQDATA) * equality;
  return {Vec3(data[3], data[4], data[5]), Quat(data[6], data[7], data[8], data[9])};
}

void set_weld_pose(MujocoModel& world, int equality, const WeldPose& pose) {
  mjtNum* data = world.mutable_model().eq_data + static_cast<std::ptrdiff_t>(mjNEQDATA) * equality;
  data[0] = data[1] = data[2] = 0.0;
  data[3] = pose.p_m.x(), data[4] = pose.p_m.y(), data[5] = pose.p_m.z();
  const Quat q = pose.q_rel.normalized();
  data[6] = q.w(), data[7] = q.x(), data[8] = q.y(), data[9] = q.z();
}

void set_weld_timeconst(MujocoModel& world, int equality, double timeconst_s) {
  mjModel& m = world.mutable_model();
  m.eq_solref[mjNREF * equality] = timeconst_s;
  m.eq_solref[mjNREF * equality + 1] = 1.0;
}

}  // namespace chaser::plant::multibody
