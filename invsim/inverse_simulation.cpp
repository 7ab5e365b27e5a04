#include "invsim/inverse_simulation.hpp"

#include <algorithm>
#include <cmath>

#include "core/constants.hpp"
#include "core/hill_frames.hpp"
#include "invsim/carried_opening.hpp"
#include "invsim/desired_trajectory.hpp"
#include "invsim/inverse_step.hpp"
#include "invsim/measurement_link.hpp"
#include "invsim/paper_reading.hpp"
#include "invsim/phase_plane.hpp"
#include "invsim/pulse_conversion.hpp"
#include "invsim/relative_dynamics.hpp"
#include "invsim/sensor_geometry.hpp"
#include "invsim/thruster_set.hpp"

namespace chaser::invsim {
namespace {

constexpr double kDivergedRangeM = 1e4;  // [m] beyond this the approach has clearly failed

using GroupWrenches = std::array<std::array<Wrench, 2>, 3>;  // [axis][0: +, 1: -]

int dir_index(int direction) { return direction > 0 ? 0 : 1; }

// Everything a run takes from its thrusters and their faults. thruster_signature is values(): a
// field added here must be added there, beside it, or layouts that differ in it would share a flight.
struct ThrusterContext {
  std::array<std::array<double, 2>, 3> u_max_pilot;    // [m/s^2] the inverse model's u_max per group
  std::array<std::array<double, 2>, 3> u_max_nominal;  // [m/s^2] the healthy group's
  Vec3 a0_radps2;                                      // attitude control accelerations
  GroupWrenches translation;                           // wrenches per group, with the faults
  GroupWrenches attitude;

