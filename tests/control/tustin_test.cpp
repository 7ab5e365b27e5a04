#include "control/tustin.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <stdexcept>

#include "control/frequency_response.hpp"

namespace chaser::control {
namespace {

using Eigen::MatrixXd;

// H_d(z) = Cd (zI - Ad)^-1 Bd + Dd at z = e^{j w T}.
std::complex<double> discrete_response(const StateSpace& d, double omega_radps, double period_s) {
  const std::complex<double> z = std::exp(std::complex<double>(0.0, omega_radps * period_s));
  const Eigen::Index n = d.states();
  const Eigen::MatrixXcd resolvent =
      (z * Eigen::MatrixXcd::Identity(n, n) - d.a.cast<std::complex<double>>()).inverse();
  return (d.c.cast<std::complex<double>>() * resolvent * d.b.cast<std::complex<double>>())(0, 0) + d.d(0, 0);
}

// A fourth-order controller of the shape the axis designs produce (a lead, a lag and a real pole
// pair; poles at -0.002, -0.4, -3 +- 2j rad/s): the bilinear map's identity
// H_d(e^{jwT}) = H_c(j (2/T) tan(wT/2)) holds at every frequency up to Nyquist, to rounding.
TEST(Tustin, FrequencyResponseIsTheWarpedContinuousOne) {
  StateSpace c;
  c.a = (MatrixXd(4, 4) << -0.002, 0, 0, 0,  //
         1.0, -0.4, 0, 0,                    //
         0, 1.0, -3.0, 2.0,                  //
         0, 0, -2.0, -3.0)
            .finished();
  c.b = (MatrixXd(4, 1) << 1.0, 0.5, -0.2, 0.3).finished();
  c.c = (MatrixXd(1, 4) << 0.7, -1.1, 2.0, 0.4).finished();
  c.d = MatrixXd::Constant(1, 1, 0.05);
  const double period = 0.1;
  const StateSpace d = discretise_tustin(c, period);
  for (const double w : {1e-4, 1e-2, 0.3, 1.0, 5.0, 20.0, 31.0}) {
    const std::complex<double> hc = frequency_response(c, 2.0 / period * std::tan(0.5 * w * period))(0, 0);
    const std::complex<double> hd = discrete_response(d, w, period);
    EXPECT_NEAR(std::abs(hd - hc), 0.0, 1e-12 * std::max(1.0, std::abs(hc))) << w;
  }
  // Stable in, stable out: every pole inside the unit circle.
  const Eigen::VectorXcd poles = d.a.eigenvalues();
  for (Eigen::Index i = 0; i < poles.size(); ++i) EXPECT_LT(std::abs(poles[i]), 1.0);
}

// The integrator 1/s becomes the trapezoidal rule: u_k = u_{k-1} + T/2 (e_k + e_{k-1}).
TEST(Tustin, IntegratorIsTheTrapezoidalRule) {
  StateSpace c{MatrixXd::Zero(1, 1), MatrixXd::Ones(1, 1), MatrixXd::Ones(1, 1), MatrixXd::Zero(1, 1)};
  const double period = 0.25;
  const StateSpace d = discretise_tustin(c, period);
  double x = 0.0, trapezoid = 0.0, previous = 0.0;
  for (int k = 0; k < 20; ++k) {
    const double e = std::sin(0.3 * k) + 0.1 * k;
    const double u = d.c(0, 0) * x + d.d(0, 0) * e;
    x = d.a(0, 0) * x + d.b(0, 0) * e;
    trapezoid += k == 0 ? 0.5 * period * e : 0.5 * period * (e + previous);
    previous = e;
    EXPECT_NEAR(u, trapezoid, 1e-13) << k;
  }
}

TEST(Tustin, BadInputIsRefused) {
  StateSpace c{MatrixXd::Constant(1, 1, 20.0), MatrixXd::Ones(1, 1), MatrixXd::Ones(1, 1), MatrixXd::Zero(1, 1)};
  EXPECT_THROW(discretise_tustin(c, 0.1), std::invalid_argument);  // pole at 2/T = 20 rad/s
  EXPECT_THROW(discretise_tustin(c, 0.0), std::invalid_argument);
  const StateSpace gain = static_gain(MatrixXd::Constant(1, 1, 3.0));
  EXPECT_EQ(discretise_tustin(gain, 0.1).d(0, 0), 3.0);
}

}  // namespace
}  // namespace chaser::control
