#pragma once
// A compiled MuJoCo model and its data, owned together. Every MuJoCo call that can raise an error
// runs guarded (plant/multibody/mujoco_errors.hpp), so an error is a MujocoError; a step whose state
// becomes non-finite (MuJoCo warns and resets the state) throws one too.
#include <memory>
#include <string>

#include <Eigen/Core>
#include <mujoco/mujoco.h>

#include "core/types.hpp"
#include "plant/multibody/mujoco_errors.hpp"

namespace chaser::plant::multibody {

// A body's frame in the world as mj_kinematics left it: its origin [m] and attitude (xpos, xquat).
inline Vec3 body_position(const mjData& d, int body) {
  return Vec3(d.xpos[3 * body], d.xpos[3 * body + 1], d.xpos[3 * body + 2]);
}
inline Quat body_attitude(const mjData& d, int body) {
  return Quat(d.xquat[4 * body], d.xquat[4 * body + 1], d.xquat[4 * body + 2], d.xquat[4 * body + 3]);
}

// Where an actuator with state (a filter, as the joints' torque loops) keeps it in mjData::act.
// MuJoCo 2.2 has no actuator_actadr: the actuators with state come after every one without (its
// compiler refuses another order), one activation each, in order.
inline int activation_index(const mjModel& m, int actuator) { return actuator - (m.nu - m.na); }

// Momentum of the whole scene, world frame: linear [kg m/s] and angular about the scene's
// centre of mass [kg m^2/s].
struct Momentum {
  Vec3 linear_kgmps = Vec3::Zero();
  Vec3 angular_kgm2ps = Vec3::Zero();
};

class MujocoModel {
 public:
  // Compiles MJCF text; throws MujocoError with MuJoCo's own message for a model it refuses.
  explicit MujocoModel(const std::string& mjcf);
  ~MujocoModel();
  // A deep copy (mj_copyModel, mj_copyData): the copy steps on its own, as a plant copied to reset
  // a benchmark or held per campaign thread must.
  MujocoModel(const MujocoModel& other);
  MujocoModel& operator=(const MujocoModel& other);
  MujocoModel(MujocoModel&& other) noexcept;
  MujocoModel& operator=(MujocoModel&& other) noexcept;

  const mjModel& model() const { return *model_; }
  // The fields a plant changes between steps (opt.timestep, a body's mass, eq_active): each copy
  // has its own model.
  mjModel& mutable_model() { return *model_; }
  mjData& data() { return *data_; }
  const mjData& data() const { return *data_; }

  // mj_step: one step of the model's integrator. Throws MujocoError naming the time when MuJoCo
  // raises an error or finds a non-finite acceleration (the step is then not taken).
  void step();
  // The same step with the applied forces set by `apply()` inside the step's first evaluation: once
  // its positions and velocities are evaluated (mj_fwdPosition, mj_fwdVelocity: the bodies' poses,
  // centres of mass, Jacobians' cdof and velocities at the step's start) and before its
  // accelerations. A caller whose forces depend on that state reads it there instead of running a
  // kinematics pass of its own before step(), which costs a quarter of an RK4 step's kinematics and
  // normalises qpos's quaternions a second time. It is mj_step's own sequence (mj_checkPos,
  // mj_checkVel, mj_forward, mj_checkAcc, the integrator) split at the velocity stage: the same
  // state to the bit as step() after forces computed from the start on a copy, for RK4 and Euler
  // (tests/plant/multibody/mujoco_model_test.cpp). `apply` runs outside MuJoCo's error guard and
  // may throw.
  template <class Apply>
  void step_applying(Apply&& apply) {
    step_applying(apply, [](const mjData&) {});
  }
  // The same, with `observe(data)` called once the step's first evaluation is whole (its constraint
  // forces efc_force at the step's start, before RK4's later stages overwrite them with their own).
  template <class Apply, class Observe>
  void step_applying(Apply&& apply, Observe&& observe) {
    const int bad_before = begin_step();
    apply();
    if (finish_evaluation()) {
      observe(static_cast<const mjData&>(*data_));
      integrate(bad_before);
    } else {  // an integrator whose step evaluates itself: its one evaluation is the step's start
      integrate(bad_before);
      observe(static_cast<const mjData&>(*data_));
    }
  }
  // mj_forward: positions, velocities and accelerations consistent with qpos, qvel and the inputs.
  void forward();

  // The joint-space mass matrix M(q) (nv x nv) after forward().
  Eigen::MatrixXd mass_matrix() const;
  // The scene's momentum at the current state (calls mj_subtreeVel).
  Momentum momentum();

  // Index helpers; throw MujocoError for a name the model does not have.
  int body(const char* name) const;
  int joint(const char* name) const;
  int actuator(const char* name) const;

 private:
  int begin_step();  // the checks and the first evaluation's position and velocity stages
  // The rest of the first evaluation (false: the integrator evaluates itself, in integrate).
  bool finish_evaluation();
  void integrate(int bad_before);  // the integrator, from the evaluated start
  mjModel* model_ = nullptr;
  mjData* data_ = nullptr;
  int index(int type, const char* name, const char* what) const;
};

}  // namespace chaser::plant::multibody
