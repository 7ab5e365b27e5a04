#include "io/invsim_loader.hpp"

#include <algorithm>

#include <gtest/gtest.h>

#include "core/constants.hpp"

namespace chaser::io {
namespace {

constexpr const char* kScenario = "scenarios/manual_rvd.yaml";

bool has_error_at(const InvSimLoadResult& r, const std::string& key_path) {
  return std::any_of(r.errors.begin(), r.errors.end(),
                     [&](const ScenarioError& e) { return e.key_path == key_path; });
}

// The shipped scenario loads and carries the paper's Table 3 values.
TEST(InvSimLoader, ShippedScenarioHasTable3Settings) {
  const InvSimLoadResult r = load_invsim_file(kScenario);
  ASSERT_TRUE(r.errors.empty()) << format_errors(r.errors);
  const model::InvSimParams& p = *r.params;
  EXPECT_EQ(p.r0_hill_m, Vec3(100.038, -0.0167, -0.023));
  EXPECT_EQ(p.v0_hill_mps, Vec3(-0.0076, 0.131, -0.0087));
  EXPECT_EQ(p.envelope_m, Vec3(4.0, 2.42, 2.42));
  EXPECT_EQ(p.inverse.horizon_steps, 3);
  EXPECT_EQ(p.step_s, 1.0);
  EXPECT_EQ(p.duration_s, 1300.0);
  EXPECT_EQ(p.pulses.basic_pulse_amount, 3000.0);
  EXPECT_EQ(p.pulses.time_sensitivity, 0.35);
  EXPECT_NEAR(p.sensor.azimuth_limit_rad, 10.0 * kDegToRad, 1e-15);
  EXPECT_NEAR(p.sensor.attitude_limit_rad, 1.0 * kDegToRad, 1e-15);
  ASSERT_EQ(p.thrusters.size(), 19u);
  for (const model::InvSimThruster& t : p.thrusters) {
    if (t.role == model::InvSimThrusterRole::kTranslation) {
      EXPECT_EQ(t.thrust_N, 60.0);
    }
    if (t.role == model::InvSimThrusterRole::kAttitude) {
      EXPECT_EQ(t.thrust_N, 25.0);
    }
  }
  EXPECT_EQ(r.faults.failed_mask, 0u);
}

// Overrides reach the schema like the file (Scheme I: attitude thrusters at 50 N), and faults are
// given by name.
TEST(InvSimLoader, OverridesAndFaultsByName) {
  const InvSimLoadResult r =
      load_invsim_file(kScenario, {"thrusters.1.thrust_N=50", "faults=[e1, d2~]"});
  ASSERT_TRUE(r.errors.empty()) << format_errors(r.errors);
  EXPECT_EQ(r.params->thrusters[1].thrust_N, 50.0);
  EXPECT_EQ(r.faults.failed_mask, (std::uint64_t{1} << 11) | (std::uint64_t{1} << 10));
}

// Every problem is reported at once with its key path: a bad value, a misspelt key, an unknown
// axis, a duplicated name, a fault naming no thruster, a period that does not divide the step.
TEST(InvSimLoader, ReportsEveryErrorWithItsKeyPath) {
  const InvSimLoadResult r = load_invsim_file(
      kScenario, {"chaser.mass_kg=-1", "pulses.time_sensitivty=0.3", "thrusters.7.axis=w",
                  "thrusters.8.name=d1", "faults=[zz]", "attitude_control.period_s=0.3"});
  EXPECT_FALSE(r.params.has_value());
  EXPECT_TRUE(has_error_at(r, "chaser.mass_kg")) << format_errors(r.errors);
  EXPECT_TRUE(has_error_at(r, "pulses.time_sensitivty")) << format_errors(r.errors);
  EXPECT_TRUE(has_error_at(r, "thrusters.7.axis")) << format_errors(r.errors);
  EXPECT_TRUE(has_error_at(r, "attitude_control.period_s")) << format_errors(r.errors);
  // The thruster list has errors, so the cross-checks that need it (names, faults) wait.
  const InvSimLoadResult names = load_invsim_file(kScenario, {"thrusters.8.name=d1", "faults=[zz]"});
  EXPECT_TRUE(has_error_at(names, "thrusters.8.name")) << format_errors(names.errors);
  const InvSimLoadResult faults = load_invsim_file(kScenario, {"faults=[zz, e1, e1]"});
  EXPECT_TRUE(has_error_at(faults, "faults.0")) << format_errors(faults.errors);
  EXPECT_TRUE(has_error_at(faults, "faults.2")) << format_errors(faults.errors);
}

// pulses.reading is smooth unless the file says otherwise; `paper` reads its own block; an unknown
// reading is named with its key and the allowed values; the paper reading needs its block.
TEST(InvSimLoader, ReadingIsSmoothByDefaultAndValidated) {
  const InvSimLoadResult shipped = load_invsim_file(kScenario);
  ASSERT_TRUE(shipped.errors.empty()) << format_errors(shipped.errors);
  EXPECT_EQ(shipped.params->pulses.reading, model::InvSimReading::kSmooth);
  const InvSimLoadResult paper = load_invsim_file(
      kScenario, {"pulses.reading=paper", "pulses.paper.pulse_width_s=0.05",
                  "pulses.paper.state_weights=[1, 1, 1, 2, 3, 4]"});
  ASSERT_TRUE(paper.errors.empty()) << format_errors(paper.errors);
  EXPECT_EQ(paper.params->pulses.reading, model::InvSimReading::kPaper);
  EXPECT_EQ(paper.params->pulses.paper.pulse_width_s, 0.05);
  EXPECT_EQ(paper.params->pulses.paper.state_weights[5], 4.0);
  const InvSimLoadResult bad = load_invsim_file(kScenario, {"pulses.reading=chatter", "pulses.paper.pulse_width_s=0"});
  ASSERT_TRUE(has_error_at(bad, "pulses.reading")) << format_errors(bad.errors);
  EXPECT_TRUE(has_error_at(bad, "pulses.paper.pulse_width_s")) << format_errors(bad.errors);
  const std::string text = format_errors(bad.errors);
  EXPECT_NE(text.find("must be smooth or paper (got 'chatter')"), std::string::npos) << text;
}

// pulses.paper.inverse_model and pulses.paper.measurement_noise: optional (nominal, no noise: the
// earlier paper reading), read as written, each bad value named with its key and allowed range.
TEST(InvSimLoader, PaperInverseModelAndMeasurementNoise) {
  const InvSimLoadResult shipped = load_invsim_file(kScenario);
  ASSERT_TRUE(shipped.errors.empty()) << format_errors(shipped.errors);
  const model::InvSimPaperReadingParams& paper = shipped.params->pulses.paper;
  EXPECT_EQ(paper.inverse_model, model::InvSimInverseModel::kFaulted);
  EXPECT_EQ(paper.measurement_noise.range_sigma_m, 0.01);
  EXPECT_NEAR(paper.measurement_noise.angle_sigma_rad, 0.01 * kDegToRad, 1e-18);
  EXPECT_EQ(paper.measurement_noise.seed, 1u);
  EXPECT_EQ(paper.measurement_noise.draws, 20u);
  EXPECT_EQ(paper.lateral_time_constant_s, 0.0);
  EXPECT_EQ(paper.opening, model::InvSimOpening::kCarried);
  const model::InvSimPaperReadingParams defaults;
  EXPECT_EQ(defaults.inverse_model, model::InvSimInverseModel::kNominal);
  EXPECT_FALSE(defaults.measurement_noise.enabled());
  EXPECT_EQ(defaults.lateral_time_constant_s, 0.0);
  EXPECT_EQ(defaults.opening, model::InvSimOpening::kCapped);
  const InvSimLoadResult bad = load_invsim_file(
      kScenario, {"pulses.paper.inverse_model=psychic", "pulses.paper.measurement_noise.range_sigma_m=-1",
                  "pulses.paper.measurement_noise.angle_sigma_deg=6", "pulses.paper.measurement_noise.seed=-2",
                  "pulses.paper.lateral_time_constant_s=-5", "pulses.paper.opening=leaky"});
  const std::string text = format_errors(bad.errors);
  EXPECT_FALSE(bad.params.has_value());
  EXPECT_NE(text.find("pulses.paper.inverse_model: must be nominal or faulted (got 'psychic')"), std::string::npos) << text;
  EXPECT_TRUE(has_error_at(bad, "pulses.paper.measurement_noise.range_sigma_m")) << text;
  EXPECT_TRUE(has_error_at(bad, "pulses.paper.measurement_noise.angle_sigma_deg")) << text;
  EXPECT_TRUE(has_error_at(bad, "pulses.paper.measurement_noise.seed")) << text;
  EXPECT_TRUE(has_error_at(bad, "pulses.paper.lateral_time_constant_s")) << text;
  EXPECT_NE(text.find("pulses.paper.opening: must be capped or carried (got 'leaky')"), std::string::npos) << text;
}

// pulses.paper.lateral_brake_mps2: optional (0, no brake), read as written, needs the return's
// time constant, and a bad value is named with its key and range.
TEST(InvSimLoader, PaperLateralBrake) {
  EXPECT_EQ(load_invsim_file(kScenario).params->pulses.paper.lateral_brake_mps2, 0.0);
  const InvSimLoadResult ok = load_invsim_file(
      kScenario, {"pulses.paper.lateral_brake_mps2=0.0075", "pulses.paper.lateral_time_constant_s=100"});
  ASSERT_TRUE(ok.errors.empty()) << format_errors(ok.errors);
  EXPECT_EQ(ok.params->pulses.paper.lateral_brake_mps2, 0.0075);
  EXPECT_EQ(ok.params->pulses.paper.lateral_time_constant_s, 100.0);
  const InvSimLoadResult no_return = load_invsim_file(kScenario, {"pulses.paper.lateral_brake_mps2=0.0075"});
  EXPECT_FALSE(no_return.params.has_value());
  EXPECT_NE(format_errors(no_return.errors)
                .find("pulses.paper.lateral_brake_mps2: needs lateral_time_constant_s > 0: the return after the "
                      "brake (got 0 s)"),
            std::string::npos)
      << format_errors(no_return.errors);
  for (const char* value : {"-0.01", "11", "fast"}) {
    const InvSimLoadResult bad = load_invsim_file(
        kScenario, {std::string("pulses.paper.lateral_brake_mps2=") + value, "pulses.paper.lateral_time_constant_s=100"});
    EXPECT_FALSE(bad.params.has_value()) << value;
    EXPECT_TRUE(has_error_at(bad, "pulses.paper.lateral_brake_mps2")) << value << format_errors(bad.errors);
  }
}

// A layout that cannot push along an axis is rejected before any run.
TEST(InvSimLoader, RejectsAGroupThatDoesNotPushAlongItsAxis) {
  const InvSimLoadResult r = load_invsim_file(
      kScenario, {"thrusters.7.direction_body=[0, 1, 0]", "thrusters.8.direction_body=[0, 1, 0]"});
  EXPECT_TRUE(has_error_at(r, "thrusters")) << format_errors(r.errors);
}

// The shipped study: Schemes I and II as configurations (by thruster name), and five free choices
// for --optimize (3 x 2 x 2 x 2 x 2 candidates); the loader keeps only what is written.
TEST(InvSimLoader, ShippedStudyHasSchemesIAndIIAndFiveFreeChoices) {
  const InvSimLoadResult r = load_invsim_file(kScenario);
  ASSERT_TRUE(r.errors.empty()) << format_errors(r.errors);
  const model::InvSimStudy& study = r.study;
  ASSERT_EQ(study.configurations.size(), 2u);
  EXPECT_EQ(study.configurations[0].name, "scheme_I");
  ASSERT_EQ(study.configurations[0].changes.size(), 6u);
  EXPECT_EQ(study.configurations[0].changes[0].thruster, 1u);  // a
  EXPECT_EQ(study.configurations[0].changes[0].thrust_N, 50.0);
  EXPECT_FALSE(study.configurations[0].changes[0].position_body_m.has_value());
  EXPECT_EQ(study.configurations[1].name, "scheme_II");
  ASSERT_EQ(study.configurations[1].changes.size(), 4u);
  EXPECT_EQ(study.configurations[1].changes[0].thruster, 7u);  // d1
  EXPECT_EQ(study.configurations[1].changes[0].position_body_m, Vec3(-1.5, 0.0, 0.7));
  ASSERT_EQ(study.free_choices.size(), 5u);
  EXPECT_EQ(model::candidate_count(study.free_choices), 48u);
  EXPECT_EQ(study.optimize_keep, 5);
}

// Study errors name their key: an unknown thruster, a reserved or repeated name, a name that cannot
// name a directory, a change that leaves nothing to change, a configuration whose layout cannot push
// along an axis, two choices changing one thruster, `keep` out of range.
TEST(InvSimLoader, StudyErrorsNameTheirKey) {
  const auto errors_of = [](std::vector<std::string> overrides) { return load_invsim_file(kScenario, overrides); };
  InvSimLoadResult r = errors_of({"configurations.0.thrusters={zz: {thrust_N: 50}}"});
  EXPECT_TRUE(has_error_at(r, "configurations.0.thrusters.zz")) << format_errors(r.errors);
  r = errors_of({"configurations.0.name=baseline"});
  EXPECT_TRUE(has_error_at(r, "configurations.0.name")) << format_errors(r.errors);
  r = errors_of({"configurations.1.name=scheme_I"});
  EXPECT_TRUE(has_error_at(r, "configurations.1.name")) << format_errors(r.errors);
  r = errors_of({"configurations.0.name=a/b"});
  EXPECT_TRUE(has_error_at(r, "configurations.0.name")) << format_errors(r.errors);
  r = errors_of({"configurations.0.thrusters.a={}"});
  EXPECT_TRUE(has_error_at(r, "configurations.0.thrusters.a")) << format_errors(r.errors);
  r = errors_of({"configurations.0.thrusters.a.thrust_N=-5"});
  EXPECT_TRUE(has_error_at(r, "configurations.0.thrusters.a.thrust_N")) << format_errors(r.errors);
  r = errors_of({"configurations.1.thrusters={d1: {direction_body: [0, 1, 0]}, d2: {direction_body: [0, 1, 0]}}"});
  EXPECT_TRUE(has_error_at(r, "configurations.1")) << format_errors(r.errors);
  r = errors_of({"optimize.choices.1.options.1.thrusters={e1: {position_body_m: [0, 1, 0]}}"});
  EXPECT_TRUE(has_error_at(r, "optimize.choices.3")) << format_errors(r.errors);  // e_negative, the later one
  r = errors_of({"optimize.keep=0"});
  EXPECT_TRUE(has_error_at(r, "optimize.keep")) << format_errors(r.errors);
  r = errors_of({"optimize.choices.0.options.1.name=25N"});
  EXPECT_TRUE(has_error_at(r, "optimize.choices.0.options.1.name")) << format_errors(r.errors);
  r = errors_of({"optimize.bogus=1"});
  EXPECT_TRUE(has_error_at(r, "optimize.bogus")) << format_errors(r.errors);
}

// The number of candidates is bounded: 13 choices of 2 options give 8192 > 4096, an error at
// optimize.choices rather than a search that never ends.
TEST(InvSimLoader, TooManyCandidatesIsAnError) {
  std::string choices = "optimize.choices=[";
  for (int k = 0; k < 13; ++k)
    choices += (k ? ", " : "") + std::string("{name: c") + std::to_string(k) + ", options: [{name: p}, {name: q}]}";
  choices += "]";
  const InvSimLoadResult r = load_invsim_file(kScenario, {choices});
  EXPECT_TRUE(has_error_at(r, "optimize.choices")) << format_errors(r.errors);
}

TEST(InvSimLoader, MissingFileIsAnError) {
  const InvSimLoadResult r = load_invsim_file("scenarios/no_such_file.yaml");
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].key_path, "scenarios/no_such_file.yaml");
}

}  // namespace
}  // namespace chaser::io
