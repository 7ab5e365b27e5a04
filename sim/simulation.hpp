#pragma once
// One closed-loop run as an object that can be advanced period by period (run_scenario flies it to
// the end; the Python module's chaser.Simulation steps it, reads it, and may fly a period itself).
// A control period is begin_period (the truth at its start, the sensors' measurements), a flight
// output computed from those measurements only, and end_period (the mission monitor, the plant's
// propagation under the command, telemetry). step() is the three with Chaser's flight software.
#include <array>
#include <chrono>
#include <functional>
#include <string>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "flight/flight_software.hpp"
#include "model/scenario.hpp"
#include "model/target_orbit.hpp"
#include "plant/plant.hpp"
#include "sim/phase_sequence.hpp"
#include "sim/rate_schedule.hpp"
#include "sim/run_phases.hpp"
#include "sim/run.hpp"
#include "sim/telemetry.hpp"
#include "sim/telemetry_channels.hpp"

namespace chaser::sim {

class Simulation {
 public:
  // The plant from `truth`, flown by flight software built from `flight_params`; options as for
  // run_scenario (a telemetry file and/or rows in memory, GLR maxima per second). Both references
  // must outlive the simulation.
  Simulation(const model::Scenario& truth, const flight::FlightParams& flight_params, const RunOptions& options);
  // A fork: `from` as it stands between two periods (plant, flight software, phases, the results so
  // far), to be flown on by itself to period `periods` (at most from's), recording no telemetry. A
  // study flies many from one state this way (campaign/rigidise_study.hpp), from several threads at
  // once: the fork only reads `from`. The blocks added by add_block are copied as they are (what
  // they capture, they share). Throws std::invalid_argument in the middle of a period or past
  // from's periods.
  Simulation(const Simulation& from, std::int64_t periods);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  // Every period flown, or the monitor stopped the run (diverged); finish() may then be called.
  bool done() const { return done_; }
  std::int64_t period() const { return k_; }  // the next period to fly
  std::int64_t periods() const { return periods_; }
  double t_s() const { return to_seconds(k_ * period_ns_); }  // [s] its start

  // One period flown by Chaser's flight software.
  void step() { end_period(flight::step_flight(flight_params_, flight_state_, begin_period())); }

  // The two halves of a period, for a flight output computed elsewhere (sim/user_flight.hpp).
  // begin_period draws the sensors' noise once per period: called again before end_period (a
  // flight callback that failed, retried), it returns the same measurements.
  const model::SensorMeasurements& begin_period();
  void end_period(const flight::FlightOutput& out);

  // A block at its own rate beside the flight software's period (a fast inner loop, a sensor, a
  // probe): called at each activation, in the order blocks were added and after the flight
  // software at a time they share, with the time and the plant at that time (the truth is carried
  // there: the plant stops inside the period). Before the first period; throws std::invalid_argument
  // for a rate sim::validate refuses or more than kMaxScheduledBlocks - 1 blocks.
  using Block = std::function<void(TimeNs t, const plant::Plant& plant)>;
  void add_block(const std::string& name, const Rate& rate, Block block);

  // The capture's closed chain started anew: the joints' rates set, hub and target moving with them
  // as the weld and the momentum demand (plant/arm_joints.hpp). Between periods, the grasp engaged.
  void set_closed_chain_joint_rates(const std::array<double, model::kArmJoints>& rates_radps);

  // A fault added to the plant's from now on (its onset is not before t_s(), checked by the caller).
  void add_fault(const model::FaultParams& fault) { plant::inject_fault(plant_, fault); }

  // The end of the run: the final monitor sample, the FDIR's diagnoses, the timings, the telemetry
  // file finished. Called once, when done().
  RunResult finish();

  const plant::Plant& plant() const { return plant_; }
  // The phase of the period starting at t_s() (decided at its start: sim/run_phases.hpp), and the
  // run's phases.
  int phase() const { return phase_state_.phase; }
  const PhaseSequenceParams& phases() const { return phase_params_; }
  const flight::FlightParams& flight_params() const { return flight_params_; }
  flight::FlightState& flight_state() { return flight_state_; }

 private:
  flight::GuidanceRef final_reference(double t_end_s) const;
  const std::chrono::steady_clock::time_point wall_start_;
  const model::Scenario& scenario_;
  const flight::FlightParams& flight_params_;
  const RunOptions options_;
  const model::TargetOrbit orbit_;  // the truth's, for the initial state and the monitor
  const TimeNs period_ns_;
  const std::int64_t periods_;
  const TelemetryShape shape_;
  const PhaseSequenceParams phase_params_;
  PhaseSequenceState phase_state_;
  // The rates: block 0 the flight software's period, then the blocks added (add_block).
  ScheduleParams schedule_;
  ScheduleState schedule_state_;
  std::vector<std::string> block_names_;
  std::vector<Block> blocks_;

  plant::Plant plant_;
  flight::FlightState flight_state_;
  flight::GuidanceRef last_reference_;  // the flight software's, kept with the approach steps (final_reference)

  // Telemetry: the file's writer, the rows in memory, the channels they hold.
  std::unique_ptr<TelemetryWriter> telemetry_;
  TelemetryRows* memory_ = nullptr;
  std::vector<TelemetryChannel> channels_;
  bool every_channel_ = true;
  bool recording_ = false;
  bool keep_out_ = false;  // the target has a keep-out volume: its attitude is needed every period
  // The capture: the arm wakes with the first phase configured so (the plant becomes the multibody
  // one); the joint loop's period; the pose the truth judges the gripper against.
  Vec3 reach_goal_target_m_ = Vec3::Zero();  // the pre-grasp pose on the target, as the truth judges the gripper
  Quat q_target_from_reach_goal_ = Quat::Identity();
  TimeNs joint_period_ns_ = 0;
  TimeNs braked_step_ns_ = 0;  // capture.escape.braked_step_s (0: no escape)
  bool arm_awake_ = false;
  std::vector<PhaseRequirements> phase_requirements_;  // by phase index (sim/run_phases.hpp)
  std::vector<PhaseConfiguration> phase_configuration_;

  // The period begun: the truth at its start and the FDI's lanes before a recovery changes them.
  plant::RigidState truth_;
  model::SensorMeasurements measurements_;
  flight::fdi::WatchedSet watched_;

  RunResult result_;
  std::chrono::steady_clock::time_point loop_start_;
  std::int64_t k_ = 0;
  bool begun_ = false;  // begin_period has sensed period k_
  bool done_ = false;

  // The stages of end_period, in order.
  EscapeSample escape_sample(const MonitorSample& sample, const plant::GripperTruth& gripper, double t_s) const;
  struct PeriodTruth {
    MonitorSample sample;
    plant::TargetRotation target;
    std::array<model::SloshState, model::kMaxSloshTanks> slosh{};
    model::ArmMeasurements arm;  // with a capture: the joints (the stowed angles before the arm wakes)
    std::optional<plant::GripperTruth> gripper;  // once the arm is awake
    std::optional<plant::ArmFigure> figure;       // once the arm is awake, when recorded
  };
  PeriodTruth sample_truth(const flight::FlightOutput& out, double t_s);
  bool judge(const MonitorSample& sample);
  std::uint64_t phase_flags() const;
  void propagate(const model::ThrusterCommand& command, TimeNs t_k);
  void propagate_with_arm(const model::ThrusterCommand& command, TimeNs t_k);
  void tally(const flight::FlightOutput& out, double t_s);
  void record(const flight::FlightOutput& out, const PeriodTruth& truth, double t_s);
};

}  // namespace chaser::sim
