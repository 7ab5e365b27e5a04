#include "flight/flight_software.hpp"

#include "core/rotation.hpp"
#include "model/run_timing.hpp"

namespace chaser::flight {

namespace {

// The estimator flies with a pose sensor and a rigid-body target (its inertia is the model's).
std::optional<TargetEstimatorParams> make_target_estimator_params(const model::Scenario& scenario) {
  if (!scenario.sensors.target_pose || !scenario.target.body) return std::nullopt;
  return TargetEstimatorParams{
      .inertia_kgm2 = scenario.target.body->inertia_kgm2,
      .torque_noise_Nm = scenario.navigation.target_torque_noise_Nm,
      .attitude_noise_rad = scenario.sensors.target_pose->attitude_noise_rad,
  };
}

}  // namespace

std::optional<SyncTransferParams> make_sync_transfer(const model::Scenario& scenario) {
  const auto& sync = scenario.guidance.synchronised;
  if (!sync || !scenario.target.body) return std::nullopt;
  return SyncTransferParams{.start_target_m = sync->start_target_m,
                            .capture_target_m = scenario.target.body->capture_point_target_m,
                            .start_s = sync->transfer_start_s,
                            .duration_s = sync->transfer_duration_s,
                            .q_target_from_body = sync->q_target_from_body};
}

std::optional<SyncApproachPlan> make_sync_approach(const model::Scenario& scenario) {
  const auto transfer = make_sync_transfer(scenario);
  if (!transfer || !scenario.guidance.synchronised->approach) return std::nullopt;
  return SyncApproachPlan{.line = scenario.guidance,  // the line's part: guidance_reference reads no more
                          .approach = *scenario.guidance.synchronised->approach,
                          .transfer = *transfer,
                          .target_inertia_kgm2 = scenario.target.body->inertia_kgm2};
}

FlightParams make_flight_params(const model::Scenario& scenario) {
  return FlightParams{
      .orbit = model::TargetOrbit(scenario.orbit),
      .period_ns = model::run_timing(scenario).control_period_ns,
      .guidance = scenario.guidance,
      .navigation = make_nav_params(scenario),
      .position = make_position_control(scenario),
      .attitude = make_attitude_control(scenario),
      .hinf = make_hinf_control(scenario),
      .target_estimator = make_target_estimator_params(scenario),
      .sync = make_sync_transfer(scenario),
      .approach = make_sync_approach(scenario),
      .reach = make_reach(scenario),
      .tmu = make_tmu_params(scenario),
      .management = make_thruster_management(scenario),
      .fdir = make_fdir_params(scenario),
      .active_check = make_active_check_params(scenario),
      .recovery = scenario.fdi.recovery,
      .supervisor = make_flight_supervisor(scenario),
      .supervisor_accommodates = scenario.fdi.supervisor.enabled && scenario.fdi.supervisor.accommodate,
      .mass_from_gauge = scenario.control.mass_from_gauge,
  };
}

FlightOutput step_flight(const FlightParams& params, FlightState& state, const model::SensorMeasurements& meas) {
  FlightOutput out;
  if (!state.initialised) {
    state.navigation = init_nav(params.navigation, meas);
    state.thrusters = model::initial_configuration(params.management.thrusters);
    set_active_thrusters(params.management, state.management, state.thrusters.active);
    if (params.target_estimator) state.target.emplace(*params.target_estimator);
    state.initialised = true;
  }
  const double t_s = to_seconds(meas.t);
  // The chaser's mass as the loops take it (control.mass_from_gauge): the starting mass less the
  // propellant the tank gauge says is used, in the navigation's prediction (its filter divides the
  // commanded force by the design mass: scaled so that it divides by this one) and the position loop.
  PositionControlParams gauged;
  if (params.mass_from_gauge) gauged = with_mass(params.position, params.position.mass_kg - meas.propellant_used_kg);
  const PositionControlParams& position = params.mass_from_gauge ? gauged : params.position;
  const Vec3 force_for_nav_N = params.mass_from_gauge
                                   ? Vec3(state.force_cmd_lvlh_N_prev * (params.position.mass_kg / position.mass_kg))
                                   : state.force_cmd_lvlh_N_prev;
  out.estimate = step_nav(params.navigation, state.navigation, meas, force_for_nav_N);
  if (state.target) {  // the pose in the chaser's body, turned into inertial by the attitude estimate
    if (meas.target_pose.valid)
      state.target->update(meas.target_pose.taken_s,
                           out.estimate.q_inertial_from_body * meas.target_pose.q_body_from_target);
    if (state.target->initialised()) out.target = state.target->predict(t_s);
  }
  const model::LvlhFrame lvlh = params.orbit.lvlh_at(t_s);
  if (params.approach) {
    out.reference = sync_approach_reference(*params.approach, state.sync_latch, out.target, params.orbit, t_s);
  } else if (params.sync) {
    // The synchronised reference follows the target's estimate; until the first pose has arrived,
    // hold where the chaser is (the estimate as its own reference: no feedback, no feed-forward).
    if (out.target) {
      out.reference = sync_reference(*params.sync, *out.target, lvlh, t_s);
    } else {
      out.reference.r_lvlh_m = out.estimate.r_lvlh_m;
      out.reference.v_lvlh_mps = out.estimate.v_lvlh_mps;
      out.reference.q_inertial_from_body = out.estimate.q_inertial_from_body;
      out.reference.omega_body_radps = out.estimate.omega_body_radps;
    }
  } else {
    out.reference = guidance_reference(params.guidance, t_s, lvlh);
  }
  const bool reaching = params.reach && t_s >= params.reach->start_s;
  if (reaching) {
    hold_estimates(state.reach, out.estimate, out.target, t_s, lvlh);
    // The escape withdraws to where the synchronised transfer started, as the approach fixed it.
    if (!state.reach.escape.started() && state.sync_latch.start_target_m)
      state.reach.escape.withdraw_point_target_m = state.sync_latch.start_target_m;
    if (meas.arm && meas.arm->fixture.valid) update_from_camera(*params.reach, state.reach, meas.arm->fixture);
  }
  // Escaping, the chaser's reference is the escape's plan (flight/escape.hpp), which the combined
  // law's platform share below flies.
  if (reaching && state.reach.escape.started() && state.reach.target)
    out.reference = escape_guidance(*params.reach->escape, state.reach.escape, *state.reach.target,
                                    state.reach.frame_offset_m, state.reach.frame_rotation_rad, lvlh, t_s);
  // The rigidisation inhibits the thrusters (flight/reach.hpp): no demand, nothing released (the
  // TMU's owed impulse included), no test pulse, so the allocation commands nothing.
  const bool inhibited = reaching && thrusters_inhibited(*params.reach, state.reach);
  // The escape's arm braked (flight/escape.hpp): the platform's own loops fly the plan's reference,
  // from rest (their states were last stepped before the reach).
  const bool escape_braked = reaching && state.reach.escape.braked();
  if (escape_braked && !state.escape_loops_engaged) {
    state.hinf = HinfControlState{};
    state.escape_loops_engaged = true;
  }
  Vec3 reach_force_inertial_N, reach_torque_body_Nm;
  if (inhibited) {
    out.force_demand_lvlh_N.setZero();
    out.torque_demand_body_Nm.setZero();
  } else if (reaching && stabilising(*params.reach, state.reach) && meas.arm) {
    // The composite detumbled by a pure couple (flight/stabilise.hpp): no force asked for.
    arm::JointVector q;
    for (int j = 0; j < model::kArmJoints; ++j) q(j) = meas.arm->q_rad[static_cast<std::size_t>(j)];
    out.force_demand_lvlh_N.setZero();
    out.torque_demand_body_Nm =
        stabilise_couple(*params.reach->stabilise, params.reach->servicer, state.reach.stabilise, q,
                         out.estimate.q_inertial_from_body, out.estimate.omega_body_radps, t_s);
  } else if (reaching && !escape_braked && platform_command(*params.reach, state.reach, t_s, reach_force_inertial_N, reach_torque_body_Nm)) {
    // The combined controller's platform share, from the joint loop's last step (flight/reach.hpp).
    out.force_demand_lvlh_N = lvlh.q_inertial_from_lvlh.conjugate() * reach_force_inertial_N;
    out.torque_demand_body_Nm = reach_torque_body_Nm;
  } else if (params.hinf.enabled) {
    const HinfDemand demand =
        hinf_control(params.hinf, state.hinf, position, params.attitude, out.estimate, out.reference, lvlh);
    out.force_demand_lvlh_N = demand.force_lvlh_N;
    out.torque_demand_body_Nm = demand.torque_body_Nm;
  } else {
    out.force_demand_lvlh_N = position_control(position, out.estimate, out.reference);
    out.torque_demand_body_Nm = attitude_control(params.attitude, out.estimate, out.reference);
  }

  // The force is wanted in LVLH; the thrusters are fixed in the body: rotate with the estimate.
  const Quat q_body_from_lvlh = out.estimate.q_inertial_from_body.conjugate() * lvlh.q_inertial_from_lvlh;
  Vec6 demand_wrench;
  demand_wrench << q_body_from_lvlh * out.force_demand_lvlh_N, out.torque_demand_body_Nm;

  out.released_wrench = inhibited ? Vec6::Zero().eval() : tmu_release(params.tmu, state.tmu, demand_wrench);
  // The check chosen last period, if any: its pulse rides on this period's allocation.
  const TestPulse pulse{.thruster = inhibited ? model::kNoThruster : state.active_check.next,
                        .on_fraction = params.active_check.pulse_fraction};
  ThrusterManagementOutput managed =
      manage_thrusters(params.management, state.management, out.released_wrench, out.command.ton, pulse);

  // Captured, the chaser no longer flies free: the arm holds it to the target (the rigidisation),
  // then the thrusters turn chaser and target as one body (the stabilisation). Every diagnosis
  // model here is the free chaser's (its inertia, its thrusters' torques about its own CoM), so the
  // diagnosis stands down at the capture: FDIR, supervisor and active checks stop, keeping what they
  // concluded before, and a recovery already made stays in force.
  const bool diagnosing = !(reaching && state.reach.rigidise.started());
  if (!diagnosing && state.fdir.stood_down_s < 0) state.fdir.stood_down_s = t_s;

  // The awake arm's momentum and moving mass, in the deficit bank's torque rows (flight/arm_reaction.hpp).
  const ArmReaction arm = reaching && meas.arm && diagnosing && params.fdir.deficit_isolation
                              ? arm_reaction(params.reach->servicer, state.arm_reaction, *meas.arm, meas.omega_body_radps)
                              : ArmReaction{};

  // FDIR watches the active set's command; a confirmed fault may change the set from this period on.
  fdi::WatchedTon watched_ton = watched_on_times(params.fdir, state.fdir, out.command.ton);
  add_uncommanded_on_time(params.fdir, state.fdir, state.management.uncommanded_thruster,
                          state.management.uncommanded_on_fraction, watched_ton);
  const FdirInput fdir_in{.t_s = t_s,
                          .period = meas.t / params.period_ns,
                          .q_est_inertial_from_body = out.estimate.q_inertial_from_body,
                          .q_ref_inertial_from_body = out.reference.q_inertial_from_body,
                          .q_inertial_from_lvlh = lvlh.q_inertial_from_lvlh,
                          .ton = watched_ton,
                          .commanded_wrench = managed.commanded_wrench,
                          .checked_thruster = managed.pulsed,
                          .arm_momentum_Nms = arm.momentum_Nms,
                          .com_shift_m = arm.com_shift_m};
  if (diagnosing) step_fdir(params.fdir, state.fdir, meas, fdir_in, out.fdir);
  if (out.fdir.confirmed_now != model::kNoThruster) {
    const model::ThrusterMask watched_before = state.thrusters.active;
    if (const auto next = model::recover(params.management.thrusters, params.recovery, state.thrusters,
                                         out.fdir.confirmed_now)) {
      state.thrusters = *next;
      set_active_thrusters(params.management, state.management, state.thrusters.active);
      // An excluded thruster read stuck open or leaking keeps firing: the allocation cancels it, and
      // the FDI watches on over the set it watched, that thruster's lane read at its known on-time
      // (add_uncommanded_on_time). One with nothing left to give leaves the watched set.
      double uncommanded = 0.0;
      if (params.recovery == model::RecoveryPolicy::kExclude) {
        uncommanded = out.fdir.confirmed_uncommanded_on_fraction;
        set_uncommanded_thrust(params.management, state.management, out.fdir.confirmed_now, uncommanded);
      }
      rearm_fdir(params.fdir, state.fdir, uncommanded > 0.0 ? watched_before : state.thrusters.active, t_s,
                 out.fdir.confirmed_now);
      managed = manage_thrusters(params.management, state.management, out.released_wrench, out.command.ton, pulse);
      out.recovered_now = true;
    }
  }
  // The supervisor reads what was commanded this period; the mode it switches to flies from the next
  // (and, stood down, stays flown).
  if (params.supervisor) {
    if (state.supervisor.z.size() == 0)  // the first period
      state.supervisor = fdi::make_supervisor_state(*params.supervisor);
    if (diagnosing &&
        fdi::step_supervisor(*params.supervisor, state.supervisor, t_s, meas.omega_body_radps, out.command.ton) &&
        params.supervisor_accommodates)
      fly_supervisor_mode(*params.supervisor, state.supervisor.mode, params.management, state.management,
                          state.thrusters);
    out.supervisor_mode = state.supervisor.mode;
  }
  tmu_account(params.tmu, state.tmu, managed.commanded_wrench);
  step_active_check(params.active_check, state.active_check,
                    {.t_s = t_s,
                     .range_m = out.estimate.r_lvlh_m.norm(),
                     .active = state.thrusters.active,
                     .suspect = params.active_check.enabled && !reaching
                                    ? thruster_to_check_again(params.fdir, state.fdir, params.active_check.recheck_gain)
                                    : model::kNoThruster,
                     // No check once the arm wakes: its reaction on the hub is in the rates a check's
                     // pulse is read from, and the pulse would shake the gripper.
                     .fdi_listening = !reaching && fdi_listening(state.fdir)},
                    out.command.ton);

  out.command.latch_closed_groups = state.thrusters.closed_groups;
  out.commanded_wrench = managed.commanded_wrench;
  out.allocation_feasible = managed.feasible;
  out.checked_thruster = managed.pulsed;
  state.force_cmd_lvlh_N_prev = q_body_from_lvlh.conjugate() * managed.commanded_wrench.head<3>();
  return out;
}

}  // namespace chaser::flight
