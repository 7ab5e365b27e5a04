#include "campaign/rigidise_study.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>

#include "campaign/statistics.hpp"
#include "core/random.hpp"
#include "flight/flight_software.hpp"
#include "sim/simulation.hpp"

namespace chaser::campaign {

namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

std::array<double, model::kArmJoints> draw_start(const RigidiseStart& start, RandomStream& random) {
  std::array<double, model::kArmJoints> rate{};
  for (double& w : rate)
    w = start.every_joint ? (random.uniform() < 0.5 ? -start.mean_degps : start.mean_degps)
                          : random.normal(start.mean_degps, start.sd_degps);
  return rate;
}

RigidiseRun fly_from(const sim::Simulation& base, std::int64_t periods, const RigidiseStart& start, RandomStream random) {
  RigidiseRun run;
  run.start_rate_degps = draw_start(start, random);
  try {
    sim::Simulation fork(base, periods);
    std::array<double, model::kArmJoints> rate_radps{};
    for (std::size_t j = 0; j < rate_radps.size(); ++j) rate_radps[j] = run.start_rate_degps[j] / kDegPerRad;
    fork.set_closed_chain_joint_rates(rate_radps);
    while (!fork.done()) fork.step();
    const sim::RunResult result = fork.finish();
    const sim::RigidiseResult& r = result.reach.rigidise;
    if (!r.flown) throw std::runtime_error("the rigidisation was not flown");
    for (std::size_t j = 0; j < run.angle_error_deg.size(); ++j) {
      run.angle_error_deg[j] = kDegPerRad * r.final_angle_error_rad[j];
      run.rate_degps[j] = kDegPerRad * r.final_rate_radps[j];
      run.peak_torque_Nm[j] = r.peak_torque_Nm[j];
    }
  } catch (const std::exception& e) {
    run.error = e.what();
  }
  return run;
}

struct Moments {
  double mean = 0.0, sd = 0.0, largest = 0.0;
  int count = 0;
};

// Mean, sample standard deviation (campaign/statistics.hpp's running sums; 0 below two values) and
// largest magnitude of `value(run, joint)` over every joint of every run flown.
template <class F>
Moments moments(const RigidiseColumn& column, F value) {
  RunningStats stats;
  Moments m;
  for (const RigidiseRun& run : column.runs) {
    if (!run.error.empty()) continue;
    for (std::size_t j = 0; j < run.angle_error_deg.size(); ++j) {
      const double v = value(run, j);
      stats.add(v);
      m.largest = std::max(m.largest, std::abs(v));
    }
  }
  m.count = static_cast<int>(stats.count());
  if (m.count > 0) m.mean = stats.mean();
  if (m.count > 1) m.sd = stats.sample_std();
  return m;
}

int flown(const RigidiseColumn& column) {
  return static_cast<int>(std::ranges::count_if(column.runs, [](const RigidiseRun& r) { return r.error.empty(); }));
}

std::array<double, model::kArmJoints> peak_torques(const RigidiseColumn& column) {
  std::array<double, model::kArmJoints> peak{};
  for (const RigidiseRun& run : column.runs)
    if (run.error.empty())
      for (std::size_t j = 0; j < peak.size(); ++j) peak[j] = std::max(peak[j], run.peak_torque_Nm[j]);
  return peak;
}

Moments angle_moments(const RigidiseColumn& c) {
  return moments(c, [](const RigidiseRun& r, std::size_t j) { return std::abs(r.angle_error_deg[j]); });
}
Moments rate_moments(const RigidiseColumn& c) {
  return moments(c, [](const RigidiseRun& r, std::size_t j) { return std::abs(r.rate_degps[j]); });
}
Moments start_moments(const RigidiseColumn& c) {
  return moments(c, [](const RigidiseRun& r, std::size_t j) { return r.start_rate_degps[j]; });
}

std::string joined(const std::array<double, model::kArmJoints>& v, const char* format) {
  std::string out;
  for (std::size_t j = 0; j < v.size(); ++j) out += (j ? ", " : "") + fmt::format(fmt::runtime(format), v[j]);
  return out;
}

}  // namespace

std::vector<RigidiseColumnSpec> comrade_table7_columns(int runs) {
  return {{.name = "hinf", .law = model::RigidiseLaw::kHinf, .start = {.every_joint = false, .mean_degps = 0.14, .sd_degps = 0.20},
           .runs = runs},
          {.name = "compliance", .law = model::RigidiseLaw::kCompliance, .start = {.every_joint = true, .mean_degps = 1.0},
           .runs = runs}};
}

