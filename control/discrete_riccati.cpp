#include "control/discrete_riccati.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <vector>

// SB02OD (SLICOT 5.0, src/SB02OD.f): Fortran 77, every argument by reference, arrays column-major
// (Eigen's default), INTEGER = int, LOGICAL = int (gfortran's default kinds). Its six CHARACTER*1
// arguments each add a hidden length, passed by value after the last argument (gfortran >= 8:
// size_t).
extern "C" void sb02od_(const char* dico, const char* jobb, const char* fact, const char* uplo, const char* jobl,
                        const char* sort, const int* n, const int* m, const int* p, const double* a, const int* lda,
                        const double* b, const int* ldb, double* q, const int* ldq, double* r, const int* ldr,
                        const double* l, const int* ldl, double* rcond, double* x, const int* ldx, double* alfar,
                        double* alfai, double* beta, double* s, const int* lds, double* t, const int* ldt, double* u,
                        const int* ldu, const double* tol, int* iwork, double* dwork, const int* ldwork, int* bwork,
                        int* info, std::size_t, std::size_t, std::size_t, std::size_t, std::size_t, std::size_t);

namespace chaser::control {

using Eigen::MatrixXd;

namespace {

DareResult refuse(std::string message, int info = 0) {
  DareResult r;
  r.message = std::move(message);
  r.slicot_info = info;
  return r;
}

const char* info_text(int info) {
  switch (info) {
    case 1: return "the extended pencil is singular (R singular, or rounding)";
    case 2: return "the QZ algorithm failed";
    case 3: return "reordering the generalised eigenvalues failed";
    case 4: return "rounding moved eigenvalues across the unit circle (no stabilising solution, or too close to none)";
    case 5: return "the stable deflating subspace does not have dimension n (eigenvalues on the unit circle)";
    case 6: return "a singular matrix was met forming X";
    default: return "SB02OD refused an argument";
  }
}

bool finite(const MatrixXd& m) { return m.allFinite(); }

}  // namespace

DareResult solve_dare(const MatrixXd& A, const MatrixXd& B, const MatrixXd& Q, const MatrixXd& R) {
  const auto n64 = A.rows();
  const auto m64 = B.cols();
  if (n64 < 1 || A.cols() != n64) return refuse("solve_dare: A must be square with at least one row");
  if (B.rows() != n64 || m64 < 1) return refuse("solve_dare: B must have A's rows and at least one column");
  if (Q.rows() != n64 || Q.cols() != n64) return refuse("solve_dare: Q must be n x n");
  if (R.rows() != m64 || R.cols() != m64) return refuse("solve_dare: R must be m x m");
  if (!finite(A) || !finite(B) || !finite(Q) || !finite(R)) return refuse("solve_dare: a matrix is not finite");
  const double scale_q = std::max(1.0, Q.norm());
  const double scale_r = std::max(1.0, R.norm());
  if ((Q - Q.transpose()).norm() > 1e-12 * scale_q || (R - R.transpose()).norm() > 1e-12 * scale_r)
    return refuse("solve_dare: Q and R must be symmetric");
  if (n64 > 2000 || m64 > 2000) return refuse("solve_dare: sizes above 2000 are not supported");

  const int n = static_cast<int>(n64), m = static_cast<int>(m64), p = 0;
  const int n2 = 2 * n, ldsm = 2 * n + m;
  MatrixXd q = Q, r = R, x(n, n), s(ldsm, ldsm), t(ldsm, n2), u(n2, n2);
  const MatrixXd l = MatrixXd::Zero(n, 1);
  std::vector<double> alfar(static_cast<std::size_t>(n2)), alfai(alfar.size()), beta(alfar.size());
  const int ldwork = std::max({7 * (2 * n + 1) + 16, 16 * n, 2 * n + m, 3 * m}) * 4;
  std::vector<double> dwork(static_cast<std::size_t>(ldwork));
  std::vector<int> iwork(static_cast<std::size_t>(std::max({1, m, 2 * n}))), bwork(static_cast<std::size_t>(n2));
  const int ldl = 1;
  const double tol = 0.0;  // SB02OD's default: machine epsilon
  double rcond = 0;
  int info = 0;
  sb02od_("D", "B", "N", "U", "Z", "S", &n, &m, &p, A.data(), &n, B.data(), &n, q.data(), &n, r.data(), &m,
          l.data(), &ldl, &rcond, x.data(), &n, alfar.data(), alfai.data(), beta.data(), s.data(), &ldsm, t.data(),
          &ldsm, u.data(), &n2, &tol, iwork.data(), dwork.data(), &ldwork, bwork.data(), &info, 1, 1, 1, 1, 1, 1);
  if (info != 0) return refuse(std::string("SB02OD INFO = ") + std::to_string(info) + ": " + info_text(info), info);

  DareResult out;
  out.ok = true;
  out.X = 0.5 * (x + x.transpose());
  out.rcond = rcond;
  out.closed_loop.resize(n);
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    out.closed_loop(i) = std::complex<double>(alfar[k], alfai[k]) / beta[k];
  }
  // The residual from the equation itself, independent of SLICOT's own test.
  const MatrixXd& X = out.X;
  const MatrixXd btx_a = B.transpose() * X * A;
  const MatrixXd rhs = A.transpose() * X * A - btx_a.transpose() * (R + B.transpose() * X * B).lu().solve(btx_a) + Q;
  out.residual = (rhs - X).norm() / std::max(1.0, X.norm());
  return out;
}

}  // namespace chaser::control
