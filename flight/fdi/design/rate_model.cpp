#include "flight/fdi/design/rate_model.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <complex>
#include <span>
#include <stdexcept>

#include "model/chaser_slosh.hpp"
#include "model/thruster_geometry.hpp"
#include "model/thrusters.hpp"

namespace chaser::flight::fdi {

namespace {

// Two unit directions perpendicular to a tank's axis (the lateral plane its mass moves in).
std::array<Vec3, 2> lateral_basis(const Vec3& axis) {
  const Vec3 n = axis.normalized();
  Eigen::Index least = 0;
  n.cwiseAbs().minCoeff(&least);
  const Vec3 e1 = n.cross(Vec3::Unit(least)).normalized();
  return {e1, n.cross(e1)};
}

// The coupled equations of model/slosh.hpp in the rate model's coordinates: the derivative of
// x = [omega; q; q'] under the wrench (force, torque about the chaser's nominal centre of mass)
// and a torque disturbance on the body.
struct Equations {
  model::ChaserSloshParams slosh;
  std::vector<std::array<Vec3, 2>> basis;  // per tank
  int n = 0;                               // states

  Eigen::VectorXd derivative(const Eigen::VectorXd& x, const Vec6& wrench, const Vec3& disturbance, double mass_kg) const {
    const auto tanks = static_cast<std::size_t>(slosh.count);
    const Eigen::Index rates = 3 + 2 * static_cast<Eigen::Index>(tanks);  // where q' starts in x
    std::array<model::SloshState, model::kMaxSloshTanks> states{};
    for (std::size_t i = 0; i < tanks; ++i) {
      const auto k = static_cast<Eigen::Index>(2 * i);
      states[i].s_body_m = basis[i][0] * x(3 + k) + basis[i][1] * x(4 + k);
      states[i].s_dot_body_mps = basis[i][0] * x(rates + k) + basis[i][1] * x(rates + k + 1);
    }
    const model::RigidBodyMassProps body{.mass_kg = mass_kg - slosh.mass_kg,
                                         .inertia_com_body_kgm2 = slosh.body_inertia_kgm2,
                                         .com_body_m = slosh.body_com_body_m};
    const Vec3 force = wrench.head<3>();
    const Vec3 torque = Vec3(wrench.tail<3>()) + (slosh.com_body_m - slosh.body_com_body_m).cross(force) + disturbance;
    const model::SloshAccelerations a = model::coupled_accelerations(
        body, slosh.body_inertia_inv_kgm2, std::span(slosh.tanks.data(), tanks),
        std::span<const model::SloshState>(states.data(), tanks), Vec3(x.head<3>()), force, torque);
    Eigen::VectorXd dx(n);
    dx.head<3>() = a.omega_dot_body_radps2;
    for (std::size_t i = 0; i < tanks; ++i) {
      const auto k = static_cast<Eigen::Index>(2 * i);
      for (Eigen::Index j = 0; j < 2; ++j) {
        dx(3 + k + j) = basis[i][static_cast<std::size_t>(j)].dot(a.s_dot_body_mps[i]);
        dx(rates + k + j) = basis[i][static_cast<std::size_t>(j)].dot(a.s_ddot_body_mps2[i]);
      }
    }
    return dx;
  }
};

// Central differences about rest: exact for the linear terms; the products of two state
// components (the only non-linear terms at rest) cancel.
template <class F>
Eigen::MatrixXd jacobian(const F& f, int rows, int columns, double step) {
  Eigen::MatrixXd J(rows, columns);
  for (int j = 0; j < columns; ++j) J.col(j) = (f(j, step) - f(j, -step)) / (2.0 * step);
  return J;
}

}  // namespace

RateModel rate_model(const model::Scenario& s) {
  if (!s.chaser.slosh) throw std::invalid_argument("chaser.slosh: the rate model needs the tanks' slosh (absent)");
  model::SpacecraftParams chaser = s.chaser;
  chaser.slosh->model = model::SloshModel::spring_mass;  // the pendulum's small-swing limit at g_eff
  Equations eq{.slosh = model::chaser_slosh(chaser)};
  const int tanks = eq.slosh.count;
  eq.n = 3 + 4 * tanks;
  for (int i = 0; i < tanks; ++i) eq.basis.push_back(lateral_basis(eq.slosh.tanks[static_cast<std::size_t>(i)].axis_body));
  const double mass = s.chaser.mass_kg;

  RateModel m;
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(eq.n);
  m.A = jacobian([&](int j, double h) {
    Eigen::VectorXd x = rest;
    x(j) = h;
    return eq.derivative(x, Vec6::Zero(), Vec3::Zero(), mass);
  }, eq.n, eq.n, 1e-6);
  const Eigen::MatrixXd B_wrench = jacobian([&](int j, double h) {
    Vec6 w = Vec6::Zero();
    w(j) = h;
    return eq.derivative(rest, w, Vec3::Zero(), mass);
  }, eq.n, 6, 1.0);
  m.E = jacobian([&](int j, double h) {
    Vec3 d = Vec3::Zero();
    d(j) = h;
    return eq.derivative(rest, Vec6::Zero(), d, mass);
  }, eq.n, 3, 1.0);
  const model::ThrusterMask active = model::initial_active_set(s.thrusters);
  const Eigen::Matrix<double, 6, Eigen::Dynamic> config = model::configuration_columns(s.thrusters, active, s.chaser.com_body_m);
  m.B = B_wrench * config;
  m.thrusters = static_cast<int>(config.cols());
  m.C = Eigen::MatrixXd::Zero(3, eq.n);
  m.C.leftCols<3>().setIdentity();
  m.state_names = {"omega_x", "omega_y", "omega_z"};
  for (const char* kind : {"q", "q_dot"})
    for (int i = 0; i < tanks; ++i)
      for (int j = 1; j <= 2; ++j) m.state_names.push_back(std::string(kind) + std::to_string(i + 1) + "_" + std::to_string(j));

  // Modes: the rigid rates (eigenvalue 0, the first three states) and the slosh pairs.
  const Eigen::EigenSolver<Eigen::MatrixXd> eig(m.A);
  struct Pair { std::complex<double> lambda; Eigen::VectorXcd v; };
  std::vector<Pair> pairs;
  for (Eigen::Index k = 0; k < eq.n; ++k)
    if (eig.eigenvalues()(k).imag() > 1e-9) pairs.push_back({eig.eigenvalues()(k), eig.eigenvectors().col(k)});
  std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) { return a.lambda.imag() < b.lambda.imag(); });
  if (static_cast<int>(pairs.size()) != 2 * tanks)
    throw std::invalid_argument("chaser.slosh: the rate model found " + std::to_string(pairs.size()) +
                                " oscillating slosh modes, expected " + std::to_string(2 * tanks) +
                                " (an undamped or overdamped tank?)");
  // The real basis [rigid; (Re v, Im v) per pair] and its inverse, whose rows project onto each mode.
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(eq.n, eq.n);
  T.topLeftCorner<3, 3>().setIdentity();
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    T.col(3 + 2 * static_cast<Eigen::Index>(p)) = pairs[p].v.real();
    T.col(4 + 2 * static_cast<Eigen::Index>(p)) = pairs[p].v.imag();
  }
  const Eigen::MatrixXd W = T.inverse();
  std::vector<Eigen::Index> keep = {0, 1, 2};
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const auto r = 3 + 2 * static_cast<Eigen::Index>(p);
    SloshModeFigures f;
    f.frequency_radps = std::abs(pairs[p].lambda);
    f.damping_ratio = -pairs[p].lambda.real() / std::abs(pairs[p].lambda);
    const Eigen::MatrixXd left = W.middleRows(r, 2);
    f.controllability = (left * B_wrench).norm() / (left.norm() * B_wrench.norm());
    const Eigen::MatrixXd right = T.middleCols(r, 2);
    f.observability = (m.C * right).norm() / right.norm();
    f.kept = f.controllability > kRateModeTolerance && f.observability > kRateModeTolerance;
    if (f.kept) keep.insert(keep.end(), {r, r + 1});
    m.modes.push_back(f);
  }
  const auto k = static_cast<Eigen::Index>(keep.size());
  Eigen::MatrixXd T_keep(eq.n, k), W_keep(k, eq.n);
  for (Eigen::Index i = 0; i < k; ++i) {
    T_keep.col(i) = T.col(keep[static_cast<std::size_t>(i)]);
    W_keep.row(i) = W.row(keep[static_cast<std::size_t>(i)]);
  }
  m.A_reduced = W_keep * m.A * T_keep;
  m.B_reduced = W_keep * m.B;
  m.E_reduced = W_keep * m.E;
  m.C_reduced = m.C * T_keep;
  return m;
}

}  // namespace chaser::flight::fdi
