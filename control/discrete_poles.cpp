#include "control/discrete_poles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Eigenvalues>

namespace chaser::control {

DiscreteLoopPoles discrete_loop_poles(const Eigen::MatrixXd& Ad, const Eigen::MatrixXd& Bd, const Eigen::MatrixXd& K,
                                      double period_s) {
  if (Ad.rows() != Ad.cols() || Bd.rows() != Ad.rows() || K.rows() != Bd.cols() || K.cols() != Ad.cols() ||
      !(period_s > 0.0))
    throw std::invalid_argument("discrete_loop_poles: Ad n x n, Bd n x m, K m x n and a period > 0");
  const Eigen::MatrixXd closed = Ad - Bd * K;
  const Eigen::EigenSolver<Eigen::MatrixXd> eig(closed, /*computeEigenvectors=*/false);
  DiscreteLoopPoles out;
  for (Eigen::Index i = 0; i < closed.rows(); ++i) {
    const std::complex<double> z = eig.eigenvalues()(i);
    if (z.imag() < 0.0) continue;  // its conjugate is listed
    LoopPole p;
    p.s = std::log(z) / period_s;
    p.natural_radps = std::abs(p.s);
    p.damping = p.natural_radps > 0.0 ? -p.s.real() / p.natural_radps : 1.0;
    p.time_constant_s = p.s.real() < 0.0 ? -1.0 / p.s.real() : std::numeric_limits<double>::infinity();
    out.poles.push_back(p);
  }
  std::sort(out.poles.begin(), out.poles.end(),
            [](const LoopPole& a, const LoopPole& b) { return a.natural_radps < b.natural_radps; });
  return out;
}

}  // namespace chaser::control
