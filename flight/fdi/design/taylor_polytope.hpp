#pragma once
// Taylor polytope of the delay uncertainty Gamma_1(delta) (Fonod 2015, Prop. 2, App. B, after
// Hetel et al. 2006).
//
// Gamma_1(delta) = int_{T-delta}^T e^{At} dt B = e^{AT} int_{-delta}^0 e^{As} ds B
//                = sum_{i>=1} delta^i G_i,   G_i = (-1)^{i+1} A^{i-1} e^{AT} B / i!   (Theorem 3)
// and the order-h approximation keeps i = 1..h. With v(delta) = (delta^h, ..., delta) it is
// [G_h, ..., G_1] v(delta) (x I). v(delta) lies in the convex hull of the h+1 vectors
//   Phi_j: entry for power p is delta_max^p if p <= j-1, else delta_min^p        (j = 1..h+1)
// because w_p = (delta^p - delta_min^p) / (delta_max^p - delta_min^p) is non-increasing in p for
// 0 <= delta_min <= delta <= delta_max. Weights mu_1 = 1 - w_1, mu_j = w_{j-1} - w_j (j = 2..h),
// mu_{h+1} = w_h: the last weight is missing from the printed eq. 52 and follows from sum mu = 1.
// Vertices U^b_j = [G_h, ..., G_1] Phi_j = sum_p G_p Phi_j(p).
#include <Eigen/Core>
#include <vector>

namespace chaser::flight::fdi {

struct TaylorPolytope {
  int order = 2;                       // h
  double delta_min_s = 0.0;            // [s]
  double delta_max_s = 0.0;            // [s]
  std::vector<Eigen::MatrixXd> terms;     // G_1 .. G_h
  std::vector<Eigen::MatrixXd> vertices;  // U^b_1 .. U^b_{h+1}, eq. 52
};

TaylorPolytope taylor_polytope(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, double period_s,
                               double delta_min_s, double delta_max_s, int order);

// The order-h approximation Gamma_1^b(delta) = sum_{i=1}^h delta^i G_i.
Eigen::MatrixXd taylor_gamma1(const TaylorPolytope& polytope, double delta_s);

// mu^b(delta) of eq. 52 (h+1 entries, non-negative, summing to one for delta in the range).
Eigen::VectorXd taylor_weights(const TaylorPolytope& polytope, double delta_s);

// Bound on || Gamma_1(delta) - Gamma_1^b(delta) ||_2 (spectral norm): with a = ||A||_2,
// || sum_{i>h} delta^i A^{i-1} e^{AT} B / i! || <= ||e^{AT} B|| delta^{h+1} a^h e^{a delta} / (h+1)!.
double taylor_remainder_bound(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, double period_s,
                              double delta_s, int order);

}  // namespace chaser::flight::fdi
