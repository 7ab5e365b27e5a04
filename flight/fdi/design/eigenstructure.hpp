#pragma once
// Left eigenstructure assignment of the residual observer (Fonod 2015, eqs. 35-38).
//
// For an eigenvalue lambda_i of A_bar - L C with left eigenvector l_i, eq. 35 gives
// l_i^T = m_i^T K_i with K_i = -C (lambda_i I - A_bar)^{-1}: l_i must lie in the row space of K_i
// (the assignable subspace, eq. 36). The first n_r left eigenvectors should be the rows h_i of
// H = Q C (Theorem 1); they are replaced by their projections l_i° = K_i^T m_i°,
// m_i° = (K_i K_i^T)^{-1} K_i h_i (eq. 37). The paper leaves the other n_x - n_r free ("e.g. using
// SVD"); here each is the unit vector of its assignable subspace with the largest component
// orthogonal to the eigenvectors already chosen (the leading right singular vector of
// (I - Pi) V_i, V_i an orthonormal basis of the row space of K_i, Pi the projector on the chosen
// ones), which keeps P well conditioned. Then P L = S (eq. 38).
// Eigenvalues must be real and distinct and must not be eigenvalues of A_bar.
#include <Eigen/Core>
#include <Eigen/QR>
#include <vector>

namespace chaser::flight::fdi {

struct EigenstructureAssignment {
  Eigen::MatrixXd L;                  // [n_x x n_y] observer gain, eq. 38
  Eigen::MatrixXd P;                  // [n_x x n_x] rows l_i^T (l_i° for i <= n_r)
  Eigen::MatrixXd S;                  // [n_x x n_y] rows m_i^T
  std::vector<double> relative_miss;  // ||h_i - l_i°|| / ||h_i||, i = 1..n_r (0: exactly assignable)
  double p_condition = 0.0;           // 2-norm condition number of P
};

// Orthonormal basis [n_x x n_y] of the row space of K = -C (lambda I - A_bar)^{-1}, K itself, and
// the factorisation of K^T that gives m_i from l_i (eq. 35), stored row-major as K^T is: a
// column-major copy factors with other rounding (an L entry of -0.0 for +0.0 in the MSR design).
struct AssignableSubspace {
  using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  Eigen::MatrixXd K;                                 // [n_y x n_x]
  Eigen::MatrixXd basis;                             // [n_x x rank K]
  Eigen::ColPivHouseholderQR<RowMajorMatrix> K_t_qr;  // of K^T [n_x x n_y]
};
AssignableSubspace assignable_subspace(const Eigen::MatrixXd& A_bar, const Eigen::MatrixXd& C,
                                       double lambda);

// One per eigenvalue, in order. They depend on A_bar, C and the eigenvalues only, not on H: a
// design's subspace search assigns a few hundred H against the same ones, so it computes them once.
// Throws std::invalid_argument on a singular lambda_i I - A_bar.
std::vector<AssignableSubspace> assignable_subspaces(const Eigen::MatrixXd& A_bar,
                                                     const Eigen::MatrixXd& C,
                                                     const std::vector<double>& eigenvalues);

// H: [n_r x n_x] rows to assign to eigenvalues[0 .. n_r-1]; eigenvalues: n_x values.
// Throws std::invalid_argument on a size mismatch or a singular lambda_i I - A_bar.
EigenstructureAssignment assign_left_eigenstructure(const Eigen::MatrixXd& A_bar,
                                                    const Eigen::MatrixXd& C,
                                                    const Eigen::MatrixXd& H,
                                                    const std::vector<double>& eigenvalues);

// The same on subspaces computed beforehand (the same numbers, bit for bit).
EigenstructureAssignment assign_left_eigenstructure(const std::vector<AssignableSubspace>& subspaces,
                                                    const Eigen::MatrixXd& H);

}  // namespace chaser::flight::fdi
