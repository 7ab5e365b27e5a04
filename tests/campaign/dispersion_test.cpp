// The dispersion sampler: truncated normal draws with the scenario's 3-sigma values.
#include "campaign/dispersion.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "campaign/statistics.hpp"
#include "core/constants.hpp"
#include "core/random.hpp"
#include "plant/orbit_plant.hpp"

namespace chaser::campaign {
namespace {

model::SpacecraftParams nominal() {
  model::SpacecraftParams p;
  p.mass_kg = 2500.0;
  p.inertia_kgm2 = Vec3(2000.0, 2500.0, 3000.0).asDiagonal();
  p.com_body_m = Vec3(0.01, 0.0, -0.02);
  return p;
}

constexpr int kDraws = 20000;

// A normal truncated at +-3 sigma has standard deviation sigma * sqrt(1 - 6 phi(3) / (2 Phi(3) - 1))
// = 0.98664 sigma. With n = 20000 draws the sample mean has standard error 0.0071 sigma and the
// sample std about 0.005 sigma: 5 standard errors (0.035 and 0.025 sigma) never fail by chance and
// still catch a wrong sigma (a 3-sigma value used as 1-sigma is off by a factor 3).
constexpr double kTruncatedStdFactor = 0.98664;

TEST(Dispersion, MomentsMatchATruncatedNormalAndNoDrawPassesThreeSigma) {
  const model::CampaignParams params;
  const model::SpacecraftParams nom = nominal();
  RunningStats mass, ixx, izz, com_x;
  for (int i = 0; i < kDraws; ++i) {
    const model::SpacecraftParams d = disperse_chaser(nom, params, run_seed(11, static_cast<std::uint64_t>(i)));
    const double m_rel = d.mass_kg / nom.mass_kg - 1.0;
    const double ixx_rel = d.inertia_kgm2(0, 0) / 2000.0 - 1.0, izz_rel = d.inertia_kgm2(2, 2) / 3000.0 - 1.0;
    ASSERT_LE(std::abs(m_rel), params.mass_3sigma_rel * (1 + 1e-12));
    ASSERT_LE(std::abs(ixx_rel), params.inertia_3sigma_rel * (1 + 1e-12));
    ASSERT_LE(std::abs(d.com_body_m(0) - 0.01), params.com_3sigma_m * (1 + 1e-12));
    mass.add(m_rel);
    ixx.add(ixx_rel);
    izz.add(izz_rel);
    com_x.add(d.com_body_m(0) - 0.01);
  }
  const auto check = [](const RunningStats& s, double three_sigma) {
    const double sigma = three_sigma / 3.0;
    EXPECT_NEAR(s.mean(), 0.0, 0.035 * sigma);
    EXPECT_NEAR(s.sample_std(), kTruncatedStdFactor * sigma, 0.025 * sigma);
  };
  check(mass, params.mass_3sigma_rel);
  check(com_x, params.com_3sigma_m);
  // Rejection of the (rare) triangle-inequality failures leaves the moments' law practically intact.
  check(ixx, params.inertia_3sigma_rel);
  check(izz, params.inertia_3sigma_rel);
}

// Every dispersed tensor is a physical inertia: symmetric, and the triangle inequality holds even
// when the nominal sits on its edge (2000 + 1000 = 3000 fails at the first unlucky draw).
TEST(Dispersion, InertiaStaysPhysical) {
  model::SpacecraftParams nom = nominal();
  nom.inertia_kgm2 = Vec3(1000.0, 2000.0, 3000.0).asDiagonal();
  const model::CampaignParams params;
  for (int i = 0; i < 2000; ++i) {
    const Mat3 I = disperse_chaser(nom, params, run_seed(3, static_cast<std::uint64_t>(i))).inertia_kgm2;
    EXPECT_EQ(I(0, 1), 0.0);  // principal axes of a diagonal tensor stay the body axes exactly
    EXPECT_LE(I(2, 2), I(0, 0) + I(1, 1));
    EXPECT_LE(I(0, 0), I(1, 1) + I(2, 2));
  }
}

// A rotated nominal tensor keeps its principal axes: the dispersed tensor commutes with the
// nominal one (both diagonal in the same basis).
TEST(Dispersion, RotatedTensorKeepsItsPrincipalAxes) {
  model::SpacecraftParams nom = nominal();
  const Mat3 R = Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  nom.inertia_kgm2 = R * nom.inertia_kgm2 * R.transpose();
  const Mat3 I = disperse_chaser(nom, {}, 99).inertia_kgm2;
  EXPECT_LT((I * nom.inertia_kgm2 - nom.inertia_kgm2 * I).norm(), 1e-9 * nom.inertia_kgm2.squaredNorm());
  EXPECT_LT((I - I.transpose()).norm(), 1e-9 * I.norm());
}

TEST(Dispersion, SameSeedSameChaserOtherSeedOtherChaser) {
  const auto a = disperse_chaser(nominal(), {}, 5), b = disperse_chaser(nominal(), {}, 5);
  const auto c = disperse_chaser(nominal(), {}, 6);
  EXPECT_EQ(a.mass_kg, b.mass_kg);
  EXPECT_EQ(a.com_body_m, b.com_body_m);
  EXPECT_NE(a.mass_kg, c.mass_kg);
}

}  // namespace
}  // namespace chaser::campaign

