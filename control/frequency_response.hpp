#pragma once
// Frequency response of a continuous-time StateSpace and an H-infinity norm estimate from it,
// independent of SLICOT: the check on what hinf_synthesis reports.
//
//   G(j omega) = C (j omega I - A)^-1 B + D,   sigma_max(omega) = largest singular value of G(j omega)
//   ||G||_inf = sup_omega sigma_max(omega)        (for a stable G; Zhou, Doyle, Glover, "Robust and
//                                                 Optimal Control", 1996, on H2 and H-inf spaces)
//
// The norm estimate is a sweep, not Bruinsma & Steinbuch's Hamiltonian bisection: a log grid over a
// range taken from the pole magnitudes, with the frequency of every pole added to the grid (so a
// resonance sharper than the grid spacing is not stepped over), omega = 0 and omega -> inf (D),
// then a golden-section search in log omega on the two grid intervals beside the largest point.
//
// What it achieves: the golden section shrinks the bracket to kGoldenLogTolerance = 1e-10 in
// ln omega, i.e. omega* to ~1e-10 relative. Near a peak sigma_max(omega) = peak (1 - kappa (dw/w)^2),
// so the norm's error from the bracket is ~kappa 1e-20, far below the rounding of one evaluation
// (~1e-15 relative for a well-conditioned j omega I - A; ~cond(j omega I - A) eps in general).
// Like any sweep it is a lower bound: a peak the grid and the pole frequencies do not bracket can
// be missed (a peak of sigma_max not near any pole frequency, between grid points and narrower
// than the 1/kPointsPerDecade grid spacing). Design-time code: allocates.
#include <Eigen/Core>
#include <complex>
#include <vector>

#include "control/state_space.hpp"

namespace chaser::control {

// G(j omega_radps), p x m complex. omega must be finite.
Eigen::MatrixXcd frequency_response(const StateSpace& g, double omega_radps);

// Largest singular value of G(j omega_radps) (JacobiSVD).
double sigma_max(const StateSpace& g, double omega_radps);

// count points from omega_min to omega_max, equally spaced in log omega (count >= 2, 0 < min < max).
std::vector<double> log_grid(double omega_min_radps, double omega_max_radps, int count);

// Eigenvalues of a: the poles of the system (of the closed loop, for a closed-loop StateSpace).
Eigen::VectorXcd poles(const StateSpace& g);

// max Re(pole); -inf for a static gain. Stable (continuous time) iff < 0.
double max_real_pole(const StateSpace& g);

struct HinfNormEstimate {
  double norm = 0.0;             // sup of sigma_max found: a lower bound on ||G||_inf (see above)
  double omega_peak_radps = 0.0;  // where it was found; +inf if the supremum is D's (omega -> inf)
  int evaluations = 0;            // sigma_max evaluations spent
};

constexpr int kPointsPerDecade = 40;
constexpr double kGoldenLogTolerance = 1e-10;

// The sweep and refinement described above. The grid spans [w_lo / 100, w_hi * 100] where w_lo and
// w_hi are the smallest and largest nonzero pole magnitudes (1 rad/s if there are none).
HinfNormEstimate hinf_norm_estimate(const StateSpace& g);

}  // namespace chaser::control
