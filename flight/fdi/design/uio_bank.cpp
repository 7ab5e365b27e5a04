#include "flight/fdi/design/uio_bank.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "control/discrete_riccati.hpp"
#include "core/constants.hpp"
#include "core/discretize.hpp"

namespace chaser::flight::fdi {

using Eigen::MatrixXd;

namespace {

constexpr double kTorqueRankTolerance = 1e-6;  // [-] |C F_i| / max_j |C F_j| below: thruster i has no torque to decouple
constexpr double kRiccatiResidualMax = 1e-8;   // [-] relative DARE residual above: the solution is not trusted
constexpr double kGammaRelTolerance = 1e-3;    // [-] gamma_min's bisection stops when hi / lo is below 1 + this

double spectral_radius(const MatrixXd& a) { return a.eigenvalues().cwiseAbs().maxCoeff(); }

// Orthonormal rows spanning the complement of the unit vector u in R^3.
MatrixXd complement_rows(const Eigen::Vector3d& u) {
  Eigen::Index least = 0;
  u.cwiseAbs().minCoeff(&least);
  const Eigen::Vector3d e1 = u.cross(Eigen::Vector3d::Unit(least)).normalized();
  const Eigen::Vector3d e2 = u.cross(e1);
  MatrixXd q(2, 3);
  q.row(0) = e1.transpose();
  q.row(1) = e2.transpose();
  return q;
}

// The fixed part of observer i: everything but the gain.
struct Decoupled {
  MatrixXd H, T, A1, G, Q, Bw, Dv;
};

struct Gain {
  MatrixXd K, N;
};

// The central a-priori H-infinity gain at gamma, when gamma is admissible (see the header).
std::optional<Gain> hinf_gain(const Decoupled& d, const MatrixXd& C, double sigma_v, double gamma) {
  const Eigen::Index n = d.A1.rows();
  const MatrixXd QC = d.Q * C;
  const Eigen::Index q = QC.rows();
  MatrixXd M(q + C.rows(), n);
  M << QC, C;
  MatrixXd R = MatrixXd::Zero(M.rows(), M.rows());
  R.topLeftCorner(q, q) = sigma_v * sigma_v * MatrixXd::Identity(q, q);
  R.bottomRightCorner(3, 3) = -gamma * gamma * MatrixXd::Identity(3, 3);
  // The filter's equation is the control equation of the dual: A -> A1', B -> M'.
  const control::DareResult dare = control::solve_dare(d.A1.transpose(), M.transpose(), d.Bw * d.Bw.transpose(), R);
  if (!dare.ok || dare.residual > kRiccatiResidualMax) return std::nullopt;
  const MatrixXd& P = dare.X;
  const double scale = std::max(P.norm(), std::numeric_limits<double>::min());
  if (Eigen::SelfAdjointEigenSolver<MatrixXd>(P).eigenvalues().minCoeff() < -1e-9 * scale) return std::nullopt;
  const MatrixXd cpc = C * P * C.transpose();
  if (Eigen::SelfAdjointEigenSolver<MatrixXd>(gamma * gamma * MatrixXd::Identity(3, 3) - cpc).eigenvalues().minCoeff() <= 0)
    return std::nullopt;
  const MatrixXd S = sigma_v * sigma_v * MatrixXd::Identity(q, q) + QC * P * QC.transpose();
  Gain g;
  g.K = d.A1 * P * QC.transpose() * S.inverse();
  g.N = d.A1 - g.K * QC;
  if (spectral_radius(g.N) >= 1.0) return std::nullopt;
  return g;
}

// Steady-state covariance of eps(k+1) = N eps + B w, w unit white: vec(S) = (I - N (x) N)^-1 vec(B B').
MatrixXd steady_covariance(const MatrixXd& N, const MatrixXd& B) {
  const Eigen::Index n = N.rows();
  MatrixXd kron(n * n, n * n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) kron.block(i * n, j * n, n, n) = N(i, j) * N;
  const MatrixXd W = B * B.transpose();
  const Eigen::VectorXd vec_s =
      (MatrixXd::Identity(n * n, n * n) - kron).partialPivLu().solve(Eigen::Map<const Eigen::VectorXd>(W.data(), n * n));
  const MatrixXd S = Eigen::Map<const MatrixXd>(vec_s.data(), n, n);
  return 0.5 * (S + S.transpose());
}

double sigma_max_at(const MatrixXd& A, const MatrixXd& B, const MatrixXd& C, const MatrixXd& D, double theta) {
  const Eigen::Index n = A.rows();
  const Eigen::MatrixXcd zI = std::polar(1.0, theta) * Eigen::MatrixXcd::Identity(n, n);
  const Eigen::MatrixXcd g = C.cast<std::complex<double>>() *
                                 (zI - A.cast<std::complex<double>>()).partialPivLu().solve(B.cast<std::complex<double>>()) +
                             D.cast<std::complex<double>>();
  return Eigen::JacobiSVD<Eigen::MatrixXcd>(g).singularValues()(0);
}

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

// Observer `thruster` (-1: the nominal one) from its decoupling H and residual directions Q.
UioObserver design_observer(const UioBank& bank, Decoupled d, const UioBankParams& p, int thruster) {
  const MatrixXd& C = bank.C;
  const Eigen::Index n = bank.Ad.rows();
  const double sv = p.gyro_noise_radps, sd = p.disturbance_torque_Nm;
  const std::string who = thruster < 0 ? "the nominal observer" : "thruster " + std::to_string(thruster + 1);
  d.T = MatrixXd::Identity(n, n) - d.H * C;
  d.A1 = d.T * bank.Ad;
  d.G = d.T * bank.Bd;
  const Eigen::Index q = d.Q.rows();
  d.Bw.resize(n, 6);
  d.Bw << d.T * bank.Ed * sd, -d.A1 * d.H * sv;
  d.Dv = MatrixXd::Zero(q, 6);
  d.Dv.rightCols(3) = sv * d.Q;

  // Bracket gamma_min between lo (not admissible) and hi (admissible), starting from the gyro's
  // noise (gamma_min is a few times it: the rate error cannot beat the gyro), then bisect
  // geometrically.
  double lo = sv, hi = sv;
  if (hinf_gain(d, C, sv, hi)) {
    for (int k = 0; k < 200 && hinf_gain(d, C, sv, lo); ++k) hi = lo, lo /= 2.0;
  } else {
    int k = 0;
    for (; k < 200 && !hinf_gain(d, C, sv, hi); ++k) lo = hi, hi *= 2.0;
    require(k < 200, "uio bank: no admissible gamma for " + who);
  }
  while (hi > lo * (1.0 + kGammaRelTolerance)) {
    const double mid = std::sqrt(lo * hi);
    if (hinf_gain(d, C, sv, mid)) hi = mid; else lo = mid;
  }
  UioObserver o;
  o.thruster = thruster;
  o.gamma_min = hi;
  o.gamma = p.gamma_backoff * hi;
  const std::optional<Gain> gain = hinf_gain(d, C, sv, o.gamma);
  require(gain.has_value(), "uio bank: " + who + ": gamma_backoff x gamma_min not admissible");
  o.K = gain->K;
  o.N = gain->N;
  o.H = d.H;
  o.G = d.G;
  o.Q = d.Q;
  o.L = o.K * d.Q + o.N * d.H;
  o.spectral_radius = spectral_radius(o.N);
  if (!p.figures) return o;
  const MatrixXd Be = d.Bw - o.K * d.Dv;  // eps(k+1) = N eps + Be w
  o.gamma_sweep = discrete_hinf_norm(o.N, Be, C, MatrixXd::Zero(3, 6));
  const MatrixXd S = steady_covariance(o.N, Be);
  o.residual_noise_rms =
      std::sqrt((d.Q * C * S * C.transpose() * d.Q.transpose()).trace() + static_cast<double>(q) * sv * sv);
  return o;
}

}  // namespace

double discrete_hinf_norm(const MatrixXd& A, const MatrixXd& B, const MatrixXd& C, const MatrixXd& D) {
  // A grid dense at low frequency (the slosh modes sit near 0.01 rad per sample), then a golden
  // search around the best point.
  constexpr int kGrid = 2000;
  double best = sigma_max_at(A, B, C, D, 0.0), best_theta = 0.0;
  for (int k = 0; k <= kGrid; ++k) {
    const double theta = kPi * std::pow(1e-6, 1.0 - static_cast<double>(k) / kGrid);
    const double s = sigma_max_at(A, B, C, D, theta);
    if (s > best) best = s, best_theta = theta;
  }
  const double ratio = std::pow(1e-6, -1.0 / kGrid);  // between neighbouring grid points
  double lo = best_theta / ratio, hi = std::min(kPi, best_theta * ratio);
  if (best_theta == 0.0) lo = 0.0, hi = kPi * 1e-6;
  const double phi = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 100 && hi - lo > 1e-12 * std::max(1.0, hi); ++it) {
    const double a = hi - phi * (hi - lo), b = lo + phi * (hi - lo);
    const double sa = sigma_max_at(A, B, C, D, a), sb = sigma_max_at(A, B, C, D, b);
    best = std::max({best, sa, sb});
    if (sa > sb) hi = b; else lo = a;
  }
  return best;
}

