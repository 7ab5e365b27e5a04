// chaser.Simulation (step by step): one run advanced period by period from Python, its
// truth, estimate and command read between periods, faults injected at run time, and periods flown
// by a Python flight callback that sees the measurements only. The run itself is sim::Simulation,
// the object run_scenario flies, so stepping to the end gives chaser.run's bits.
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "python/module/module.hpp"
#include "sim/simulation.hpp"
#include "sim/summary.hpp"
#include "sim/user_flight.hpp"

namespace chaser::python {

namespace {

template <typename Vector>
py::array_t<double> array(const Vector& v) {
  py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
  for (py::ssize_t i = 0; i < a.size(); ++i) a.mutable_data()[i] = v[static_cast<Eigen::Index>(i)];
  return a;
}

// (w, x, y, z), as in telemetry.csv.
py::array_t<double> quaternion(const Quat& q) { return array(Eigen::Vector4d(q.w(), q.x(), q.y(), q.z())); }

// The flight side's view of one period: the measurements, the time, and the LVLH frame the flight
// software believes (its own orbit model, FlightParams::orbit), nothing of the truth.
py::dict measurements_dict(const model::SensorMeasurements& m, std::int64_t period, const model::TargetOrbit& orbit) {
  py::dict d;
  d["t_s"] = to_seconds(m.t);
  d["period"] = period;
  d["q_inertial_from_lvlh"] = quaternion(orbit.q_inertial_from_lvlh(to_seconds(m.t)));
  d["r_lvlh_m"] = array(m.r_lvlh_m);
  d["lidar_valid"] = m.lidar_valid;
  d["q_inertial_from_body"] = quaternion(m.q_inertial_from_body);
  d["omega_body_radps"] = array(m.omega_body_radps);
  d["propellant_used_kg"] = m.propellant_used_kg;
  return d;
}

class Simulation {
 public:
  Simulation(const Scenario& loaded, std::optional<std::uint64_t> seed, const std::vector<std::string>& channels)
      : loaded_(loaded) {
    if (seed) loaded_.scenario.seed = *seed;
    check_channels(loaded_.scenario, channels);
    py::gil_scoped_release released;
    flight_params_ = std::make_unique<flight::FlightParams>(flight::make_flight_params(loaded_.scenario));
    const sim::RunOptions options{.telemetry_path = {}, .telemetry_channels = channels, .telemetry_rows = &rows_,
                                  .record_glr_per_second = false};
    sim_ = std::make_unique<sim::Simulation>(loaded_.scenario, *flight_params_, options);
  }
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  // n periods (fewer where the run ends), by Chaser's flight software or by `flight`.
  void step(std::int64_t n, const py::object& flight) {
    if (n < 0) throw py::value_error("n_periods: must be >= 0 (got " + std::to_string(n) + ")");
    if (result_) throw std::runtime_error("the run is finished: result() was called");
    if (flight.is_none()) return step_chaser(n);
    for (std::int64_t i = 0; i < n && !sim_->done(); ++i) step_user(flight);
  }

  double t() const { return sim_->t_s(); }
  // The mission phase of the next period (sim/run_phases.hpp): the one the run is in.
  std::string phase() const {
    return sim_->phases().phases[static_cast<std::size_t>(sim_->phase())].name;
  }
  std::int64_t period() const { return sim_->period(); }
  bool done() const { return sim_->done(); }

  py::dict truth() const {
    const plant::RigidState& chaser = plant::chaser_state(sim_->plant());
    py::dict d;
    d["t_s"] = sim_->t_s();
    d["r_lvlh_m"] = array(chaser.r_lvlh_m);
    d["v_lvlh_mps"] = array(chaser.v_lvlh_mps);
    d["q_inertial_from_body"] = quaternion(chaser.q_inertial_from_body);
    d["omega_body_radps"] = array(chaser.omega_body_radps);
    d["mass_kg"] = chaser.mass_kg;
    d["propellant_used_kg"] = sim_->plant().state.propellant_used_kg;
    return d;
  }

  // The last period's: None before the first.
  py::object estimate() const {
    if (!last_) return py::none();
    const flight::NavEstimate& e = last_->estimate;
    py::dict d;
    d["t_s"] = last_t_s_;
    d["r_lvlh_m"] = array(e.r_lvlh_m);
    d["v_lvlh_mps"] = array(e.v_lvlh_mps);
    d["q_inertial_from_body"] = quaternion(e.q_inertial_from_body);
    d["omega_body_radps"] = array(e.omega_body_radps);
    return d;
  }

