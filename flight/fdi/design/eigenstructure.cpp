#include "flight/fdi/design/eigenstructure.hpp"

#include <Eigen/LU>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <stdexcept>

namespace chaser::flight::fdi {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

AssignableSubspace assignable_subspace(const MatrixXd& A_bar, const MatrixXd& C, double lambda) {
  const Index n = A_bar.rows();
  // K = -C (lambda I - A_bar)^{-1}, i.e. (lambda I - A_bar)^T K^T = -C^T.
  const Eigen::FullPivLU<MatrixXd> lu((lambda * MatrixXd::Identity(n, n) - A_bar).transpose());
  if (lu.rcond() < 1e-13)
    throw std::invalid_argument("assigned eigenvalue coincides with an eigenvalue of A_bar");
  const MatrixXd K = -lu.solve(C.transpose()).transpose();
  Eigen::JacobiSVD<MatrixXd> svd(K, Eigen::ComputeThinV);
  Index r = 0;
  const VectorXd& s = svd.singularValues();
  while (r < s.size() && s(r) > 1e-12 * s(0)) ++r;
  return {K, svd.matrixV().leftCols(r), K.transpose().colPivHouseholderQr()};
}

std::vector<AssignableSubspace> assignable_subspaces(const MatrixXd& A_bar, const MatrixXd& C,
                                                     const std::vector<double>& eigenvalues) {
  std::vector<AssignableSubspace> subspaces;
  subspaces.reserve(eigenvalues.size());
  for (const double lambda : eigenvalues) subspaces.push_back(assignable_subspace(A_bar, C, lambda));
  return subspaces;
}

namespace {

// The unit vector of span(basis) with the largest component orthogonal to span(chosen).
VectorXd most_orthogonal(const MatrixXd& basis, const MatrixXd& chosen_orthonormal) {
  const MatrixXd residual = basis - chosen_orthonormal * (chosen_orthonormal.transpose() * basis);
  Eigen::JacobiSVD<MatrixXd> svd(residual, Eigen::ComputeThinV);
  VectorXd l = basis * svd.matrixV().col(0);
  Index j = 0;
  l.cwiseAbs().maxCoeff(&j);
  return l(j) < 0.0 ? VectorXd(-l) : l;
}

}  // namespace

EigenstructureAssignment assign_left_eigenstructure(const MatrixXd& A_bar, const MatrixXd& C,
                                                    const MatrixXd& H,
                                                    const std::vector<double>& eigenvalues) {
  const Index n = A_bar.rows();
  if (static_cast<Index>(eigenvalues.size()) != n || H.rows() > n || H.cols() != n)
    throw std::invalid_argument("need n_x eigenvalues and at most n_x rows of H");
  return assign_left_eigenstructure(assignable_subspaces(A_bar, C, eigenvalues), H);
}

EigenstructureAssignment assign_left_eigenstructure(const std::vector<AssignableSubspace>& subspaces,
                                                    const MatrixXd& H) {
  const Index n = static_cast<Index>(subspaces.size());
  const Index n_r = H.rows();
  if (n == 0 || n_r > n || H.cols() != n)
    throw std::invalid_argument("need n_x eigenvalues and at most n_x rows of H");
  EigenstructureAssignment result;
  result.P.resize(n, n);
  result.S.resize(n, subspaces.front().K.rows());
  MatrixXd chosen(n, 0);  // orthonormal basis of the eigenvectors chosen so far
  for (Index i = 0; i < n; ++i) {
    const AssignableSubspace& sub = subspaces[i];
    VectorXd l;
    if (i < n_r) {  // eq. 37: projection of h_i on the assignable subspace
      const VectorXd h = H.row(i).transpose();
      l = sub.basis * (sub.basis.transpose() * h);
      result.relative_miss.push_back((h - l).norm() / h.norm());
    } else {
      l = most_orthogonal(sub.basis, chosen);
    }
    // m with K^T m = l in the least-squares sense (exact when l is in the row space of K).
    const VectorXd m = sub.K_t_qr.solve(l);
    result.P.row(i) = l.transpose();
    result.S.row(i) = m.transpose();
    const VectorXd fresh = l - chosen * (chosen.transpose() * l);
    if (fresh.norm() > 1e-14 * l.norm()) {
      chosen.conservativeResize(Eigen::NoChange, chosen.cols() + 1);
      chosen.col(chosen.cols() - 1) = fresh.normalized();
    }
  }
  const VectorXd sp = result.P.jacobiSvd().singularValues();
  result.p_condition = sp(0) / sp(sp.size() - 1);
  result.L = result.P.fullPivLu().solve(result.S);  // eq. 38
  return result;
}

}  // namespace chaser::flight::fdi