namespace chaser::campaign {
namespace {

// ENVISAT-like spin case S1 (about target +Y, along H-bar) at 2.5 deg/s.
model::TargetParams tumbling_target() {
  model::TargetParams t;
  t.body.emplace();
  t.body->inertia_kgm2 = Vec3(17000.0, 125000.0, 129000.0).asDiagonal();
  t.body->spin_case = model::SpinCase::s1;
  t.body->spin_rate_radps = 2.5 * kDegToRad;
  return t;
}

// The spin's dispersion: the rate scaled within its 3 sigma, the axis tilted within its 3 sigma
// about a perpendicular, the rate still along the same body axis (the body turned with it), the
// tilts' standard deviation that of the truncated normal (kTruncatedStdFactor, 2,000 draws: 5
// standard errors are 8 %), and the same seed the same target.
TEST(Dispersion, TargetSpinIsScaledAndTiltedWithTheBody) {
  const model::TargetParams nominal = tumbling_target();
  model::CampaignParams params;
  params.target_spin_rate_3sigma_rel = 0.1;
  params.target_spin_axis_3sigma_rad = 5.0 * kDegToRad;
  const plant::TargetSpin spin = plant::initial_target_spin(nominal);
  const Vec3 omega0 = spin.q_inertial_from_target * spin.omega_target_body_radps;
  RunningStats tilts;
  for (std::uint64_t seed = 1; seed <= 2000; ++seed) {
    const model::TargetParams t = disperse_target_spin(nominal, params, run_seed(7, seed));
    ASSERT_EQ(t.body->spin_case, model::SpinCase::given);
    const double factor = t.omega_inertial_radps.norm() / omega0.norm();
    EXPECT_LE(std::abs(factor - 1.0), 0.1 + 1e-12);
    const double tilt = std::atan2(t.omega_inertial_radps.cross(omega0).norm(), t.omega_inertial_radps.dot(omega0));
    EXPECT_LE(tilt, 5.0 * kDegToRad + 1e-12);
    tilts.add(tilt * (seed % 2 == 0 ? 1.0 : -1.0));  // the angle's sign is the perpendicular's: symmetric
    const Vec3 omega_body = t.q_inertial_from_target.conjugate() * t.omega_inertial_radps;
    EXPECT_LE(omega_body.normalized().cross(Vec3::UnitY()).norm(), 1e-12);  // still about target +Y
  }
  EXPECT_NEAR(tilts.sample_std(), kTruncatedStdFactor * 5.0 / 3.0 * kDegToRad, 0.08 * 5.0 / 3.0 * kDegToRad);
  const model::TargetParams a = disperse_target_spin(nominal, params, 42), b = disperse_target_spin(nominal, params, 42);
  EXPECT_EQ(a.omega_inertial_radps, b.omega_inertial_radps);
  EXPECT_EQ(a.q_inertial_from_target.coeffs(), b.q_inertial_from_target.coeffs());
}

// Without the keys (or without a rigid-body target) nothing moves; the start's offsets stay within
// their 3 sigma per axis.
TEST(Dispersion, NoSpinKeysNoChangeAndStartOffsetsWithinThreeSigma) {
  const model::TargetParams nominal = tumbling_target();
  const model::TargetParams same = disperse_target_spin(nominal, model::CampaignParams{}, 5);
  EXPECT_EQ(same.body->spin_case, model::SpinCase::s1);
  model::InitialState initial;
  disperse_initial(initial, model::CampaignParams{}, 5);
  EXPECT_EQ(initial.offset_r_lvlh_m, Vec3::Zero());
  model::CampaignParams params;
  params.initial_position_3sigma_m = 1.0;
  params.initial_velocity_3sigma_mps = 0.001;
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    model::InitialState x;
    disperse_initial(x, params, seed);
    EXPECT_LE(x.offset_r_lvlh_m.cwiseAbs().maxCoeff(), 1.0);
    EXPECT_LE(x.offset_v_lvlh_mps.cwiseAbs().maxCoeff(), 0.001);
    EXPECT_GT(x.offset_r_lvlh_m.norm(), 0.0);
  }
}

}  // namespace
}  // namespace chaser::campaign
