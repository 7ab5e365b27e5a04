// The dispersion sampler: truncated normal draws with the scenario's 3-sigma values.
#include "campaign/dispersion.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "campaign/statistics.hpp"
#include "core/random.hpp"

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
