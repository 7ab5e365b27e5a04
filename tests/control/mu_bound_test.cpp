#include "control/mu_bound.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <cmath>
#include <complex>
#include <random>

namespace chaser::control {
namespace {

using Eigen::MatrixXcd;
using Eigen::VectorXcd;
using cd = std::complex<double>;

// AB13MD stops its iteration at TOL = 100 sqrt(eps) (its source): the closed forms are met to this.
constexpr double kIterationTolerance = 1e-5;

MatrixXcd random_matrix(int n, std::mt19937& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  MatrixXcd m(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) m(i, j) = cd(g(rng), g(rng));
  return m;
}

double sigma_max(const MatrixXcd& m) { return Eigen::JacobiSVD<MatrixXcd>(m).singularValues()(0); }

double spectral_radius(const MatrixXcd& m) { return m.eigenvalues().cwiseAbs().maxCoeff(); }

std::vector<UncertaintyBlock> scalar_blocks(int n, BlockType type = BlockType::kComplex) {
  return std::vector<UncertaintyBlock>(static_cast<std::size_t>(n), UncertaintyBlock{1, type});
}

// One full complex block: mu is sigma_max (AB13MD's SVD branch), to rounding.
TEST(MuBound, FullComplexBlockIsSigmaMax) {
  std::mt19937 rng(18);
  for (const int n : {1, 2, 4, 7}) {
    const MatrixXcd m = random_matrix(n, rng);
    const MuBound r = mu_upper_bound(m, {{n, BlockType::kComplex}});
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_NEAR(r.bound, sigma_max(m), 1e-13 * sigma_max(m)) << n;
  }
}

// Scalar complex blocks and a rank-one M = u v^H: I - M Delta is singular first at
// Delta_i = conj-phase / sum |u_i v_i|, so mu = sum |u_i v_i| exactly (S&P sec. 8.8, rank one).
TEST(MuBound, RankOneWithScalarBlocksIsSumOfProducts) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> mag(0.3, 3.0), phase(-M_PI, M_PI);
  for (const int n : {2, 3, 5}) {
    VectorXcd u(n), v(n);
    double exact = 0.0;
    for (int i = 0; i < n; ++i) {
      u(i) = std::polar(mag(rng), phase(rng));
      v(i) = std::polar(mag(rng), phase(rng));
      exact += std::abs(u(i) * v(i));
    }
    const MatrixXcd m = u * v.adjoint();
    const MuBound r = mu_upper_bound(m, scalar_blocks(n));
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_NEAR(r.bound, exact, kIterationTolerance * exact) << n;
  }
  // u and v far from parallel in magnitude: mu = 0.2 against sigma_max = 1.01, which the D scaling
  // (D_i = sqrt(|v_i| / |u_i|)) must find.
  VectorXcd u(2), v(2);
  u << 1.0, 0.1;
  v << cd(0.0, 0.1), -1.0;
  const MuBound r = mu_upper_bound(u * v.adjoint(), scalar_blocks(2));
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_NEAR(r.bound, 0.2, kIterationTolerance * 0.2);
}

// rho(M) <= mu <= bound <= sigma_max(M) for scalar complex blocks, on random matrices; and the
// mixed bound (first block real) is at most the all-complex one (it adds the G scaling).
TEST(MuBound, BoundLiesBetweenSpectralRadiusAndSigmaMax) {
  std::mt19937 rng(2026);
  for (int trial = 0; trial < 40; ++trial) {
    const int n = 2 + trial % 4;
    const MatrixXcd m = random_matrix(n, rng);
    const MuBound c = mu_upper_bound(m, scalar_blocks(n));
    ASSERT_TRUE(c.ok()) << c.message;
    EXPECT_GE(c.bound, spectral_radius(m) * (1.0 - kIterationTolerance)) << trial;
    EXPECT_LE(c.bound, sigma_max(m) * (1.0 + kIterationTolerance)) << trial;
    std::vector<UncertaintyBlock> mixed = scalar_blocks(n);
    mixed[0].type = BlockType::kReal;
    const MuBound r = mu_upper_bound(m, mixed);
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_LE(r.bound, c.bound * (1.0 + kIterationTolerance)) << trial;
  }
}

// A diagonal M with scalar blocks: mu = max |m_ii| (Delta_i = 1 / m_ii on the largest).
TEST(MuBound, DiagonalMatrixIsLargestEntry) {
  MatrixXcd m = MatrixXcd::Zero(3, 3);
  m.diagonal() << cd(0.5, 0.1), cd(-2.0, 1.0), cd(0.0, 0.7);
  const MuBound r = mu_upper_bound(m, scalar_blocks(3));
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_NEAR(r.bound, std::sqrt(5.0), kIterationTolerance * std::sqrt(5.0));
}

// One real scalar: AB13MD returns 0 even for a real M (SLICOT-Reference issue 4); ours is |M| then,
// and 0 for a complex M (no real delta makes 1 - M delta vanish).
TEST(MuBound, ScalarRealBlockIsExact) {
  const MuBound real = mu_upper_bound(MatrixXcd::Constant(1, 1, cd(-0.8, 0.0)), {{1, BlockType::kReal}});
  ASSERT_TRUE(real.ok());
  EXPECT_DOUBLE_EQ(real.bound, 0.8);
  const MuBound cplx = mu_upper_bound(MatrixXcd::Constant(1, 1, cd(-0.8, 0.3)), {{1, BlockType::kReal}});
  ASSERT_TRUE(cplx.ok());
  EXPECT_DOUBLE_EQ(cplx.bound, 0.0);
}

TEST(MuBound, ZeroMatrixHasZeroBound) {
  const MuBound r = mu_upper_bound(MatrixXcd::Zero(3, 3), scalar_blocks(3));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.bound, 0.0);
}

// Inputs that cannot be right are named, every one, and SLICOT never sees them.
TEST(MuBound, BadInputIsNamed) {
  const MuBound not_square = mu_upper_bound(MatrixXcd::Ones(2, 3), scalar_blocks(2));
  EXPECT_EQ(not_square.status, MuStatus::kInvalidInput);
  EXPECT_NE(not_square.message.find("square"), std::string::npos) << not_square.message;

  MatrixXcd nan = MatrixXcd::Ones(2, 2);
  nan(1, 0) = cd(std::nan(""), 0.0);
  const MuBound r = mu_upper_bound(nan, {{2, BlockType::kReal}, {0, BlockType::kComplex}});
  EXPECT_EQ(r.status, MuStatus::kInvalidInput);
  EXPECT_NE(r.message.find("non-finite"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("block 1: a real block must be a scalar"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("block 2: size must be >= 1"), std::string::npos) << r.message;

  const MuBound sum = mu_upper_bound(MatrixXcd::Ones(3, 3), scalar_blocks(2));
  EXPECT_NE(sum.message.find("sum to 2, M has order 3"), std::string::npos) << sum.message;
  const MuBound none = mu_upper_bound(MatrixXcd::Ones(2, 2), {});
  EXPECT_NE(none.message.find("no block"), std::string::npos) << none.message;
  const MuBound empty = mu_upper_bound(MatrixXcd(0, 0), scalar_blocks(1));
  EXPECT_NE(empty.message.find("empty"), std::string::npos) << empty.message;
}

}  // namespace
}  // namespace chaser::control
