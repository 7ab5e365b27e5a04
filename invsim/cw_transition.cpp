// Closed-form CW transition matrices in the manual-RVD Hill frame (Zhou 2018, eqs. 2-7).
#include "invsim/cw_transition.hpp"

#include <cmath>

namespace chaser::invsim {

Mat6 cw_state_matrix(double n) {
  Mat6 a = Mat6::Zero();
  a.topRightCorner<3, 3>() = Mat3::Identity();
  a(3, 5) = 2.0 * n;       // x'' = 2 n z'
  a(4, 1) = -n * n;        // y'' = -n^2 y
  a(5, 3) = -2.0 * n;      // z'' = -2 n x' + 3 n^2 z
  a(5, 2) = 3.0 * n * n;
  return a;
}

Mat63 cw_input_matrix() {
  Mat63 b = Mat63::Zero();
  b.bottomRows<3>() = Mat3::Identity();
  return b;
}

// Classic HCW solution (x radial, y along-track) mapped to X = y, Y = -z, Z = -x.
Mat6 cw_state_transition(double n, double tau) {
  const double s = std::sin(n * tau), c = std::cos(n * tau), nt = n * tau;
  Mat6 phi = Mat6::Zero();
  phi.rightCols<3>() = cw_impulse_transition(n, tau);
  phi(0, 0) = 1.0;                    // x: along-track drift driven by z
  phi(0, 2) = 6.0 * (nt - s);
  phi(1, 1) = c;                      // y: harmonic, decoupled
  phi(2, 2) = 4.0 - 3.0 * c;          // z
  phi(3, 2) = 6.0 * n * (1.0 - c);    // x'
  phi(4, 1) = -n * s;                 // y'
  phi(5, 2) = 3.0 * n * s;            // z'
  return phi;
}

Mat63 cw_impulse_transition(double n, double tau) {
  const double s = std::sin(n * tau), c = std::cos(n * tau), nt = n * tau;
  Mat63 g = Mat63::Zero();
  g(0, 0) = (4.0 * s - 3.0 * nt) / n;
  g(0, 2) = 2.0 * (1.0 - c) / n;
  g(1, 1) = s / n;
  g(2, 0) = -2.0 * (1.0 - c) / n;
  g(2, 2) = s / n;
  g(3, 0) = 4.0 * c - 3.0;
  g(3, 2) = 2.0 * s;
  g(4, 1) = c;
  g(5, 0) = -2.0 * s;
  g(5, 2) = c;
  return g;
}

// Integral over [0, tau] of cw_impulse_transition. 1 - cos and n tau - sin are evaluated in forms
// that keep their relative accuracy for small n tau (2 sin^2(x/2); a series below 1e-2).
Mat63 cw_held_input_transition(double n, double tau) {
  const double nt = n * tau, s = std::sin(nt);
  const double half = std::sin(0.5 * nt);
  const double one_minus_c = 2.0 * half * half;
  const double nt3 = nt * nt * nt;
  const double nt_minus_s = std::abs(nt) < 1e-2
                                ? nt3 / 6.0 * (1.0 - nt * nt / 20.0 * (1.0 - nt * nt / 42.0))
                                : nt - s;
  const double n2 = n * n;
  Mat63 g = Mat63::Zero();
  // 4 (1 - c)/n^2 - 3 tau^2 / 2, written as a difference of O(tau^2) terms that cancels to O(tau^2)
  g(0, 0) = 4.0 * one_minus_c / n2 - 1.5 * tau * tau;
  g(0, 2) = 2.0 * nt_minus_s / n2;
  g(1, 1) = one_minus_c / n2;
  g(2, 0) = -2.0 * nt_minus_s / n2;
  g(2, 2) = one_minus_c / n2;
  g(3, 0) = 4.0 * s / n - 3.0 * tau;
  g(3, 2) = 2.0 * one_minus_c / n;
  g(4, 1) = s / n;
  g(5, 0) = -2.0 * one_minus_c / n;
  g(5, 2) = s / n;
  return g;
}

}  // namespace chaser::invsim
