#pragma once
// Plants and weights shared by the control tests.
#include <Eigen/Core>

#include "control/mixed_sensitivity.hpp"
#include "control/state_space.hpp"

namespace chaser::control::testing {

// Skogestad & Postlethwaite (S&P), Multivariable Feedback Control, 2nd ed., 2005, sec. 2.8 ("shaping
// closed-loop transfer functions", its S/KS mixed-sensitivity example):
// G(s) = 200 / ((10 s + 1)(0.05 s + 1)^2), as a series of three lags.
inline StateSpace skogestad_siso_plant() {
  StateSpace g;
  g.a = Eigen::MatrixXd::Zero(3, 3);
  g.a(0, 0) = -0.1;                     // 1 / (10 s + 1): x0' = -0.1 x0 + 0.1 u
  g.a(1, 1) = -20.0, g.a(1, 0) = 20.0;  // 1 / (0.05 s + 1) on x0
  g.a(2, 2) = -20.0, g.a(2, 1) = 20.0;  // and again on x1
  g.b = Eigen::MatrixXd::Zero(3, 1);
  g.b(0, 0) = 0.1;
  g.c = Eigen::MatrixXd::Zero(1, 3);
  g.c(0, 2) = 200.0;
  g.d = Eigen::MatrixXd::Zero(1, 1);
  return g;
}

// S&P's LV distillation column (2nd ed., sec. 3.7, used again in chapters 8 and 9):
// G(s) = 1 / (75 s + 1) [87.8 -86.4; 108.2 -109.6]. Ill conditioned: condition number 141.7.
inline StateSpace distillation_plant() {
  StateSpace g;
  g.a = -Eigen::MatrixXd::Identity(2, 2) / 75.0;
  g.b = Eigen::MatrixXd::Identity(2, 2) / 75.0;
  g.c = (Eigen::MatrixXd(2, 2) << 87.8, -86.4, 108.2, -109.6).finished();
  g.d = Eigen::MatrixXd::Zero(2, 2);
  return g;
}

// A block-diagonal copy of a SISO weight for n channels.
inline StateSpace diagonal_weight(const StateSpace& w, int n) {
  const Eigen::Index k = w.states();
  StateSpace out{Eigen::MatrixXd::Zero(n * k, n * k), Eigen::MatrixXd::Zero(n * k, n), Eigen::MatrixXd::Zero(n, n * k),
                 Eigen::MatrixXd::Zero(n, n)};
  for (int i = 0; i < n; ++i) {
    out.a.block(i * k, i * k, k, k) = w.a;
    out.b.block(i * k, i, k, 1) = w.b;
    out.c.block(i, i * k, 1, k) = w.c;
    out.d(i, i) = w.d(0, 0);
  }
  return out;
}

}  // namespace chaser::control::testing
