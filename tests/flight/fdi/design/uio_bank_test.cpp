// The observer bank (flight/fdi/design/uio_bank.hpp) against what it must do, each by a method of
// its own: the discrete plant with a fault simulated step by step (observer i's residual stays at
// round-off while the others settle at the design's steady fault gains), the attenuation bound
// against the error system's frequency sweep, the steady noise covariance against its recursion,
// and the observers blind to a thruster against the layout's geometry (parallel torques).
#include "flight/fdi/design/uio_bank.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "tests/support/two_tank_chaser.hpp"

namespace chaser::flight::fdi {
namespace {

using chaser::testing::two_tank_chaser;
using Eigen::MatrixXd;
using Eigen::VectorXd;

const UioBank& comrade_bank() {
  static const UioBank bank = design_uio_bank(rate_model(two_tank_chaser()), UioBankParams{});
  return bank;
}

// The discrete plant with thruster `faulty` stuck open from step 0 (one full on-time every period on
// top of random commands), no noise: observer `faulty`'s residual is round-off throughout; every
// observer that sees the fault settles at fault_gain. 2e5 steps: the slowest pole of N (a slosh mode,
// |lambda| = 0.99994) has then decayed to 1e-5.
TEST(UioBank, DecouplesItsThrusterAndSettlesAtTheSteadyGains) {
  const UioBank& b = comrade_bank();
  const int faulty = 4;  // T5, one of COMRADE's four
  const Eigen::Index n = b.Ad.rows(), m = b.Bd.cols();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> on(0.0, 0.05);
  VectorXd x = VectorXd::Zero(n);
  std::vector<VectorXd> z(b.observers.size(), VectorXd::Zero(n));
  std::vector<double> residual(b.observers.size());
  double worst_own = 0.0;
  constexpr int kSteps = 200000;
  for (int k = 0; k < kSteps; ++k) {
    VectorXd u(m);
    for (Eigen::Index j = 0; j < m; ++j) u(j) = on(rng);
    const VectorXd y = b.C * x;
    for (std::size_t o = 0; o < b.observers.size(); ++o) {
      const UioObserver& obs = b.observers[o];
      residual[o] = (obs.Q * (y - b.C * (z[o] + obs.H * y))).norm();
      z[o] = obs.N * z[o] + obs.G * u + obs.L * y;
    }
    worst_own = std::max(worst_own, residual[static_cast<std::size_t>(faulty)]);
    u(faulty) += 1.0;
    x = b.Ad * x + b.Bd * u;
  }
  // Round-off: the rates reach ~500 rad/s (the fault's torque integrated over 2e4 s); measured 1.6e-13.
  EXPECT_LT(worst_own, 1e-9);
  EXPECT_LT(worst_own, 1e-4 * b.fault_gain(0, faulty));
  for (std::size_t o = 0; o < b.observers.size(); ++o) {
    const double expected = b.fault_gain(static_cast<Eigen::Index>(o), faulty);
    if (expected < 1e-9) continue;  // blind: covered by the geometry test
    // The random commands add their own zero-mean residual (observer o sees them exactly, so none):
    // only the fault's steady part and the slow poles' leftover remain.
    EXPECT_NEAR(residual[o] / expected, 1.0, 1e-3) << "observer T" << o + 1;
  }
}

// The Riccati's gamma is an upper bound the error system must honour: checked by the sweep (an
// independent evaluation of C (zI - N)^-1 Be on the unit circle), and gamma_min is its lower edge.
TEST(UioBank, SweepStaysUnderTheDesignedGamma) {
  for (const UioObserver& o : comrade_bank().observers) {
    EXPECT_LE(o.gamma_sweep, o.gamma * (1.0 + 1e-9)) << "T" << o.thruster + 1;
    EXPECT_LT(o.gamma_min, o.gamma);
    EXPECT_LT(o.spectral_radius, 1.0);
    EXPECT_GT(o.gamma_sweep, 0.5 * o.gamma_min);  // a bound that is not vacuous
  }
}

// A thruster's fault is invisible at steady state exactly to the observers of thrusters whose torque
// is parallel to its own (the rates measure torque; the liquid, which the force also drives,
// settles). On the box layout each torque line holds four thrusters.
TEST(UioBank, BlindObserversAreTheParallelTorques) {
  const UioBank& b = comrade_bank();
  const model::ThrusterSetParams set = chaser::testing::box_24_thrusters();
  auto torque = [&](int j) {
    const auto& t = set.thrusters[static_cast<std::size_t>(j)];
    return Vec3(t.position_body_m.cross(t.direction_body));
  };
  for (int j = 0; j < 24; ++j) {
    std::vector<int> parallel;
    for (int o = 0; o < 24; ++o)
      if (o != j && torque(o).cross(torque(j)).norm() < 1e-12) parallel.push_back(o);
    EXPECT_EQ(b.blind[static_cast<std::size_t>(j)], parallel) << "T" << j + 1;
    EXPECT_EQ(parallel.size(), 3u);
    EXPECT_GT(b.isolation_snr[static_cast<std::size_t>(j)], 10.0);  // the others see it well
  }
}

// The steady covariance (a Kronecker solve) against the Lyapunov recursion run to convergence.
TEST(UioBank, NoiseRmsMatchesTheCovarianceRecursion) {
  const UioBankParams p;
  const UioBank& b = comrade_bank();
  const UioObserver& o = b.observers[0];
  // Rebuild the error system's input from the observer: Be = [T Ed sd, -A1 H sv] - K [0, sv Q].
  const Eigen::Index n = b.Ad.rows();
  const MatrixXd T = MatrixXd::Identity(n, n) - o.H * b.C;
  MatrixXd Be(n, 6);
  Be << T * b.Ed * p.disturbance_torque_Nm, -T * b.Ad * o.H * p.gyro_noise_radps - o.K * o.Q * p.gyro_noise_radps;
  MatrixXd S = MatrixXd::Zero(n, n);
  for (int k = 0; k < 2000000; ++k) {
    const MatrixXd next = o.N * S * o.N.transpose() + Be * Be.transpose();
    if ((next - S).norm() < 1e-15 * next.norm()) break;
    S = next;
  }
  const double rms = std::sqrt((o.Q * b.C * S * b.C.transpose() * o.Q.transpose()).trace() +
                               2.0 * p.gyro_noise_radps * p.gyro_noise_radps);
  EXPECT_NEAR(rms / o.residual_noise_rms, 1.0, 1e-6);
}

TEST(UioBank, RefusesBadParametersAndATorquelessThruster) {
  const RateModel m = rate_model(two_tank_chaser());
  auto message = [&](UioBankParams p) {
    try {
      design_uio_bank(m, p);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message({.period_s = 0.0}).find("period_s"), std::string::npos);
  EXPECT_NE(message({.gyro_noise_radps = -1.0}).find("gyro"), std::string::npos);
  EXPECT_NE(message({.disturbance_torque_Nm = NAN}).find("disturbance_torque_Nm"), std::string::npos);
  EXPECT_NE(message({.gamma_backoff = 1.0}).find("gamma_backoff"), std::string::npos);
  model::Scenario s = two_tank_chaser();
  s.thrusters.thrusters[2].position_body_m = Vec3::Zero();  // T3 fires through the centre of mass
  try {
    design_uio_bank(rate_model(s), UioBankParams{});
    ADD_FAILURE() << "a torqueless thruster was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("thruster 3 has no torque"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace chaser::flight::fdi