UioBank design_uio_bank(const RateModel& model, const UioBankParams& p) {
  require(std::isfinite(p.period_s) && p.period_s > 0, "uio bank: period_s must be > 0");
  require(std::isfinite(p.gyro_noise_radps) && p.gyro_noise_radps > 0, "uio bank: gyro noise must be > 0 rad/s");
  require(std::isfinite(p.disturbance_torque_Nm) && p.disturbance_torque_Nm > 0,
          "uio bank: disturbance_torque_Nm must be > 0");
  require(std::isfinite(p.gamma_backoff) && p.gamma_backoff > 1.0 && p.gamma_backoff <= 10.0,
          "uio bank: gamma_backoff must be in (1, 10]");
  UioBank bank;
  const Eigen::Index n = model.A_reduced.rows();
  MatrixXd inputs(n, model.B_reduced.cols() + model.E_reduced.cols());
  inputs << model.B_reduced, model.E_reduced;
  const DiscreteModel dm = discretize_zoh(model.A_reduced, inputs, p.period_s);
  bank.Ad = dm.Ad;
  bank.Bd = dm.Bd.leftCols(model.B_reduced.cols());
  bank.Ed = dm.Bd.rightCols(model.E_reduced.cols());
  bank.C = model.C_reduced;
  const MatrixXd& C = bank.C;
  {
    Decoupled nominal;  // mode 0: no thruster decoupled, every rate a residual
    nominal.H = MatrixXd::Zero(n, 3);
    nominal.Q = MatrixXd::Identity(3, 3);
    bank.nominal = design_observer(bank, nominal, p, -1);
  }
  if (!p.decoupled) return bank;
  const double largest_rate = (C * bank.Bd).colwise().norm().maxCoeff();
  for (int i = 0; i < bank.Bd.cols(); ++i) {
    const Eigen::VectorXd F = bank.Bd.col(i);
    const Eigen::Vector3d CF = C * F;
    require(CF.norm() > kTorqueRankTolerance * largest_rate,
            "uio bank: thruster " + std::to_string(i + 1) + " has no torque: no observer can decouple it from the rates");
    Decoupled d;
    d.H = F * CF.transpose() / CF.squaredNorm();  // F (C F)^+
    d.Q = complement_rows(CF.normalized());
    bank.observers.push_back(design_observer(bank, d, p, i));
  }

  if (!p.figures) return bank;
  const auto m = static_cast<Eigen::Index>(bank.observers.size());
  bank.fault_gain = MatrixXd::Zero(m, bank.Bd.cols());
  for (Eigen::Index o = 0; o < m; ++o) {
    const UioObserver& obs = bank.observers[static_cast<std::size_t>(o)];
    const MatrixXd steady = (MatrixXd::Identity(n, n) - obs.N).partialPivLu().solve(obs.G);  // eps per unit fault
    for (Eigen::Index j = 0; j < bank.Bd.cols(); ++j) bank.fault_gain(o, j) = (obs.Q * C * steady.col(j)).norm();
  }
  const double scale = bank.fault_gain.maxCoeff();
  for (Eigen::Index j = 0; j < bank.Bd.cols(); ++j) {
    std::vector<int> blind;
    int closest = -1;
    double snr = std::numeric_limits<double>::infinity();
    for (Eigen::Index o = 0; o < m; ++o) {
      if (o == j) continue;
      if (bank.fault_gain(o, j) < kUioBlindTolerance * scale) {
        blind.push_back(static_cast<int>(o));
        continue;
      }
      const double s = bank.fault_gain(o, j) / bank.observers[static_cast<std::size_t>(o)].residual_noise_rms;
      if (s < snr) snr = s, closest = static_cast<int>(o);
    }
    bank.blind.push_back(std::move(blind));
    bank.closest.push_back(closest);
    bank.isolation_snr.push_back(snr);
  }
  return bank;
}

UioBankParams uio_bank_params(const model::Scenario& scenario) {
  UioBankParams p;
  p.period_s = scenario.control_period_s;
  p.gyro_noise_radps = scenario.sensors.gyro.noise_sigma_radps;
  p.disturbance_torque_Nm = scenario.fdi.observer_bank.disturbance_torque_Nm;
  p.gamma_backoff = scenario.fdi.observer_bank.gamma_backoff;
  return p;
}

UioBank design_uio_bank(const model::Scenario& scenario, bool figures) {
  UioBankParams p = uio_bank_params(scenario);
  p.figures = figures;
  return design_uio_bank(rate_model(scenario), p);
}

}  // namespace chaser::flight::fdi
