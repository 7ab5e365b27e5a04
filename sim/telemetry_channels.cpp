#include "sim/telemetry_channels.hpp"

#include <fmt/format.h>

namespace chaser::sim {

namespace {

void add_vector_names(std::vector<std::string>& names, const char* base, const char* unit) {
  for (const char* axis : {"x", "y", "z"}) names.push_back(fmt::format("{}_{}_{}", base, axis, unit));
}

void add_quat_names(std::vector<std::string>& names, const char* base) {
  for (const char* c : {"w", "x", "y", "z"}) names.push_back(fmt::format("{}_{}", base, c));
}

void add(TelemetryWriter& w, const Vec3& v) {
  for (int i = 0; i < 3; ++i) w.add(v[i]);
}

// A lane of the watched set as a thruster number 1..N in telemetry, 0 for none.
int thruster_number(const flight::fdi::WatchedSet& watched, int lane) {
  return lane >= 0 ? watched.index[static_cast<std::size_t>(lane)] + 1 : 0;
}

void add(TelemetryWriter& w, const flight::fdi::FdiSchemeOutput& s, const flight::fdi::WatchedSet& watched) {
  add(w, s.residual);
  w.add(s.glr.value());
  w.add(s.alarm);
  w.add(thruster_number(watched, s.candidate));
  w.add(thruster_number(watched, s.confirmed));
}

void add(TelemetryWriter& w, const Quat& q) {
  w.add(q.w()), w.add(q.x()), w.add(q.y()), w.add(q.z());
}

}  // namespace

std::vector<std::string> telemetry_channels(int thrusters) {
  std::vector<std::string> n{"t_s"};
  add_vector_names(n, "r_lvlh", "m");
  add_vector_names(n, "v_lvlh", "mps");
  add_quat_names(n, "q_inertial_from_body");
  add_vector_names(n, "omega_body", "radps");
  add_quat_names(n, "q_inertial_from_target");
  add_vector_names(n, "r_est_lvlh", "m");
  add_vector_names(n, "v_est_lvlh", "mps");
  add_quat_names(n, "q_est_inertial_from_body");
  add_vector_names(n, "omega_est_body", "radps");
  add_vector_names(n, "r_ref_lvlh", "m");
  add_vector_names(n, "att_err_body", "rad");
  add_vector_names(n, "force_demand_lvlh", "N");
  add_vector_names(n, "torque_demand_body", "Nm");
  add_vector_names(n, "force_cmd_body", "N");
  add_vector_names(n, "torque_cmd_body", "Nm");
  for (int i = 1; i <= thrusters; ++i) n.push_back(fmt::format("ton_cmd_{}", i));
  for (int i = 1; i <= thrusters; ++i) n.push_back(fmt::format("ton_real_{}", i));
  for (const char* scheme : {"position", "attitude"}) {
    for (int i = 1; i <= 3; ++i) n.push_back(fmt::format("residual_{}_{}", scheme, i));
    n.push_back(fmt::format("glr_{}", scheme));
    n.push_back(fmt::format("alarm_{}", scheme));
    n.push_back(fmt::format("candidate_{}", scheme));
    n.push_back(fmt::format("confirmed_{}", scheme));
  }
  for (const char* name : {"glr_deficit", "alarm_deficit", "candidate_deficit", "confirmed_deficit"}) n.push_back(name);
  n.push_back("over_consumption");
  n.push_back("active_thrusters");
  n.push_back("delay_s");
  n.push_back("mass_kg");
  n.push_back("propellant_used_kg");
  return n;
}

void record_period(TelemetryWriter& w, double t_s, const plant::RigidState& x, const plant::PlantState& plant,
                   const flight::FlightOutput& f, const flight::FlightState& flight_state, int thrusters,
                   const flight::fdi::WatchedSet& watched, const Vec3& attitude_error_body_rad,
                   const Quat& q_inertial_from_target) {
  w.add(t_s);
  add(w, x.r_lvlh_m), add(w, x.v_lvlh_mps), add(w, x.q_inertial_from_body), add(w, x.omega_body_radps);
  add(w, q_inertial_from_target);
  add(w, f.estimate.r_lvlh_m), add(w, f.estimate.v_lvlh_mps), add(w, f.estimate.q_inertial_from_body);
  add(w, f.estimate.omega_body_radps);
  add(w, f.reference.r_lvlh_m), add(w, attitude_error_body_rad);
  add(w, f.force_demand_lvlh_N), add(w, f.torque_demand_body_Nm);
  add(w, Vec3(f.commanded_wrench.head<3>())), add(w, Vec3(f.commanded_wrench.tail<3>()));
  for (int i = 0; i < thrusters; ++i) w.add(f.command.ton[static_cast<std::size_t>(i)]);
  for (int i = 0; i < thrusters; ++i) w.add(plant.last_profile.ton_realised[static_cast<std::size_t>(i)]);
  add(w, f.fdir.position, watched), add(w, f.fdir.attitude, watched);
  w.add(f.fdir.detector.glr.value()), w.add(f.fdir.detector.alarm);
  w.add(thruster_number(watched, f.fdir.detector.candidate)), w.add(thruster_number(watched, f.fdir.detector.confirmed));
  w.add(f.fdir.over_consumption);
  w.add(static_cast<double>(flight_state.thrusters.active));  // exact: a 32-bit mask has at most 10 digits
  w.add(to_seconds(plant.last_delay_ns));
  w.add(x.mass_kg);
  w.add(plant.propellant_used_kg);
  w.end_row();
}

}  // namespace chaser::sim