  py::object command() const {
    if (!last_) return py::none();
    const int n = loaded_.scenario.thrusters.count;
    py::dict d;
    d["t_s"] = last_t_s_;
    d["on_times"] = array(Eigen::Map<const Eigen::VectorXd>(last_->command.ton.data(), n));
    d["latch_closed_groups"] = last_->command.latch_closed_groups;
    d["force_demand_lvlh_N"] = array(last_->force_demand_lvlh_N);
    d["torque_demand_body_Nm"] = array(last_->torque_demand_body_Nm);
    d["released_wrench"] = array(last_->released_wrench);
    d["commanded_wrench"] = array(last_->commanded_wrench);
    d["allocation_feasible"] = last_->allocation_feasible;
    return d;
  }

  void inject_fault(const std::string& thruster, const std::string& kind, std::optional<double> size,
                    std::optional<double> onset_s, std::optional<double> leak_slope_per_s);

  py::object result() {
    if (!sim_->done()) throw std::runtime_error("the run is not finished: step until sim.done first");
    if (!result_) {
      sim::RunResult run;
      {
        py::gil_scoped_release released;
        run = sim_->finish();
      }
      result_ = py::cast(run_result(sim::run_summary(loaded_.scenario, loaded_.hash, run).dump(2) + "\n",
                                    sim::summary_text(loaded_.scenario, run), rows_));
    }
    return *result_;
  }

  int thruster_count() const { return loaded_.scenario.thrusters.count; }
  double control_period_s() const { return loaded_.scenario.control_period_s; }

 private:
  Scenario loaded_;  // the scenario flown: its seed, the faults injected so far
  std::unique_ptr<flight::FlightParams> flight_params_;
  sim::TelemetryRows rows_;
  std::unique_ptr<sim::Simulation> sim_;
  std::optional<flight::FlightOutput> last_;  // of the last period flown
  double last_t_s_ = 0;                       // [s] its start
  std::optional<py::object> result_;

  void step_chaser(std::int64_t n) {
    if (n == 0 || sim_->done()) return;
    py::gil_scoped_release released;
    for (std::int64_t i = 1; i < n && !sim_->done(); ++i) sim_->step();
    if (!sim_->done()) fly(flight::step_flight(sim_->flight_params(), sim_->flight_state(), sim_->begin_period()));
  }

  void fly(const flight::FlightOutput& out) {
    last_t_s_ = sim_->t_s();
    last_ = out;
    sim_->end_period(out);
  }

  void step_user(const py::object& flight);
};

// As NumPy writes a shape: (5,) or (2,3).
std::string shape_text(const py::array& a) {
  std::string text = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i)
    text += std::to_string(a.shape(i)) + (a.ndim() == 1 || i + 1 < a.ndim() ? "," : "");
  return text + ")";
}

// One period flown by a Python callable: it gets the measurements, returns a wrench demand [Fx, Fy,
// Fz, Cx, Cy, Cz] (body axes, N and N m) or the thrusters' on-times (fractions of the period), as a
// bare sequence told apart by its length, or as {"wrench": ...} / {"on_times": ...}.
void Simulation::step_user(const py::object& flight) {
  const model::SensorMeasurements& meas = sim_->begin_period();
  const double t_s = to_seconds(meas.t);
  const int count = loaded_.scenario.thrusters.count;
  const auto at = [t_s] { return fmt::format("flight callback at t = {:.10g} s: ", t_s); };  // built on an error only
  py::object returned = flight(measurements_dict(meas, sim_->period(), sim_->flight_params().orbit));

  std::string form;  // "wrench" or "on_times", when the return says
  if (py::isinstance<py::dict>(returned)) {
    const py::dict d = returned.cast<py::dict>();
    if (d.size() != 1 || !(d.contains("wrench") || d.contains("on_times")))
      throw py::value_error(at() + "a returned dict has one key, 'wrench' or 'on_times'");
    form = d.contains("wrench") ? "wrench" : "on_times";
    returned = d[form.c_str()];
  }
  py::array_t<double> values;
  try {
    values = py::array_t<double, py::array::forcecast>::ensure(returned);
  } catch (const py::error_already_set&) {
  }
  if (!values || returned.is_none())
    throw py::type_error(at() + "returned " + py::str(py::type::of(returned)).cast<std::string>() +
                         ", not numbers: a wrench [Fx, Fy, Fz, Cx, Cy, Cz] or on-times of the " +
                         std::to_string(count) + " thrusters");
  const py::ssize_t n = values.ndim() == 1 ? values.shape(0) : -1;
  if (form.empty()) {
    if (n == 6 && count == 6)
      throw py::value_error(at() + "6 values with 6 thrusters is ambiguous: return {'wrench': w} or {'on_times': t}");
    form = n == 6 ? "wrench" : n == count ? "on_times" : "";
  }
  const py::ssize_t wanted = form == "wrench" ? 6 : count;
  if (form.empty() || n != wanted)
    throw py::value_error(at() + "returned an array of shape " + shape_text(values) +
                          (form.empty() ? ": a wrench [Fx, Fy, Fz, Cx, Cy, Cz] (6 values) or on-times of the " +
                                              std::to_string(count) + " thrusters (" + std::to_string(count) + " values)"
                                        : ": " + form + " has " + std::to_string(wanted) + " values"));
  const double* v = values.data();
  for (py::ssize_t i = 0; i < n; ++i) {
    if (!std::isfinite(v[i]))
      throw py::value_error(at() + fmt::format("{}[{}] is not finite ({})", form, i, v[i]));
    if (form == "on_times" && !(v[i] >= 0.0 && v[i] <= 1.0))
      throw py::value_error(at() + fmt::format("on_times[{}] (T{}) must be in [0, 1], a fraction of the period (got {})",
                                               i, i + 1, v[i]));
  }
  if (form == "wrench") {
    fly(sim::wrench_flight_output(sim_->flight_params(), sim_->flight_state(), meas, Eigen::Map<const Vec6>(v)));
  } else {
    model::ThrusterOnTimes ton{};
    std::copy_n(v, count, ton.begin());
    fly(sim::on_times_flight_output(sim_->flight_params(), sim_->flight_state(), meas, ton));
  }
}

// The fault is checked as the scenario's faults section checks it, by loading the scenario again
// with it appended to that section (so every problem reads as in a file: faults.N.kind, ...); it
// must also not begin before the simulation's time, which a scenario cannot know.
void Simulation::inject_fault(const std::string& thruster, const std::string& kind, std::optional<double> size,
                              std::optional<double> onset_s, std::optional<double> leak_slope_per_s) {
  if (result_) throw std::runtime_error("the run is finished: result() was called");
  const double now = sim_->t_s();
  const double onset = onset_s.value_or(now);
  if (onset < now)
    throw py::value_error(fmt::format("onset_s: must be >= the simulation's time t = {:.10g} s (got {})", now, onset));
  py::dict fault;
  fault["thruster"] = thruster;
  fault["kind"] = kind;
  fault["onset_s"] = onset;
  if (size && (kind == "stuck_open" || kind == "stuck_closed"))
    throw py::value_error("size: only for leak (leak_size) and loss (loss_size) faults (kind here is " + kind + ")");
  if (size && (kind == "leak" || kind == "loss")) fault[kind == "leak" ? "leak_size" : "loss_size"] = *size;
  if (leak_slope_per_s) fault["leak_slope_per_s"] = *leak_slope_per_s;
  py::list faults = py::module_::import("yaml").attr("safe_load")(loaded_.canonical_yaml)["faults"];
  faults.append(fault);
  py::dict overrides;
  overrides["faults"] = faults;
  Scenario reloaded = with_overrides(loaded_, override_strings(overrides));
  sim_->add_fault(reloaded.scenario.faults.back());
  loaded_.scenario.faults = reloaded.scenario.faults;
  loaded_.hash = reloaded.hash;
  loaded_.canonical_yaml = reloaded.canonical_yaml;
}

}  // namespace

