#include "flight/fdi/design/eigenstructure.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "flight/fdi/design/delay_discretization.hpp"
#include "flight/fdi/design/fdi_models.hpp"
#include "test_matrices.hpp"

namespace chaser::flight::fdi {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using testing::random_matrix;

const std::vector<double> kPaperEigenvalues = {0.85, 0.87, 0.89, 0.91, 0.93, 0.95};

std::vector<double> sorted_real_parts(const MatrixXd& m, double* max_imag) {
  const Eigen::VectorXcd ev = m.eigenvalues();
  std::vector<double> re;
  *max_imag = 0.0;
  for (const auto& z : ev) re.push_back(z.real()), *max_imag = std::max(*max_imag, std::abs(z.imag()));
  std::sort(re.begin(), re.end());
  return re;
}

// Eq. 35-38 for random observable systems and random H: A_bar - L C has exactly the assigned
// eigenvalues (1e-9: eigenvalues of a non-normal 6x6 matrix with cond(P) up to ~1e3 are accurate
// to cond * eps) and every row of P is a left eigenvector: P (A_bar - L C) = Lambda P (1e-10).
TEST(Eigenstructure, AssignsEigenvaluesAndLeftEigenvectors) {
  RandomStream rng(41, "eig");
  for (int trial = 0; trial < 10; ++trial) {
    const MatrixXd A_bar = random_matrix(rng, 6, 6, 0.5) + MatrixXd::Identity(6, 6);
    const MatrixXd C = random_matrix(rng, 3, 6);
    for (int n_r = 1; n_r <= 3; ++n_r) {
      const MatrixXd H = random_matrix(rng, n_r, 3) * C;
      const EigenstructureAssignment a = assign_left_eigenstructure(A_bar, C, H, kPaperEigenvalues);
      const MatrixXd A_c = A_bar - a.L * C;
      double max_imag = 0.0;
      const std::vector<double> re = sorted_real_parts(A_c, &max_imag);
      EXPECT_LT(max_imag, 1e-9);
      for (std::size_t i = 0; i < re.size(); ++i) EXPECT_NEAR(re[i], kPaperEigenvalues[i], 1e-9);
      const MatrixXd lambda = VectorXd::Map(kPaperEigenvalues.data(), 6).asDiagonal();
      EXPECT_LT((a.P * A_c - lambda * a.P).norm(), 1e-10 * a.P.norm() * A_bar.norm());
      EXPECT_EQ(a.relative_miss.size(), static_cast<std::size_t>(n_r));
    }
  }
}

// With only positions (or angles) measured, H = q^T [I 0] is never assignable: the projection on
// the assignable subspace misses it by T / sqrt((1 - lambda)^2 + T^2) (analysis note). Exact for
// the double integrator (1e-12); for HCW the orbit rate changes it by O(n T / (1 - lambda)) ~ 1e-3.
TEST(Eigenstructure, PositionOnlyMeasurementMissFormula) {
  const double T = 0.1;
  const LinearModel att = linear_attitude_model(Vec3(2000.0, 2500.0, 3000.0).asDiagonal());
  const LinearModel hcw = hcw_position_model(8.532e-4, 2500.0);
  const MatrixXd q = Eigen::RowVector3d(0.3, -0.4, 0.866).normalized();
  for (const double lambda : {0.85, 0.9, 0.95}) {
    const std::vector<double> ev = {lambda, 0.6, 0.65, 0.7, 0.75, 0.8};
    const double expected = T / std::sqrt((1 - lambda) * (1 - lambda) + T * T);
    const auto miss = [&](const LinearModel& m) {
      return assign_left_eigenstructure(discretize(m.A, m.B, T).A_bar, m.C, q * m.C, ev).relative_miss[0];
    };
    EXPECT_NEAR(miss(att), expected, 1e-12) << "lambda = " << lambda;
    EXPECT_NEAR(miss(hcw), expected, 1e-3 * expected) << "lambda = " << lambda;
  }
}

// Where H satisfies the assignability condition (H A_bar = mu H + m^T C, built backwards), the
// projection is H itself: relative miss 0 (1e-13) and H is an exact left eigenvector of A_bar - L C.
TEST(Eigenstructure, AssignableRowIsKeptExactly) {
  RandomStream rng(42, "assignable");
  MatrixXd A_bar = random_matrix(rng, 4, 4, 0.3) + MatrixXd::Identity(4, 4);
  A_bar.row(0).tail(2).setZero();  // e_1^T A_bar lies in span(e_1^T, e_2^T) = rows of C
  MatrixXd C = MatrixXd::Zero(2, 4);
  C(0, 0) = C(1, 1) = 1.0;
  const MatrixXd H = C.topRows(1);
  const std::vector<double> ev = {0.8, 0.85, 0.9, 0.95};
  const EigenstructureAssignment a = assign_left_eigenstructure(A_bar, C, H, ev);
  EXPECT_LT(a.relative_miss[0], 1e-13);
  EXPECT_LT((H * (A_bar - a.L * C) - 0.8 * H).norm(), 1e-12);
}

// Eigenvalues of A_bar cannot be assigned with this parametrisation (K_i needs the inverse).
TEST(Eigenstructure, RejectsEigenvalueOfABar) {
  const MatrixXd A_bar = MatrixXd::Identity(2, 2) * 0.9;
  const MatrixXd C = MatrixXd::Identity(1, 2);
  EXPECT_THROW(assign_left_eigenstructure(A_bar, C, C, {0.9, 0.8}), std::invalid_argument);
  EXPECT_THROW(assign_left_eigenstructure(A_bar, C, C, {0.8}), std::invalid_argument);
}

}  // namespace
}  // namespace chaser::flight::fdi
