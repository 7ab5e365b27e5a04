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

// Thruster indices 1..8 of branch A in telemetry, 0 for none.
void add(TelemetryWriter& w, const flight::fdi::FdiSchemeOutput& s) {
  add(w, s.residual);
  w.add(s.glr.value());
  w.add(s.alarm);
  w.add(s.candidate + 1);
  w.add(s.confirmed + 1);
}

void add(TelemetryWriter& w, const Quat& q) {
  w.add(q.w()), w.add(q.x()), w.add(q.y()), w.add(q.z());
}

}  // namespace

std::vector<std::string> telemetry_channels() {
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
  for (int i = 1; i <= model::kThrustersPerBranch; ++i) n.push_back(fmt::format("ton_cmd_{}", i));
  for (int i = 1; i <= model::kThrustersPerBranch; ++i) n.push_back(fmt::format("ton_real_{}", i));
  for (const char* scheme : {"position", "attitude"}) {
    for (int i = 1; i <= 3; ++i) n.push_back(fmt::format("residual_{}_{}", scheme, i));
    n.push_back(fmt::format("glr_{}", scheme));
    n.push_back(fmt::format("alarm_{}", scheme));
    n.push_back(fmt::format("candidate_{}", scheme));
    n.push_back(fmt::format("confirmed_{}", scheme));
  }
  for (const char* name : {"glr_deficit", "alarm_deficit", "candidate_deficit", "confirmed_deficit"}) n.push_back(name);
  n.push_back("over_consumption");
  n.push_back("active_branch");
  n.push_back("delay_s");
  n.push_back("mass_kg");
  n.push_back("propellant_used_kg");
  return n;
}

void record_period(TelemetryWriter& w, double t_s, const plant::RigidState& x, const plant::PlantState& plant,
                   const flight::FlightOutput& f, int active_branch, const Vec3& attitude_error_body_rad,
                   const Quat& q_inertial_from_target) {
  w.add(t_s);
  add(w, x.r_lvlh_m), add(w, x.v_lvlh_mps), add(w, x.q_inertial_from_body), add(w, x.omega_body_radps);
  add(w, q_inertial_from_target);
  add(w, f.estimate.r_lvlh_m), add(w, f.estimate.v_lvlh_mps), add(w, f.estimate.q_inertial_from_body);
  add(w, f.estimate.omega_body_radps);
  add(w, f.reference.r_lvlh_m), add(w, attitude_error_body_rad);
  add(w, f.force_demand_lvlh_N), add(w, f.torque_demand_body_Nm);
  add(w, Vec3(f.commanded_wrench.head<3>())), add(w, Vec3(f.commanded_wrench.tail<3>()));
  for (int i = 0; i < model::kThrustersPerBranch; ++i) w.add(f.ton_active[i]);
  for (int i = 0; i < model::kThrustersPerBranch; ++i) w.add(plant.last_profile.ton_realised[model::branch_first(active_branch) + i]);
  add(w, f.fdir.position), add(w, f.fdir.attitude);
  w.add(f.fdir.detector.glr.value()), w.add(f.fdir.detector.alarm);
  w.add(f.fdir.detector.candidate + 1), w.add(f.fdir.detector.confirmed + 1);
  w.add(f.fdir.over_consumption);
  w.add(active_branch);
  w.add(to_seconds(plant.last_delay_ns));
  w.add(x.mass_kg);
  w.add(plant.propellant_used_kg);
  w.end_row();
}

}  // namespace chaser::sim
