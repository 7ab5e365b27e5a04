// The arm's costs: one MuJoCo RK4 step of the hub + arm + target scene (the truth's inner cost), and
// the flight software's own model of the servicer (kinematics, the 13 x 13 mass matrix, C(q, v) v)
// that the combined controllers evaluate at their rate. docs/performance.md records the figures.
#include <cmath>

#include <benchmark/benchmark.h>

#include "flight/arm/arm_kinematics.hpp"
#include "flight/arm/coriolis_force.hpp"
#include "flight/arm/floating_base_mass_matrix.hpp"
#include "flight/arm/servicer_arm.hpp"
#include "model/arm.hpp"
#include "plant/multibody/mjcf.hpp"
#include "plant/multibody/mujoco_model.hpp"

namespace chaser {
namespace {

model::MultibodySceneParams bench_scene() {
  model::MultibodySceneParams scene;
  scene.hub_inertia_kgm2 = Vec3(1850.0, 1900.0, 1300.0).asDiagonal();
  scene.target_inertia_kgm2 = Vec3(17023.0, 124826.0, 129112.0).asDiagonal();
  return scene;
}

// One mj_step (RK4, 1 ms) with every joint driven: the multibody plant's unit of work.
void BM_MujocoSceneStep(benchmark::State& state) {
  plant::multibody::MujocoModel model(plant::multibody::mjcf_of(bench_scene()));
  mjData& d = model.data();
  for (int j = 0; j < model::kArmJoints; ++j) d.qpos[7 + j] = 0.3 * std::sin(j + 1.0);
  for (auto _ : state) {
    for (int j = 0; j < model::kArmJoints; ++j) d.ctrl[j] = 2.0 * std::sin((1.0 + 0.7 * j) * d.time);
    model.step();
  }
}
BENCHMARK(BM_MujocoSceneStep);

// The flight model at one configuration: kinematics, H(q) and C(q, v) v, as a combined controller
// needs them once per evaluation.
void BM_ServicerModel(benchmark::State& state) {
  const flight::arm::ServicerArmParams params = flight::arm::servicer_arm_of(bench_scene());
  flight::arm::JointVector q;
  for (int j = 0; j < model::kArmJoints; ++j) q[j] = 0.3 * std::sin(j + 1.0);
  flight::arm::ServicerVector v = flight::arm::ServicerVector::Constant(0.01);
  const Quat attitude = Quat(0.9, 0.1, -0.3, 0.2).normalized();
  for (auto _ : state) {
    const flight::arm::ArmKinematics k = flight::arm::arm_kinematics(params, Vec3(1.0, 2.0, 3.0), attitude, q);
    benchmark::DoNotOptimize(flight::arm::floating_base_mass_matrix(params, k));
    benchmark::DoNotOptimize(flight::arm::coriolis_force(params, k, v));
  }
}
BENCHMARK(BM_ServicerModel);

}  // namespace
}  // namespace chaser