RigidiseColumn run_rigidise_column(const model::Scenario& scenario, const RigidiseColumnSpec& spec, int threads) {
  if (!scenario.capture || !scenario.capture->rigidise)
    throw std::invalid_argument("the scenario has no capture.rigidise section: nothing to rigidise");
  // The column's law, the brakes held off (never quiet for long enough), and room for the runs
  // after the capture, wherever it comes.
  model::Scenario s = scenario;
  s.capture->rigidise->law = spec.law;
  s.capture->rigidise->brake_dwell_s = std::numeric_limits<double>::infinity();
  s.capture->stabilise.reset();
  s.duration_s += spec.duration_s;
  const flight::FlightParams flight = flight::make_flight_params(s);
  sim::Simulation base(s, flight, sim::RunOptions{});
  const auto& phases = base.phases().phases;
  const auto rigidisation = std::ranges::find_if(phases, [](const sim::PhaseSpec& p) { return p.name == "rigidisation"; });
  if (rigidisation == phases.end()) throw std::invalid_argument("the scenario's phases have no rigidisation");
  const int rigidisation_index = static_cast<int>(rigidisation - phases.begin());
  while (!base.done() && base.phase() != rigidisation_index) base.step();
  if (base.phase() != rigidisation_index)
    throw std::runtime_error(fmt::format("the capture was not made by {} s: no rigidisation to start from", base.t_s()));

  RigidiseColumn column{.spec = spec, .start_s = base.t_s(), .runs = std::vector<RigidiseRun>(static_cast<std::size_t>(spec.runs))};
  const std::int64_t periods = base.period() + std::llround(spec.duration_s / s.control_period_s);
  std::atomic<int> next{0};
  const auto worker = [&] {
    for (int i = next++; i < spec.runs; i = next++)
      column.runs[static_cast<std::size_t>(i)] =
          fly_from(base, periods, spec.start, RandomStream(s.seed, fmt::format("comrade-rigidise/{}/{}", spec.name, i)));
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < std::max(1, threads); ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  return column;
}

std::string rigidise_markdown(const std::vector<RigidiseColumn>& columns) {
  const auto cell = [&](auto f) {
    std::string row;
    for (const RigidiseColumn& c : columns) row += " | " + f(c);
    return row;
  };
  const auto pm = [](const Moments& m, int digits) { return fmt::format("{:.{}f} +- {:.{}f}", m.mean, digits, m.sd, digits); };
  std::string out = "| figure | COMRADE H-inf | COMRADE compliant" + cell([](const RigidiseColumn& c) { return c.spec.name; }) +
                    " |\n|---|---|---" + cell([](const RigidiseColumn&) { return std::string("---"); }) + "|\n";
  out += "| joint angle from q_d at the end, mean +- sd of the magnitude over joints and runs [deg] | 1.618 +- 0.809 | "
         "2.710 +- 1.169" + cell([&](const RigidiseColumn& c) { return pm(angle_moments(c), 3); }) + " |\n";
  out += "| joint rate at the end [deg/s] | 0.016 +- 0.013 | 0.078 +- 0.030" +
         cell([&](const RigidiseColumn& c) { return pm(rate_moments(c), 4); }) + " |\n";
  out += "| initial joint rate [deg/s] | 0.14 +- 0.20 (largest 3.02) | 1 on every joint" + cell([&](const RigidiseColumn& c) {
           const Moments m = start_moments(c);
           return c.spec.start.every_joint ? fmt::format("+-{:g} on every joint", c.spec.start.mean_degps)
                                           : fmt::format("{} (largest {:.2f})", pm(m, 2), m.largest);
         }) + " |\n";
  out += "| peak torque per joint 1-7, largest over the runs [N m] | 3.87, 12.23, 3.42, 29.80, 12.28, 8.11, 28.10 | "
         "10.94, 12.89, 19.83, 50.10, 17.16, 23.32, 41.45" +
         cell([&](const RigidiseColumn& c) { return joined(peak_torques(c), "{:.2f}"); }) + " |\n";
  out += "| simulated time [s] | 120 | 120" + cell([](const RigidiseColumn& c) { return fmt::format("{:g}", c.spec.duration_s); }) + " |\n";
  out += "| runs flown of runs | |" +
         cell([](const RigidiseColumn& c) { return fmt::format("{} of {}", flown(c), c.runs.size()); }) + " |\n";
  return out;
}

std::string rigidise_csv(const std::vector<RigidiseColumn>& columns) {
  std::string out = "column,figure,value\n";
  for (const RigidiseColumn& c : columns) {
    const Moments angle = angle_moments(c), rate = rate_moments(c), start = start_moments(c);
    out += fmt::format("{0},angle_mean_deg,{1}\n{0},angle_sd_deg,{2}\n{0},rate_mean_deg_s,{3}\n{0},rate_sd_deg_s,{4}\n"
                       "{0},start_every_joint,{5}\n{0},start_mean_deg_s,{6}\n{0},start_sd_deg_s,{7}\n"
                       "{0},start_largest_deg_s,{8}\n{0},duration_s,{9}\n",
                       c.spec.name, angle.mean, angle.sd, rate.mean, rate.sd, c.spec.start.every_joint ? 1 : 0, start.mean,
                       start.sd, start.largest, c.spec.duration_s);
    const auto peak = peak_torques(c);
    for (std::size_t j = 0; j < peak.size(); ++j) out += fmt::format("{},peak_torque_{}_Nm,{}\n", c.spec.name, j + 1, peak[j]);
    out += fmt::format("{},runs_flown,{}\n{},runs,{}\n", c.spec.name, flown(c), c.spec.name, c.runs.size());
  }
  return out;
}

std::string rigidise_runs_csv(const RigidiseColumn& column) {
  std::string out = "run";
  for (const char* group : {"start_rate_deg_s", "angle_error_deg", "rate_deg_s", "peak_torque_Nm"})
    for (int j = 1; j <= model::kArmJoints; ++j) out += fmt::format(",{}_{}", group, j);
  out += ",error\n";
  for (std::size_t i = 0; i < column.runs.size(); ++i) {
    const RigidiseRun& r = column.runs[i];
    out += fmt::format("{}", i);
    for (const auto* values : {&r.start_rate_degps, &r.angle_error_deg, &r.rate_degps, &r.peak_torque_Nm})
      for (const double v : *values) out += fmt::format(",{}", v);
    std::string error = r.error;
    std::ranges::replace(error, ',', ';');
    std::ranges::replace(error, '\n', ' ');
    out += "," + error + "\n";
  }
  return out;
}

}  // namespace chaser::campaign
