#pragma once
// The poles of a discrete state-feedback loop x+ = (Ad - Bd K) x held over a period T, read in the
// s-plane: z is mapped by s = ln z / T, and each pole reads as a natural frequency w_n = |s| and a
// damping ratio zeta = -Re s / |s| (a real pole: zeta = 1), its envelope decaying with the time
// constant 1 / (zeta w_n) = -1 / Re s. Used for the LQR loops the flight software flies
// (`chaser control design`, docs/gnc.md).
#include <complex>
#include <vector>

#include <Eigen/Core>

namespace chaser::control {

struct LoopPole {
  std::complex<double> s;       // [1/s] the pole mapped by s = ln z / T
  double natural_radps = 0;     // [rad/s] w_n = |s|
  double damping = 0;           // [-] zeta = -Re s / |s|
  double time_constant_s = 0;   // [s] -1 / Re s; infinite for a pole on or outside the unit circle
};

struct DiscreteLoopPoles {
  std::vector<LoopPole> poles;  // slowest first; of a complex pair only the one with Im s > 0
  // Every |z| < 1, i.e. every Re s = ln|z| / T < 0 (a pair's two poles share |z|).
  bool stable() const {
    for (const LoopPole& p : poles)
      if (!(p.s.real() < 0.0)) return false;
    return true;
  }
};

DiscreteLoopPoles discrete_loop_poles(const Eigen::MatrixXd& Ad, const Eigen::MatrixXd& Bd, const Eigen::MatrixXd& K,
                                      double period_s);

}  // namespace chaser::control
