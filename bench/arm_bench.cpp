// The arm's costs: one MuJoCo RK4 step of the hub + arm + target scene (the truth's inner cost), the
// flight software's own model of the servicer (kinematics, the 13 x 13 mass matrix, C(q, v) v) and
// the combined compliance law that the joint loop evaluates at 1 kHz, and a control period of the
// reach against the engine alone on the same model. docs/performance.md records the figures.
#include <cmath>

#include <benchmark/benchmark.h>

#include <memory>
#include <variant>

#include "flight/arm/arm_kinematics.hpp"
#include "flight/arm/coriolis_force.hpp"
#include "flight/arm/floating_base_mass_matrix.hpp"
#include "flight/arm/servicer_arm.hpp"
#include "flight/arm/servicer_momentum.hpp"
#include "model/arm.hpp"
#include "plant/multibody/mjcf.hpp"
#include "plant/multibody/mujoco_model.hpp"
#include "plant/multibody_motion.hpp"
#include "flight/arm/compliance_control.hpp"
#include "flight/flight_software.hpp"
#include "io/scenario_loader.hpp"
#include "sim/simulation.hpp"

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

// The servicer's momentum about its CoM (kinematics, H(q), one product): what the diagnosis adds to
// a control period of the reach for the arm's reaction in its torque rows (flight/arm_reaction.hpp),
// once per 0.1 s period against the joint loop's 100 evaluations of the law.
void BM_ServicerMomentum(benchmark::State& state) {
  const flight::arm::ServicerArmParams params = flight::arm::servicer_arm_of(bench_scene());
  flight::arm::JointVector q, q_dot;
  for (int j = 0; j < model::kArmJoints; ++j) {
    q[j] = 0.3 * std::sin(j + 1.0);
    q_dot[j] = 0.01 * std::cos(j + 1.0);
  }
  const Vec3 omega(0.001, -0.002, 0.003);
  for (auto _ : state) benchmark::DoNotOptimize(flight::arm::servicer_momentum(params, q, q_dot, omega));
}
BENCHMARK(BM_ServicerMomentum);

// One evaluation of the combined compliance law (the flight software's model, the extended task,
// two LU solves of 13 x 13): what the joint loop adds to each 1 ms step.
void BM_ComplianceLaw(benchmark::State& state) {
  using namespace flight::arm;
  const ServicerArmParams params = servicer_arm_of(bench_scene());
  JointVector q;
  for (int j = 0; j < model::kArmJoints; ++j) q[j] = 0.3 * std::sin(j + 1.0) + 0.5;
  const ServicerVector v = ServicerVector::Constant(0.01);
  const Quat attitude = Quat(0.9, 0.1, -0.3, 0.2).normalized();
  const ArmKinematics start = arm_kinematics(params, Vec3(1.0, 2.0, 3.0), attitude, q);
  const ComplianceGains gains = compliance_gains(params, start, ComplianceBandwidths{});
  TaskReference reference;
  reference.hub.r_m = Vec3(1.01, 2.0, 3.0);
  reference.hub.omega_radps = Vec3(0.01, 0.02, 0.03);
  reference.tool.r_m = start.r_tool_world_m + Vec3(0.01, 0.0, 0.0);
  reference.tool.omega_radps = reference.hub.omega_radps;
  for (auto _ : state) {
    const ArmKinematics k = arm_kinematics(params, Vec3(1.0, 2.0, 3.0), attitude, q);
    benchmark::DoNotOptimize(compliance_control(params, k, q, v, reference, gains));
  }
}
BENCHMARK(BM_ComplianceLaw);

// comrade_capture flown to 1 s into its reach (the arm awake on the multibody plant), the
// simulation kept between the benchmarks below.
struct CaptureRun {
  model::Scenario scenario;
  flight::FlightParams flight;
  std::unique_ptr<sim::Simulation> sim;
  CaptureRun() {
    const io::LoadResult loaded = io::load_scenario_file(CHASER_SOURCE_DIR "/scenarios/comrade_capture.yaml");
    scenario = *loaded.scenario;
    flight = flight::make_flight_params(scenario);
    restart();
  }
  void restart() {
    sim = std::make_unique<sim::Simulation>(scenario, flight, sim::RunOptions{});
    while (sim->t_s() < scenario.capture->start_s + 1.0) sim->step();
  }
};
CaptureRun& capture_run() {
  static CaptureRun run;
  return run;
}

// One 0.1 s control period of the reach: the flight software, then 100 joint steps of the combined
// law with the plant carried 1 ms on MuJoCo each, the sensors, the forces, the monitor (no
// telemetry). Its ratio to BM_CaptureEngineAlone is what Chaser's orchestration costs over the
// engine on the same model (docs/performance.md).
void BM_CapturePeriod(benchmark::State& state) {
  CaptureRun& run = capture_run();
  for (auto _ : state) {
    if (run.sim->done()) {
      state.PauseTiming();
      run.restart();
      state.ResumeTiming();
    }
    run.sim->step();
  }
}
BENCHMARK(BM_CapturePeriod)->Unit(benchmark::kMillisecond);

// The same period's worth of MuJoCo alone: 100 bare mj_step of the run's own scene (its model and
// state copied from the plant), the joints' torques held.
void BM_CaptureEngineAlone(benchmark::State& state) {
  CaptureRun& run = capture_run();
  const auto& motion = std::get<plant::MultibodyMotionState>(run.sim->plant().state.motion);
  plant::multibody::MujocoModel world = motion.world;
  world.mutable_model().opt.timestep = 1e-3;
  for (auto _ : state)
    for (int k = 0; k < 100; ++k) world.step();
}
BENCHMARK(BM_CaptureEngineAlone)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace chaser
