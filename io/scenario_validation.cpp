// Checks between keys: timing against the control period, inertia as a whole, the thruster set
// (io/thruster_set_validation.cpp), fault onsets, guidance geometry, H-infinity bandwidths against
// the period. Each check runs only if the keys it uses were read cleanly, so one bad value gives
// one error rather than a cascade.

#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include "io/scenario_sections.hpp"
#include "model/recovery.hpp"

namespace chaser::io {
namespace {

// Times are integer nanoseconds inside a run (core/time.hpp); a file time must be one to within
// rounding of its decimal text (1e-3 ns is far above double rounding of 1e8 s, 2e-8 ns relative).
constexpr double kWholeNsTolerance = 1e-3;  // [ns]
// Inertia: asymmetry and the triangle inequality are judged relative to the largest entry, at a
// level far above the rounding of a decimal file value and far below any physical asymmetry.
constexpr double kInertiaRelativeTolerance = 1e-9;
using model::kMaxSensorDelayPeriods;

std::optional<std::int64_t> whole_ns(double seconds) {
  const double ns = seconds * 1e9;
  const double rounded = std::round(ns);
  if (!(std::abs(ns - rounded) <= kWholeNsTolerance)) return std::nullopt;
  return static_cast<std::int64_t>(rounded);
}

// A thruster time that must lie in [0, T); valve times are also whole nanoseconds (the plant
// schedules valve edges in integer ns, plant/thruster_hardware.hpp).
void check_below_period(Diagnostics& d, const char* path, double value, double period_s,
                        bool whole_nanoseconds) {
  if (!d.clean(path)) return;
  if (!(value < period_s))
    d.add(path, fmt::format("must be in [0, control_period_s) = [0, {}) (got {})",
                            format_number(period_s), format_number(value)));
  else if (whole_nanoseconds && !whole_ns(value))
    d.add(path, fmt::format("must be a whole number of nanoseconds (got {})", format_number(value)));
}

// A sensor delay: a whole number k of control periods (the sample is delivered k periods late),
// k <= kMaxSensorDelayPeriods (the plant's delay line has that many slots).
void check_sensor_delay(Diagnostics& d, const char* path, double value, double period_s,
                        std::int64_t period_ns) {
  if (!d.clean(path)) return;
  const auto ns = whole_ns(value);
  if (!ns || *ns % period_ns != 0 || *ns / period_ns > kMaxSensorDelayPeriods)
    d.add(path, fmt::format("must be a whole multiple of control_period_s = {} in [0, {} periods] = "
                            "[0, {}] (got {})", format_number(period_s), kMaxSensorDelayPeriods,
                            format_number(kMaxSensorDelayPeriods * period_s), format_number(value)));
}

// A statistic of block changes (the impulse statistic, the observer bank): its window and baseline
// (keys <prefix>window_s and <prefix>baseline_s) at least a block each, and together, in whole
// blocks as the flight software rounds them (model::impulse_blocks), within the ring.
void check_block_windows(Diagnostics& d, const std::string& prefix, double window_s, double baseline_s, double period) {
  const std::string window = prefix + "window_s", baseline = prefix + "baseline_s";
  const double block_s = model::impulse_block_periods(period) * period;
  for (const std::string& key : {window, baseline}) {
    const double value = key == window ? window_s : baseline_s;
    if (d.clean(key) && value < block_s)
      d.add(key, fmt::format("must be >= one block of the statistic, {} s (got {})", format_number(block_s),
                             format_number(value)));
  }
  const int blocks = model::impulse_blocks(window_s, period) + model::impulse_blocks(baseline_s, period);
  if (d.clean(window) && d.clean(baseline) && blocks > model::kMaxImpulseBlocks)
    d.add(baseline, fmt::format("{}window_s + {}baseline_s must be <= {} s, {} blocks once each is rounded to whole "
                                "blocks (got {} blocks)",
                                prefix.substr(prefix.rfind('.') + 1), prefix.substr(prefix.rfind('.') + 1),
                                format_number(model::kMaxImpulseBlocks * block_s), model::kMaxImpulseBlocks, blocks));
}

// The deficit isolation's windows, in whole periods: at least one period before the alarm, two
// after it, the longest window holding both, and no longer than the on-board ring of samples.
void check_deficit_windows(Diagnostics& d, const model::DeficitParams& w, double period) {
  const char* keys[] = {"fdi.deficit.window_before_s", "fdi.deficit.window_after_s", "fdi.deficit.window_max_s"};
  for (const char* key : keys)
    if (!d.clean(key)) return;
  const double max_s = (model::kMaxDeficitWindowPeriods - 1) * period;
  if (w.window_before_s < period)
    d.add(keys[0], fmt::format("must be >= control_period_s = {} (got {})", format_number(period),
                               format_number(w.window_before_s)));
  if (w.window_after_s < 2 * period)
    d.add(keys[1], fmt::format("must be >= 2 control periods = {} (got {})", format_number(2 * period),
                               format_number(w.window_after_s)));
  if (w.window_max_s < w.window_before_s + w.window_after_s || w.window_max_s > max_s)
    d.add(keys[2], fmt::format("must be in [window_before_s + window_after_s = {}, {}] (got {})",
                               format_number(w.window_before_s + w.window_after_s), format_number(max_s),
                               format_number(w.window_max_s)));
  const char* detection = "fdi.deficit.detection_window_s";
  const double longest_s = model::kMaxDeficitDetectorWindowPeriods * period;
  if (d.clean(detection) && (w.detection_window_s < 2 * period || w.detection_window_s > longest_s))
    d.add(detection, fmt::format("must be in [2 control periods = {}, {}] (got {})", format_number(2 * period),
                                 format_number(longest_s), format_number(w.detection_window_s)));
  check_block_windows(d, "fdi.deficit.impulse_", w.impulse_window_s, w.impulse_baseline_s, period);
}

// The observer bank needs the tanks (its rate model) and a window of whole periods it can hold.
void check_observer_bank(Diagnostics& d, const model::Scenario& s, double period) {
  const model::ObserverBankParams& b = s.fdi.observer_bank;
  if (b.enabled && !s.chaser.slosh)
    d.add("fdi.observer_bank.enabled", "needs chaser.slosh: the bank's rate model is built from the tanks' slosh");
  check_block_windows(d, "fdi.observer_bank.", b.window_s, b.baseline_s, period);
}

// The supervisor's estimators run on the bank's rate model and watch thrusters that fly from the
// start; its accommodation is the allocation's only change (no recovery beside it).
void check_supervisor(Diagnostics& d, const model::Scenario& s, double period) {
  const model::SupervisorParams& v = s.fdi.supervisor;
  if (!v.enabled) {
    if (v.accommodate) d.add("fdi.supervisor.accommodate", "needs fdi.supervisor.enabled");
    return;
  }
  if (!s.chaser.slosh)
    d.add("fdi.supervisor.enabled", "needs chaser.slosh: the estimators' rate model is built from the tanks' slosh");
  if (d.clean("fdi.supervisor.thrusters")) {
    const model::ThrusterMask start = model::initial_configuration(s.thrusters).active;
    if (v.thrusters == 0)
      d.add("fdi.supervisor.thrusters", "must name the thrusters to monitor, e.g. [T1, T5, T13, T17]");
    for (int t = 0; t < model::kMaxThrusters; ++t)
      if ((v.thrusters >> t & 1U) && !(start >> t & 1U))
        d.add("fdi.supervisor.thrusters", fmt::format("{} does not fly at the start (not in the set or on standby)",
                                                      model::thruster_name(t)));
  }
  if (d.clean("fdi.supervisor.dwell_s") && v.dwell_s < period)
    d.add("fdi.supervisor.dwell_s", fmt::format("must be >= control_period_s = {} (got {})", format_number(period),
                                                format_number(v.dwell_s)));
  if (v.accommodate && s.fdi.recovery != model::RecoveryPolicy::kNone)
    d.add("fdi.supervisor.accommodate", "needs fdi.recovery: none (the supervisor's mode is then the only change "
                                        "to the allocation)");
}

// The rate check reads the active checks' pulses: nothing to read without them.
void check_rate_check(Diagnostics& d, const model::Scenario& s) {
  if (s.fdi.rate_check.enabled && !s.fdi.active_check.enabled)
    d.add("fdi.rate_check.enabled", "needs fdi.active_check.enabled: it reads the active checks' pulses");
}

// An active check's on-times open the valve (a shorter command is dropped) and fit in one period,
// and a check's pulse is informative (else the thruster would be checked every period); its bound
// is at least one period, the cadence at which the flight software can check.
void check_active_check(Diagnostics& d, const model::Scenario& s, double period) {
  const model::ActiveCheckParams& a = s.fdi.active_check;
  const char* informative = "fdi.active_check.informative_on_time_s";
  const char* pulse = "fdi.active_check.pulse_s";
  const double min_on_s = s.thrusters.min_on_time_s;
  const bool informative_ok = d.clean(informative) && d.clean("thrusters.min_on_time_s") &&
                              a.informative_on_time_s >= min_on_s && a.informative_on_time_s <= period;
  if (d.clean(informative) && d.clean("thrusters.min_on_time_s") && !informative_ok)
    d.add(informative, fmt::format("must be in [thrusters.min_on_time_s = {}, control_period_s = {}] (got {})",
                                   format_number(min_on_s), format_number(period),
                                   format_number(a.informative_on_time_s)));
  if (informative_ok && d.clean(pulse) && (a.pulse_s < a.informative_on_time_s || a.pulse_s > period))
    d.add(pulse, fmt::format("must be in [informative_on_time_s = {}, control_period_s = {}] (got {})",
                             format_number(a.informative_on_time_s), format_number(period), format_number(a.pulse_s)));
  const char* bound = "fdi.active_check.max_unverified_s";
  if (d.clean(bound) && a.max_unverified_s < period)
    d.add(bound, fmt::format("must be >= control_period_s = {} (got {})", format_number(period),
                             format_number(a.max_unverified_s)));
  const char* arm = "fdi.active_check.arm_range_m";
  if (d.clean(arm) && d.clean("fdi.active_check.keep_quiet_range_m") && !(a.arm_range_m > a.keep_quiet_range_m))
    d.add(arm, fmt::format("must be > keep_quiet_range_m = {} (got {})", format_number(a.keep_quiet_range_m),
                           format_number(a.arm_range_m)));
}

// A sensor sampled at control periods every period_s and delivered latency_s later, before its next
// sample: period_s at least the control period, the latency below period_s.
void check_sample_timing(Diagnostics& d, const std::string& key, double period_s, double latency_s, double control_period_s) {
  if (d.clean(key + ".period_s") && period_s < control_period_s)
    d.add(key + ".period_s", fmt::format("must be in [control_period_s = {}, 10] (got {})", format_number(control_period_s),
                                         format_number(period_s)));
  if (d.clean(key + ".latency_s") && d.clean(key + ".period_s") && latency_s >= period_s)
    d.add(key + ".latency_s",
          fmt::format("must be in [0, period_s = {}) (got {})", format_number(period_s), format_number(latency_s)));
}

void check_timing(const model::Scenario& s, Diagnostics& d) {
  if (!d.clean("control_period_s")) return;
  const double period = s.control_period_s;
  const auto period_ns = whole_ns(period);
  if (!period_ns) {
    d.add("control_period_s", fmt::format("must be a whole number of nanoseconds (got {})",
                                          format_number(period)));
    return;
  }
  if (d.clean("duration_s")) {
    const auto duration_ns = whole_ns(s.duration_s);
    if (!duration_ns || *duration_ns <= 0 || *duration_ns % *period_ns != 0)
      d.add("duration_s", fmt::format("must be a positive multiple of control_period_s = {} (got {})",
                                      format_number(period), format_number(s.duration_s)));
  }
  check_below_period(d, "thrusters.delay_max_s", s.thrusters.delay_max_s, period, false);
  check_below_period(d, "thrusters.rise_time_s", s.thrusters.rise_time_s, period, true);
  check_below_period(d, "thrusters.min_on_time_s", s.thrusters.min_on_time_s, period, true);
  check_below_period(d, "thrusters.min_off_time_s", s.thrusters.min_off_time_s, period, true);
  check_sensor_delay(d, "sensors.lidar.delay_s", s.sensors.lidar.delay_s, period, *period_ns);
  check_sensor_delay(d, "sensors.star_tracker.delay_s", s.sensors.star_tracker.delay_s, period,
                        *period_ns);
  check_sensor_delay(d, "sensors.gyro.delay_s", s.sensors.gyro.delay_s, period, *period_ns);
  // The design decouples delays up to one period (l = 0, m = 1 in Fonod 2015, below eq. 20).
  if (d.clean("fdi.design_delay_max_s") && s.fdi.design_delay_max_s > period)
    d.add("fdi.design_delay_max_s", fmt::format("must be in (0, control_period_s = {}] (got {})", format_number(period),
                                                format_number(s.fdi.design_delay_max_s)));
  check_deficit_windows(d, s.fdi.deficit, period);
  check_active_check(d, s, period);
  check_observer_bank(d, s, period);
  check_rate_check(d, s);
  check_supervisor(d, s, period);
  if (s.sensors.target_pose)
    check_sample_timing(d, "sensors.target_pose", s.sensors.target_pose->period_s, s.sensors.target_pose->latency_s, period);
  if (s.sensors.arm_camera) {  // the same timing rules; on the gripper, so with an arm
    if (!s.chaser.arm) d.add("sensors.arm_camera", "needs chaser.arm (the camera is on the gripper)");
    check_sample_timing(d, "sensors.arm_camera", s.sensors.arm_camera->period_s, s.sensors.arm_camera->latency_s, period);
  }
}

// A rigid body's inertia is symmetric positive definite, and its principal moments satisfy
// I1 + I2 >= I3 (each moment is an integral of squared distances, sum of two >= the third).
void check_inertia(const Mat3& inertia, const char* path, Diagnostics& d) {
  if (!d.clean(path)) return;
  const double scale = inertia.cwiseAbs().maxCoeff();
  const double asymmetry = (inertia - inertia.transpose()).cwiseAbs().maxCoeff();
  if (asymmetry > kInertiaRelativeTolerance * scale) {
    d.add(path, fmt::format("must be symmetric (largest |I_ij - I_ji| is {})", format_number(asymmetry)));
    return;
  }
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(inertia, Eigen::EigenvaluesOnly);
  const Vec3 moments = eig.eigenvalues();  // ascending
  const std::string listed = fmt::format("{:.6g}, {:.6g}, {:.6g}", moments(0), moments(1), moments(2));
  if (!(moments(0) > 0.0)) {
    d.add(path, fmt::format("must be positive definite (eigenvalues {})", listed));
    return;
  }
  if (moments(2) > (moments(0) + moments(1)) * (1.0 + kInertiaRelativeTolerance))
    d.add(path, fmt::format("principal moments {} violate the triangle inequality: the largest must "
                            "be <= the sum of the other two", listed));
}

void check_faults(const model::Scenario& s, Diagnostics& d) {
  if (!d.clean("duration_s")) return;
  for (std::size_t i = 0; i < s.faults.size(); ++i) {
    const std::string path = fmt::format("faults.{}.onset_s", i);
    if (d.clean(path) && s.faults[i].onset_s > s.duration_s)
      d.add(path, fmt::format("must be in [0, duration_s] = [0, {}] (got {})",
                              format_number(s.duration_s), format_number(s.faults[i].onset_s)));
  }
}

void check_guidance(const model::GuidanceParams& g, Diagnostics& d) {
  if (!d.clean("guidance.start_distance_m")) return;
  const std::string start = format_number(g.start_distance_m);
  if (d.clean("guidance.capture_distance_m") && !(g.capture_distance_m < g.start_distance_m))
    d.add("guidance.capture_distance_m", fmt::format("must be < guidance.start_distance_m = {} (got {})",
                                                     start, format_number(g.capture_distance_m)));
  if (d.clean("guidance.corridor_min_distance_m") && !(g.corridor_min_distance_m < g.start_distance_m))
    d.add("guidance.corridor_min_distance_m",
          fmt::format("must be < guidance.start_distance_m = {} (got {})", start,
                      format_number(g.corridor_min_distance_m)));
  if (d.clean("guidance.blend_time_s") && d.clean("guidance.approach_duration_s") &&
      !(2.0 * g.blend_time_s <= g.approach_duration_s))
    d.add("guidance.blend_time_s",
          fmt::format("must be <= guidance.approach_duration_s / 2 = {} (got {})",
                      format_number(g.approach_duration_s / 2.0), format_number(g.blend_time_s)));
}

// The synchronisation's steps follow each other: the fly-around leaves the line's end once the line
// has reached it, and the transfer leaves the axis point once the rotation is synchronised.
void check_sync_approach(const model::GuidanceParams& g, Diagnostics& d) {
  if (!g.synchronised->approach || !d.clean("guidance.synchronised.approach")) return;
  const model::SyncApproachParams& a = *g.synchronised->approach;
  if (d.clean("guidance.approach_duration_s") && !(a.fly_around_start_s >= g.approach_duration_s))
    d.add("guidance.synchronised.approach.fly_around_start_s",
          fmt::format("must be >= guidance.approach_duration_s = {} (the line must reach its end first; got {})",
                      format_number(g.approach_duration_s), format_number(a.fly_around_start_s)));
  if (!(g.synchronised->transfer_start_s >= a.rotation_sync_end_s()))
    d.add("guidance.synchronised.transfer_start_s",
          fmt::format("must be >= the end of the rotation's synchronisation, fly_around_start_s + "
                      "fly_around_duration_s + axis_approach_duration_s + rotation_sync_duration_s = {} (got {})",
                      format_number(a.rotation_sync_end_s()), format_number(g.synchronised->transfer_start_s)));
}

// orbit.earth and target.body come together (the perturbed plant integrates the target's attitude;
// the circular one turns it at a constant rate), and orbit.earth's environment is the Earth's, so
// the central body must be the Earth (mu and J2's reference radius within 1e-6 of WGS 84's).
void check_earth_platform(const model::Scenario& s, Diagnostics& d) {
  const bool earth = s.orbit.earth.has_value(), body = s.target.body.has_value();
  if (earth && !body && d.clean("orbit.earth"))
    d.add("target.body", "must be given with orbit.earth (a perturbed orbit flies a rigid-body target)");
  if (body && !earth && d.clean("target.body"))
    d.add("orbit.earth", "must be given with target.body (a rigid-body target flies in a perturbed Earth orbit)");
  if (earth) {
    constexpr double kEarthMu = 3.986004418e14, kEarthRadius = 6378137.0, kRelative = 1e-6;
    if (d.clean("orbit.mu_m3ps2") && std::abs(s.orbit.mu_m3ps2 / kEarthMu - 1.0) > kRelative)
      d.add("orbit.mu_m3ps2", fmt::format("must be the Earth's, 3.986004418e14 (within 1e-6), with orbit.earth (got {})",
                                          format_number(s.orbit.mu_m3ps2)));
    if (d.clean("orbit.body_radius_m") && std::abs(s.orbit.body_radius_m / kEarthRadius - 1.0) > kRelative)
      d.add("orbit.body_radius_m", fmt::format("must be the Earth's, 6378137 (within 1e-6), with orbit.earth (got {})",
                                               format_number(s.orbit.body_radius_m)));
  }
  if (body) check_inertia(s.target.body->inertia_kgm2, "target.body.inertia_kgm2", d);
}

// chaser.slosh: with the Earth-orbit plant only; each tank's liquid fits it; and what the plant
// takes out of the chaser's mass properties for the slosh masses (plant/orbit_plant.cpp) leaves a
// body of positive mass and inertia. That last is checked with a bound that needs no slosh model:
// a slosh mass m1 is at most its liquid and sits on its tank's axis between bottom and top, so the
// inertia taken out about the CoM c is at most sum m_i d_i^2 + (sum m_i d_i)^2 / M in every
// direction (the masses themselves, then the rest of the body's shift towards them), d_i the
// tank axis's farthest point from c, M the chaser's mass less its liquid.
void check_slosh(const model::Scenario& s, Diagnostics& d) {
  if (!s.chaser.slosh || !d.clean("chaser.slosh")) return;
  if (!s.orbit.earth) {
    if (d.clean("orbit")) d.add("chaser.slosh", "only with orbit.earth (the slosh model is part of the Earth-orbit plant)");
    return;
  }
  const model::SloshParams& slosh = *s.chaser.slosh;
  double liquid_kg = 0.0, moment_kgm = 0.0, inertia_kgm2 = 0.0;
  bool overfull = false;  // then the sums below are not the liquid the user meant
  for (std::size_t i = 0; i < slosh.tanks.size(); ++i) {
    const model::SloshTankSpec& t = slosh.tanks[i];
    const std::string path = fmt::format("chaser.slosh.tanks.{}", i);
    const double fill_m = model::fill_height_m(t);
    if (fill_m > t.height_m) {
      overfull = true;
      d.add(path + ".liquid_mass_kg",
            fmt::format("fills {} m of the tank, more than its height_m {} (radius_m {}, density_kgpm3 {})",
                        format_number(fill_m), format_number(t.height_m), format_number(t.radius_m),
                        format_number(t.density_kgpm3)));
    }
    const Vec3 top = t.bottom_centre_body_m + t.height_m * t.axis_body;
    const double farthest_m =
        std::max((t.bottom_centre_body_m - s.chaser.com_body_m).norm(), (top - s.chaser.com_body_m).norm());
    liquid_kg += t.liquid_mass_kg;
    moment_kgm += t.liquid_mass_kg * farthest_m;
    inertia_kgm2 += t.liquid_mass_kg * farthest_m * farthest_m;
  }
  if (overfull || !d.clean("chaser.mass_kg") || !d.clean("chaser.inertia_kgm2") || !d.clean("chaser.com_body_m"))
    return;
  if (!(liquid_kg < s.chaser.mass_kg)) {
    d.add("chaser.slosh.tanks", fmt::format("hold {} kg of liquid: must be less than chaser.mass_kg {} (the "
                                            "liquid is part of it)", format_number(liquid_kg),
                                            format_number(s.chaser.mass_kg)));
    return;
  }
  const double taken_kgm2 = inertia_kgm2 + moment_kgm * moment_kgm / (s.chaser.mass_kg - liquid_kg);
  const double smallest_kgm2 =
      Eigen::SelfAdjointEigenSolver<Mat3>(s.chaser.inertia_kgm2, Eigen::EigenvaluesOnly).eigenvalues()(0);
  if (!(taken_kgm2 < smallest_kgm2))
    d.add("chaser.slosh.tanks",
          fmt::format("their liquid may carry up to {} kg m^2 of the chaser's inertia, more than the smallest "
                      "principal moment of chaser.inertia_kgm2 ({}), which includes it: move the tanks nearer "
                      "chaser.com_body_m or check the inertia", format_number(taken_kgm2), format_number(smallest_kgm2)));
}

// A loop cannot be faster than the period that samples it: each H-infinity bandwidth below the
// Nyquist frequency pi / T (a sampled loop needs more than that; the design's margins tell).
void check_hinf(const model::Scenario& s, Diagnostics& d) {
  if (!s.control.hinf || !d.clean("control_period_s")) return;
  const double nyquist = std::numbers::pi / s.control_period_s;
  const auto check = [&](const char* key, double bandwidth) {
    if (d.clean(key) && !(bandwidth < nyquist))
      d.add(key, fmt::format("must be < pi / control_period_s = {} rad/s (got {})", format_number(nyquist),
                             format_number(bandwidth)));
  };
  check("control.hinf.translation.bandwidth_radps", s.control.hinf->translation.bandwidth_radps);
  check("control.hinf.rotation.bandwidth_radps", s.control.hinf->rotation.bandwidth_radps);
}

}  // namespace

// The loops divide by the starting mass less the gauge's reading (control.mass_from_gauge): a
// reading's noise must be small beside the mass, or a reading could turn the loops' sign.
void check_mass_from_gauge(const model::Scenario& s, Diagnostics& d) {
  const double limit = 1e-3 * s.chaser.mass_kg;
  if (s.control.mass_from_gauge && s.sensors.propellant.noise_sigma_kg > limit)
    d.add("sensors.propellant.noise_sigma_kg",
          fmt::format("with control.mass_from_gauge the gauge's noise must be <= 1e-3 chaser.mass_kg = {} kg "
                      "(got {})",
                      limit, s.sensors.propellant.noise_sigma_kg));
}

void validate_scenario(const model::Scenario& s, Diagnostics& diag) {
  check_timing(s, diag);
  check_inertia(s.chaser.inertia_kgm2, "chaser.inertia_kgm2", diag);
  check_earth_platform(s, diag);
  check_slosh(s, diag);
  validate_thruster_set(s, diag);
  check_faults(s, diag);
  check_guidance(s.guidance, diag);
  if (s.guidance.synchronised && diag.clean("guidance.synchronised")) {  // what the synchronised approach follows
    if (!s.target.body)
      diag.add("guidance.synchronised", "needs target.body (the target's frame and capture point)");
    if (!s.sensors.target_pose)
      diag.add("guidance.synchronised", "needs sensors.target_pose (the flight software follows its estimate of the target)");
    check_sync_approach(s.guidance, diag);
  }
  check_hinf(s, diag);
  check_mass_from_gauge(s, diag);
  validate_arm(s, diag);
  validate_capture(s, diag);
  validate_campaign(s, diag);
}

}  // namespace chaser::io