void add_simulation(py::module_& m) {
  py::class_<Simulation>(m, "Simulation",
                         "One run of a scenario advanced period by period (docs/python.md): the run chaser.run flies.")
      .def(py::init<const Scenario&, std::optional<std::uint64_t>, const std::vector<std::string>&>(),
           py::arg("scenario"), py::arg("seed") = py::none(), py::arg("channels") = std::vector<std::string>{},
           "seed replaces the scenario's; channels as for chaser.run (the telemetry result() holds)")
      .def("step", &Simulation::step, py::arg("n_periods") = 1, py::arg("flight") = py::none(),
           "Fly n periods (fewer if the run ends): by Chaser's flight software, or by flight(measurements) "
           "returning a body-axes wrench [Fx, Fy, Fz, Cx, Cy, Cz] (N, N m) or the thrusters' on-times (0..1).")
      .def_property_readonly("t", &Simulation::t, "[s] the time of the next period's start")
      .def_property_readonly("period", &Simulation::period, "index of the next period to fly")
      .def_property_readonly("phase", &Simulation::phase,
                             "the mission phase the run is in (summary's phases_flown lists those flown)")
      .def_property_readonly("done", &Simulation::done, "every period flown, or the run stopped (diverged)")
      .def_property_readonly("thruster_count", &Simulation::thruster_count)
      .def_property_readonly("control_period_s", &Simulation::control_period_s)
      .def("truth", &Simulation::truth, "the chaser's true state at t (dict of NumPy arrays and floats)")
      .def("estimate", &Simulation::estimate, "the navigation estimate of the last period flown (None before)")
      .def("command", &Simulation::command, "the thruster command and demands of the last period flown (None before)")
      .def("inject_fault", &Simulation::inject_fault, py::arg("thruster"), py::arg("kind"), py::arg("size") = py::none(),
           py::arg("onset_s") = py::none(), py::arg("leak_slope_per_s") = py::none(),
           "A thruster fault from onset_s (None: now), checked as the scenario's faults section is.")
      .def("result", &Simulation::result, "After the end: the chaser.RunResult chaser.run gives.");
}

}  // namespace chaser::python