  std::vector<double> values() const {
    std::vector<double> v;
    for (const GroupWrenches* groups : {&translation, &attitude})
      for (const auto& axis : *groups)
        for (const Wrench& w : axis) {
          v.insert(v.end(), w.force_body_N.data(), w.force_body_N.data() + 3);
          v.insert(v.end(), w.torque_body_Nm.data(), w.torque_body_Nm.data() + 3);
          v.push_back(w.thrust_sum_N);
        }
    for (int axis = 0; axis < 3; ++axis)
      for (int d = 0; d < 2; ++d) {
        v.push_back(u_max_pilot[axis][d]);
        v.push_back(u_max_nominal[axis][d]);
      }
    v.insert(v.end(), a0_radps2.data(), a0_radps2.data() + 3);
    return v;
  }
};

ThrusterContext make_thruster_context(const model::InvSimParams& p, const model::InvSimFaultSet& faults,
                                      model::InvSimInverseModel inverse_model) {
  ThrusterContext t{};
  for (int axis = 0; axis < 3; ++axis) {
    for (int d : {1, -1}) {
      t.translation[axis][dir_index(d)] = translation_wrench(p, faults, axis, d);
      t.u_max_nominal[axis][dir_index(d)] = nominal_translation_accel(p, axis, d);
      t.u_max_pilot[axis][dir_index(d)] = inverse_model == model::InvSimInverseModel::kFaulted
                                              ? translation_accel(p, faults, axis, d)
                                              : t.u_max_nominal[axis][dir_index(d)];
      t.attitude[axis][dir_index(d)] = attitude_wrench(p, faults, axis, d);
    }
    const Wrench nominal = attitude_wrench(p, model::InvSimFaultSet{}, axis, 1);
    t.a0_radps2(axis) = nominal.torque_body_Nm(axis) / p.inertia_kgm2(axis, axis);
  }
  return t;
}

// Everything derived once from the parameters and the fault set.
struct RunContext {
  RvdConstants rvd;
  InverseModel inverse;
  model::InvSimPaperReadingParams choices;  // the reading's flight choices (paper_reading.hpp)
  ThrusterContext thrusters;
  long steps;
  long sub_steps;  // attitude periods per IS step
};

// x_c of eq. 20 at time t: the approach (desired_trajectory.hpp), with the paper reading's
// lateral return (and brake) when it sets one.
Vec6 expected_state(const RunContext& c, const model::InvSimParams& p, double t) {
  Vec6 x_c = desired_state(p.trajectory, p.r0_hill_m.x(), t);
  const double brake = c.choices.lateral_brake_mps2, time_constant = c.choices.lateral_time_constant_s;
  if (brake > 0.0)
    set_lateral_brake_then_return(brake, time_constant, p.r0_hill_m, p.v0_hill_mps, t, x_c);
  else if (time_constant > 0.0)
    set_lateral_return(time_constant, p.r0_hill_m, p.v0_hill_mps, t, x_c);
  return x_c;
}

// One step's pulses per body axis: what the inverse model commanded (counted under the reading)
// and what the groups fly in the step. The same unless openings are carried.
struct StepPulses {
  std::array<Pulse, 3> commanded{};
  std::array<Pulse, 3> flown{};
};

RunContext make_context(const model::InvSimParams& p, const model::InvSimFaultSet& faults) {
  RunContext c{};
  c.choices = flight_choices(p);
  c.steps = std::lround(p.duration_s / p.step_s);
  c.sub_steps = std::max(1L, std::lround(p.step_s / p.attitude.period_s));
  const double period_s = p.step_s / static_cast<double>(c.sub_steps);  // the longest piece
  c.rvd = make_rvd_constants(p.mu_m3ps2, p.radius_m(), p.mass_kg, p.inertia_kgm2, period_s);
  Vec6 weights;
  const std::array<double, 6>& q = reading_state_weights(p);
  for (int i = 0; i < 6; ++i) weights(i) = q[static_cast<std::size_t>(i)];
  c.inverse = make_inverse_model(c.rvd.dynamics.orbit.mean_motion_radps(), p.step_s, p.inverse.horizon_steps, weights);
  c.thrusters = make_thruster_context(p, faults, c.choices.inverse_model);
  return c;
}

// Steps 1-3: the measured state, the inverse model's acceleration and its pulses.
StepPulses inverse_link(const RunContext& c, const model::InvSimParams& p, const RvdState& s, double t,
                        MeasurementLink& link, std::array<CarriedOpening, 3>& carried, Vec3& u_body) {
  const Mat3 r_hill_from_body = s.q_hill_from_body.toRotationMatrix();
  Vec6 x;
  if (c.choices.measurement_noise.enabled()) {
    const double range_m = line_of_sight(s.r_hill_m, r_hill_from_body, p.sensor.position_body_m).range_m;
    x << link.measured_position_hill_m(s.r_hill_m, range_m), s.v_hill_mps;
  } else {
    x << s.r_hill_m, s.v_hill_mps;
  }
  const double horizon_end = t + p.step_s * p.inverse.horizon_steps;
  const Vec6 x_c = expected_state(c, p, horizon_end);
  const Vec3 u_hill = inverse_step(c.inverse, x, x_c);
  u_body = r_hill_from_body.transpose() * u_hill;  // eq. 8 inverted
  StepPulses out;
  const bool carry = c.choices.opening == model::InvSimOpening::kCarried;
  for (int axis = 0; axis < 3; ++axis) {
    const std::array<double, 2>& u_max_pilot = c.thrusters.u_max_pilot[axis];
    // Carried: only what the opening under way will not give (invsim/carried_opening.hpp).
    const double u = carry ? command_beyond_carried(carried[axis], u_max_pilot, p.step_s, u_body(axis)) : u_body(axis);
    const int d = dir_index(u >= 0.0 ? 1 : -1);
    const PulseParams pp{u_max_pilot[d], p.step_s, p.pulses.time_sensitivity,
                         p.pulses.acceleration_sensitivity, c.thrusters.u_max_nominal[axis][d]};
    // A group with no thrust left (faulted model): the inverse model commands nothing there.
    out.commanded[axis] =
        u_max_pilot[d] <= 0.0 ? Pulse{0, 0.0} : carry ? convert_to_opening(pp, u) : convert_to_pulse(pp, u);
    out.flown[axis] = carry ? open_for_step(carried[axis], out.commanded[axis], u_max_pilot, p.step_s)
                            : out.commanded[axis];
  }
  return out;
}

// Integrates one attitude period [offset, offset + h] of the step, split at every valve edge.
void propagate_period(const RunContext& c, const std::array<Pulse, 3>& translation, double offset,
                      double h, const std::array<PhasePlaneCommand, 3>& attitude, RvdState& s,
                      double& translation_fuel_Ns, double& attitude_fuel_Ns) {
  std::array<double, 7> edges{};
  std::size_t n = 0;
  for (int axis = 0; axis < 3; ++axis) {
    edges[n++] = std::clamp(translation[axis].on_time_s - offset, 0.0, h);
    edges[n++] = std::clamp(attitude[axis].on_time_s, 0.0, h);
  }
  edges[n++] = h;
  std::sort(edges.begin(), edges.end());
  double start = 0.0;
  for (double end : edges) {
    if (end <= start) continue;
    Wrench w;
    for (int axis = 0; axis < 3; ++axis) {
      const Pulse& tp = translation[axis];
      if (tp.direction != 0 && start < tp.on_time_s - offset) {
        const Wrench& g = c.thrusters.translation[axis][dir_index(tp.direction)];
        w.force_body_N += g.force_body_N;
        w.torque_body_Nm += g.torque_body_Nm;
        translation_fuel_Ns += g.thrust_sum_N * (end - start);
      }
      const PhasePlaneCommand& ap = attitude[axis];
      if (ap.direction != 0 && start < ap.on_time_s) {
        const Wrench& g = c.thrusters.attitude[axis][dir_index(ap.direction)];
        w.force_body_N += g.force_body_N;
        w.torque_body_Nm += g.torque_body_Nm;
        attitude_fuel_Ns += g.thrust_sum_N * (end - start);
      }
    }
    propagate_piece(c.rvd, w.force_body_N, w.torque_body_Nm, end - start, s);
    start = end;
  }
}

// Step 5 for one instant: line of sight and attitude against the limits; returns the Euler angles.
Vec3 record_limits(const model::InvSimParams& p, const RvdState& s, InvSimResult& r) {
  const Mat3 r_hill_from_body = s.q_hill_from_body.toRotationMatrix();
  const Vec3 euler = euler321_from_matrix(r_hill_from_body);
  const LineOfSight los = line_of_sight(s.r_hill_m, r_hill_from_body, p.sensor.position_body_m);
  r.peak_azimuth_rad = std::max(r.peak_azimuth_rad, std::abs(los.azimuth_rad));
  r.peak_elevation_rad = std::max(r.peak_elevation_rad, std::abs(los.elevation_rad));
  r.peak_attitude_rad = r.peak_attitude_rad.cwiseMax(euler.cwiseAbs());
  if (!target_in_view(los, p.sensor.azimuth_limit_rad, p.sensor.elevation_limit_rad))
    r.target_always_in_view = false;
  if (euler.cwiseAbs().maxCoeff() > p.sensor.attitude_limit_rad) r.attitude_within_limits = false;
  return euler;
}

// Step 4: the outer loop over one IS step. `euler` holds the Euler angles of s on entry and on
// return: the angles record_limits takes at the end of a period are the next period's start.
void forward_step(const RunContext& c, const model::InvSimParams& p,
                  const std::array<Pulse, 3>& pulses, RvdState& s, InvSimResult& r,
                  double& translation_fuel_Ns, double& attitude_fuel_Ns, Vec3& euler) {
  const double h = p.step_s / static_cast<double>(c.sub_steps);
  for (long j = 0; j < c.sub_steps; ++j) {
    const Vec3 rate = relative_rate_body(c.rvd, s);
    std::array<PhasePlaneCommand, 3> attitude{};
    for (int axis = 0; axis < 3; ++axis) {
      attitude[axis] = step_phase_plane(p.attitude, c.thrusters.a0_radps2(axis), euler(axis), rate(axis));
      if (attitude[axis].direction != 0) r.attitude_on_time_s(axis) += std::clamp(attitude[axis].on_time_s, 0.0, h);
    }
    propagate_period(c, pulses, static_cast<double>(j) * h, h, attitude, s, translation_fuel_Ns,
                     attitude_fuel_Ns);
    euler = record_limits(p, s, r);
  }
}

bool finite_and_near(const RvdState& s) {
  return s.r_hill_m.allFinite() && s.v_hill_mps.allFinite() && s.omega_body_radps.allFinite() &&
         s.r_hill_m.norm() < kDivergedRangeM;
}

RvdState initial_state(const RunContext& c, const model::InvSimParams& p) {
  RvdState s;
  s.r_hill_m = p.r0_hill_m;
  s.v_hill_mps = p.v0_hill_mps;
  s.q_hill_from_body = Quat(matrix_from_euler321(p.euler0_rad));
  s.omega_body_radps = p.omega0_rel_body_radps + s.q_hill_from_body.toRotationMatrix().transpose() *
                                                   omega_hill_in_hill(c.rvd.dynamics.orbit.mean_motion_radps());
  return s;
}

void finish_result(const model::InvSimParams& p, const RvdState& s, double translation_fuel_Ns,
                   double attitude_fuel_Ns, InvSimResult& r) {
  for (const AxisPulses& a : r.pulses) r.total_pulses += a.count[0] + a.count[1];
  r.k_p = static_cast<double>(r.total_pulses) / p.pulses.basic_pulse_amount;  // eq. 22
  const double exhaust_Ns_per_kg = p.isp_s * kStandardGravity;
  r.attitude_propellant_kg = attitude_fuel_Ns / exhaust_Ns_per_kg;
  r.propellant_kg = (translation_fuel_Ns + attitude_fuel_Ns) / exhaust_Ns_per_kg;
  r.final_r_hill_m = s.r_hill_m;
  r.final_v_hill_mps = s.v_hill_mps;
  const Vec3 offset = s.r_hill_m - Vec3(p.trajectory.dock_x_m, 0.0, 0.0);
  r.docked = !r.diverged && (offset.cwiseAbs().array() <= 0.5 * p.envelope_m.array()).all();
}

}  // namespace

std::vector<double> thruster_signature(const model::InvSimParams& p, const model::InvSimFaultSet& faults) {
  return make_thruster_context(p, faults, flight_choices(p).inverse_model).values();
}

InvSimResult run_inverse_simulation(const model::InvSimParams& p,
                                    const model::InvSimFaultSet& faults,
                                    std::vector<InvSimSample>* history) {
  const RunContext c = make_context(p, faults);
  RvdState s = initial_state(c, p);
  InvSimResult r;
  double translation_fuel_Ns = 0.0, attitude_fuel_Ns = 0.0;
  MeasurementLink link(c.choices.measurement_noise);
  std::array<CarriedOpening, 3> carried{};
  Vec3 euler = euler321_from_matrix(s.q_hill_from_body.toRotationMatrix());  // kept by forward_step
  for (long k = 0; k < c.steps; ++k) {
    const double t = static_cast<double>(k) * p.step_s;
    Vec3 u_body;
    const StepPulses step = inverse_link(c, p, s, t, link, carried, u_body);
    const std::array<Pulse, 3>& pulses = step.flown;
    std::array<int, 3> counted{};
    for (int axis = 0; axis < 3; ++axis) {
      AxisPulses& a = r.pulses[axis];
      if (step.commanded[axis].direction != 0) {
        counted[axis] = counted_pulses(p.pulses, step.commanded[axis]);
        a.count[dir_index(step.commanded[axis].direction)] += counted[axis];
      }
      if (pulses[axis].direction != 0) a.on_time_s[dir_index(pulses[axis].direction)] += pulses[axis].on_time_s;
    }
    if (history != nullptr) {
      const LineOfSight los =
          line_of_sight(s.r_hill_m, s.q_hill_from_body.toRotationMatrix(), p.sensor.position_body_m);
      const Vec6 x_d = expected_state(c, p, t);
      history->push_back({t, s.r_hill_m, s.v_hill_mps, x_d.head<3>(), euler, los.azimuth_rad,
                          los.elevation_rad, u_body,
                          {step.commanded[0].direction, step.commanded[1].direction, step.commanded[2].direction},
                          counted});
    }
    forward_step(c, p, pulses, s, r, translation_fuel_Ns, attitude_fuel_Ns, euler);
    if (!finite_and_near(s)) {
      r.diverged = true;
      break;
    }
  }
  finish_result(p, s, translation_fuel_Ns, attitude_fuel_Ns, r);
  return r;
}

}  // namespace chaser::invsim
