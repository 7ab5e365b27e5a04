#include "flight/least_energy_allocation.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "core/power_of_two.hpp"

// Method (the header's (Q)): the primal active-set method for a convex QP with the Hessian I.
// Each iteration forms G = M_F M_F^T over the free on-times (at most 6 x 6 whatever the set's size)
// and solves G z = r, r = wrench - sum of the columns held at 1; the free on-times' target is
// m_i^T z, the closed-form minimiser of the equality-constrained subproblem. If the target is off
// the current point, step towards it until the first free on-time meets a bound (which joins the
// working set). At the target, the bounds' multipliers decide: an on-time held at 0 whose target
// m_i^T z is above 0 (or held at 1 with a target below 1) has a negative multiplier and is
// released, the largest violation first (Dantzig's rule, lowest index on ties). None: optimal, and
// because (Q) is strictly convex, the unique minimiser.
// G may be singular: fewer than six free on-times, or a set whose columns do not span R^6 (after
// losses). The wrench minus the held columns always lies in the free columns' range (the iterate is
// feasible), so the pseudo-inverse's solution is exact; G is solved by LDLT when its pivots are
// well apart and by its eigendecomposition (the pseudo-inverse) otherwise.
// Scaling: M is divided by a power of two so that |M_ij| <= 1 (exact), which makes the tolerances
// below dimensionless, like the simplex's (thruster_allocation.cpp).

