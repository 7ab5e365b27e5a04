#include "control/tustin.hpp"

#include <Eigen/LU>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace chaser::control {

StateSpace discretise_tustin(const StateSpace& continuous, double period_s) {
  if (!(period_s > 0.0) || !std::isfinite(period_s))
    throw std::invalid_argument(fmt::format("Tustin discretisation: the period must be > 0 s (got {})", period_s));
  const auto problems = validate(continuous, "controller");
  if (!problems.empty()) throw std::invalid_argument("Tustin discretisation: " + problems.front());
  const Eigen::Index n = continuous.states();
  if (n == 0) return continuous;  // a static gain is its own discretisation
  const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(n, n);
  const double half = 0.5 * period_s;
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(identity - half * continuous.a);
  if (!lu.isInvertible())
    throw std::invalid_argument(fmt::format("Tustin discretisation: a pole at s = 2/T = {} rad/s", 1.0 / half));
  const Eigen::MatrixXd m = lu.inverse();
  StateSpace discrete;
  discrete.a = m * (identity + half * continuous.a);
  discrete.b = m * continuous.b * period_s;
  discrete.c = continuous.c * m;
  discrete.d = continuous.d + continuous.c * m * continuous.b * half;
  return discrete;
}

}  // namespace chaser::control
