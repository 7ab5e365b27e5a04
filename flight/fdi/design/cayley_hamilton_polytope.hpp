#pragma once
// Cayley-Hamilton polytope of the delay uncertainty Gamma_1(delta) (Fonod 2015, Prop. 1, App. A).
//
// With p(lambda) = lambda^n + c_{n-1} lambda^{n-1} + ... + c_0 the characteristic polynomial of A
// (eq. 46), e^{At} = sum_i s_i(t) A^{i-1} (eq. 47), where s_i solves the scalar ODE of eq. 48 with
// s_i^{(j)}(0) = [j == i-1]. Hence Gamma_1(delta) = sum_i g_i(delta) A^{i-1} B with
// g_i(delta) = int_{T-delta}^T s_i(t) dt (eq. 49). Each g_i lies in [s_i^min, s_i^max] over the
// delay range, so Gamma_1 is a convex combination of the 2 n_x vertices
//   U_{2i-1} = n_x s_i^min A^{i-1} B,  U_{2i} = n_x s_i^max A^{i-1} B            (eq. 51)
// with weights mu_{2i-1} = alpha_{i,0} / n_x, mu_{2i} = alpha_{i,1} / n_x (eq. 50).
//
// The s_i are computed from the companion matrix F of p: z = (s, s', ..., s^{(n-1)}) obeys z' = F z,
// so s_i(t) = [e^{Ft}]_{0, i-1} and int s_i = first row of int e^{Fs} ds (Van Loan). This is exact
// for the repeated and zero eigenvalues of HCW and double-integrator models (no eigenvectors used).
// The companion matrix is badly scaled when ||A|| is far from one (its last row holds c_k ~
// ||A||^{n-k}), so it is built in the time unit time_scale_s (the period T): with A' = A time_scale,
// c'_k = c_k time_scale^{n-k}, tau = t / time_scale, and s_i(t) = s'_i(tau) time_scale^{i-1}.
// Accurate to ~1e-12 while ||A|| T is of order one (the MSR models: ||A|| T < 1e-1).
#include <Eigen/Core>
#include <vector>

namespace chaser::flight::fdi {

// c_0 .. c_{n-1} of eq. 46, by the Faddeev-LeVerrier recursion (exact zeros for nilpotent A).
Eigen::VectorXd characteristic_coefficients(const Eigen::MatrixXd& A);

// Companion matrix of eq. 48: F(j, j+1) = 1, last row -c_0 .. -c_{n-1}.
Eigen::MatrixXd companion_matrix(const Eigen::VectorXd& c);

// s_1(t) .. s_n(t) of eq. 47 for the coefficients c of eq. 46 (of A, unscaled); t [s].
Eigen::VectorXd cayley_hamilton_functions(const Eigen::VectorXd& c, double t,
                                          double time_scale_s = 1.0);

// int_{t0}^{t1} s_i(t) dt, i = 1..n; 0 <= t0 <= t1 [s].
Eigen::VectorXd cayley_hamilton_integrals(const Eigen::VectorXd& c, double t0, double t1,
                                          double time_scale_s = 1.0);

struct CayleyHamiltonPolytope {
  double period_s = 0.0;          // [s] T
  double delta_min_s = 0.0;       // [s]
  double delta_max_s = 0.0;       // [s]
  Eigen::VectorXd coefficients;   // c_0 .. c_{n-1}, eq. 46
  Eigen::VectorXd s_min;          // min over the delay range of g_i(delta), eq. 50
  Eigen::VectorXd s_max;          // max over the delay range of g_i(delta), eq. 50
  std::vector<Eigen::MatrixXd> powers_B;  // A^{i-1} B, i = 1..n_x
  std::vector<Eigen::MatrixXd> vertices;  // U^a_1 .. U^a_{2 n_x}, eq. 51
};

// The extremes of g_i over [delta_min, delta_max] sit at the ends or where g_i' = s_i(T - delta)
// changes sign: sign changes are found on a grid of grid_points intervals and refined by bisection
// to machine precision. Resolves every extremum when s_i has at most one sign change per grid
// interval, i.e. for ||A|| (delta_max - delta_min) << grid_points.
CayleyHamiltonPolytope cayley_hamilton_polytope(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                                                double period_s, double delta_min_s,
                                                double delta_max_s, int grid_points = 256);

// The weights mu^a (eq. 50-51) that reproduce the exact Gamma_1(delta): alpha_{i,1} =
// (g_i - s_i^min) / (s_i^max - s_i^min), not clamped, so that alpha in [0, 1] is the proof that the
// polytope contains Gamma_1(delta). Where s_i^max = s_i^min the two vertices coincide; alpha = 1/2.
Eigen::VectorXd cayley_hamilton_weights(const CayleyHamiltonPolytope& polytope, double delta_s);

}  // namespace chaser::flight::fdi