namespace chaser::flight {
namespace {

enum class Held : std::uint8_t { kFree, kAtZero, kAtOne };

constexpr int kMaxIterationsBase = 20;  // plus four per thruster: each on-time enters and leaves the
                                        // working set a few times at most in practice
constexpr double kStepTol = 1e-11;      // [-] a free on-time this close to its target is at it
constexpr double kEnergyTol = 1e-13;    // [-] relative: a step must lower the energy by more to count
constexpr double kMultiplierTol = 1e-11;  // [-] multipliers (target beyond the bound) below this are 0
constexpr double kGramPivotRatio = 1e-12;  // LDLT pivots spread more than this: use the pseudo-inverse
constexpr double kStartTol = 1e-9;        // [-] the start's on-times may overrun [0, 1] by rounding


// z with G z = r for a symmetric positive semidefinite G (the minimum-norm solution when singular).
Vec6 solve_gram(const Mat6& g, const Vec6& r) {
  const Eigen::LDLT<Mat6> ldlt(g);
  const Vec6 pivots = ldlt.vectorD();
  if (ldlt.info() == Eigen::Success && pivots.minCoeff() > kGramPivotRatio * pivots.maxCoeff())
    return ldlt.solve(r);
  const Eigen::SelfAdjointEigenSolver<Mat6> eigen(g);
  const Vec6 values = eigen.eigenvalues();
  const double cut = kGramPivotRatio * std::max(values.maxCoeff(), 0.0);
  Vec6 c = eigen.eigenvectors().transpose() * r;
  for (int j = 0; j < 6; ++j) c[j] = values[j] > cut ? c[j] / values[j] : 0.0;
  return eigen.eigenvectors() * c;
}

struct Problem {
  int n = 0;
  model::ConfigMatrix m;  // scaled, columns [0, n)
  Vec6 wrench;            // scaled
};

// The free on-times' target: z of the equality-constrained subproblem on the current working set.
Vec6 subproblem_z(const Problem& p, const std::array<Held, model::kMaxThrusters>& held) {
  Mat6 g = Mat6::Zero();
  Vec6 r = p.wrench;
  for (int i = 0; i < p.n; ++i) {
    const auto col = p.m.col(i);
    if (held[static_cast<std::size_t>(i)] == Held::kAtOne) r -= col;
    if (held[static_cast<std::size_t>(i)] == Held::kFree) g.selfadjointView<Eigen::Lower>().rankUpdate(col);
  }
  g.triangularView<Eigen::StrictlyUpper>() = g.transpose();
  return solve_gram(g, r);
}

// The held on-time with the most negative multiplier at the subproblem's optimum z, -1 if none;
// on-times in `skip` are passed over (see the loop's degenerate case).
int most_violated(const Problem& p, const std::array<Held, model::kMaxThrusters>& held, const Vec6& z,
                  model::ThrusterMask skip) {
  int worst = -1;
  double worst_violation = kMultiplierTol;
  for (int i = 0; i < p.n; ++i) {
    const Held h = held[static_cast<std::size_t>(i)];
    if (h == Held::kFree || (skip & model::thruster_bit(i)) != 0) continue;
    const double target = p.m.col(i).dot(z);
    const double violation = h == Held::kAtZero ? target : 1.0 - target;
    if (violation > worst_violation) {
      worst_violation = violation;
      worst = i;
    }
  }
  return worst;
}

}  // namespace

LeastEnergyResult least_energy_on_times(const AllocationParams& params, const Vec6& wrench, const AllocationTon& start) {
  LeastEnergyResult out;
  out.ton = start;
  const int n = params.thrusters;
  if (n < 1 || n > model::kMaxThrusters) return out;
  const auto config = params.config.leftCols(n);
  const auto u0 = start.head(n);
  if (!config.allFinite() || !wrench.allFinite() || !u0.allFinite() || (u0.array() < -kStartTol).any() ||
      (u0.array() > 1.0 + kStartTol).any())
    return out;

  Problem p;
  p.n = n;
  const double scale = power_of_two_above(config.cwiseAbs().maxCoeff());
  p.m = params.config / scale;
  p.wrench = wrench / scale;
  AllocationTon u = AllocationTon::Zero();
  std::array<Held, model::kMaxThrusters> held{};
  for (int i = 0; i < n; ++i) {
    const double v = std::clamp(start[i], 0.0, 1.0);
    held[static_cast<std::size_t>(i)] = v == 0.0 ? Held::kAtZero : v == 1.0 ? Held::kAtOne : Held::kFree;
    u[i] = v;
  }

  const int max_iterations = kMaxIterationsBase + 4 * n;
  // Degenerate case: where the working set is dependent (fewer than six free columns on the
  // attainable set's boundary), multipliers are not unique and a release may not open a descent
  // direction: the released on-time runs back into its bound, with no gain in energy, and the same
  // releases could repeat for ever. Such releases are marked futile and not tried again until a
  // step lowers the energy; with every violated release futile, the point is optimal (the tests'
  // KKT certificate confirms it on thousands of boundary cases).
  model::ThrusterMask released = 0;  // released since the last step that lowered the energy
  model::ThrusterMask futile = 0;
  double energy = u.head(n).squaredNorm();
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    out.iterations = iteration + 1;
    const Vec6 z = subproblem_z(p, held);
    // Step towards the target, as far as the first free on-time meeting a bound allows.
    double alpha = 1.0;
    int blocking = -1;
    bool blocking_at_one = false;
    double step_max = 0.0;
    for (int i = 0; i < n; ++i) {
      if (held[static_cast<std::size_t>(i)] != Held::kFree) continue;
      const double step = p.m.col(i).dot(z) - u[i];
      step_max = std::max(step_max, std::abs(step));
      if (u[i] + step < 0.0 && -u[i] / step < alpha) {
        alpha = -u[i] / step;
        blocking = i;
        blocking_at_one = false;
      } else if (u[i] + step > 1.0 && (1.0 - u[i]) / step < alpha) {
        alpha = (1.0 - u[i]) / step;
        blocking = i;
        blocking_at_one = true;
      }
    }
    if (step_max > kStepTol) {
      for (int i = 0; i < n; ++i)
        if (held[static_cast<std::size_t>(i)] == Held::kFree) u[i] += alpha * (p.m.col(i).dot(z) - u[i]);
      const double new_energy = u.head(n).squaredNorm();
      if (new_energy < energy - kEnergyTol * (1.0 + energy)) {
        energy = new_energy;
        released = futile = 0;
      } else if (blocking >= 0 && (released & model::thruster_bit(blocking)) != 0) {
        futile |= model::thruster_bit(blocking);
      }
      if (blocking >= 0) {
        u[blocking] = blocking_at_one ? 1.0 : 0.0;
        held[static_cast<std::size_t>(blocking)] = blocking_at_one ? Held::kAtOne : Held::kAtZero;
        continue;  // a new working set: a new subproblem
      }
    }
    // At the subproblem's optimum (z is its multiplier): release a bound whose multiplier is negative.
    const int release = most_violated(p, held, z, futile);
    if (release < 0) {
      out.converged = true;
      break;
    }
    held[static_cast<std::size_t>(release)] = Held::kFree;
    released |= model::thruster_bit(release);
  }
  if (out.converged) {
    out.ton.setZero();
    out.ton.head(n) = u.head(n).cwiseMax(0.0).cwiseMin(1.0);
  }
  return out;
}

}  // namespace chaser::flight
