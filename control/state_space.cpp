#include "control/state_space.hpp"

#include <Eigen/LU>
#include <stdexcept>

namespace chaser::control {

using Eigen::Index;
using Eigen::MatrixXd;

namespace {

std::string dims(const MatrixXd& m) { return std::to_string(m.rows()) + " x " + std::to_string(m.cols()); }

// An ill-posed loop: I - D22 Dk numerically singular (reciprocal condition below this).
constexpr double kWellPosedRcond = 1e-12;

}  // namespace

std::vector<std::string> validate(const StateSpace& sys, const std::string& name) {
  std::vector<std::string> problems;
  const Index n = sys.a.rows(), m = sys.d.cols(), p = sys.d.rows();
  const auto require = [&](bool ok, const std::string& what) {
    if (!ok) problems.push_back(name + ": " + what);
  };
  require(sys.a.cols() == n, "a must be square (got " + dims(sys.a) + ")");
  require(sys.b.rows() == n && sys.b.cols() == m,
          "b must be " + std::to_string(n) + " x " + std::to_string(m) + " (got " + dims(sys.b) + ")");
  require(sys.c.rows() == p && sys.c.cols() == n,
          "c must be " + std::to_string(p) + " x " + std::to_string(n) + " (got " + dims(sys.c) + ")");
  require(sys.a.allFinite() && sys.b.allFinite() && sys.c.allFinite() && sys.d.allFinite(),
          "every entry must be finite");
  return problems;
}

StateSpace static_gain(const MatrixXd& d) {
  return StateSpace{MatrixXd(0, 0), MatrixXd(0, d.cols()), MatrixXd(d.rows(), 0), d};
}

StateSpace lower_lft(const StateSpace& p, int n_meas, int n_ctrl, const StateSpace& k) {
  std::vector<std::string> problems = validate(p, "plant P");
  for (std::string& s : validate(k, "controller K")) problems.push_back(std::move(s));
  // At least one exogenous input w and one performance output z must remain.
  if (n_meas < 1 || n_meas >= p.outputs())
    problems.push_back("n_meas must be in 1.." + std::to_string(p.outputs() - 1) + " (P has " +
                       std::to_string(p.outputs()) + " outputs; got " + std::to_string(n_meas) + ")");
  if (n_ctrl < 1 || n_ctrl >= p.inputs())
    problems.push_back("n_ctrl must be in 1.." + std::to_string(p.inputs() - 1) + " (P has " +
                       std::to_string(p.inputs()) + " inputs; got " + std::to_string(n_ctrl) + ")");
  if (k.inputs() != n_meas || k.outputs() != n_ctrl)
    problems.push_back("controller K must have n_meas = " + std::to_string(n_meas) + " inputs and n_ctrl = " +
                       std::to_string(n_ctrl) + " outputs (got " + dims(k.d) + ", outputs x inputs)");
  if (problems.empty()) {
    const MatrixXd loop = MatrixXd::Identity(n_meas, n_meas) - p.d.bottomRightCorner(n_meas, n_ctrl) * k.d;
    if (Eigen::FullPivLU<MatrixXd>(loop).rcond() < kWellPosedRcond)
      problems.push_back("I - D22 Dk is singular: the loop is not well posed");
  }
  if (!problems.empty()) {
    std::string all = "lower_lft: invalid input:";
    for (const std::string& s : problems) all += "\n  " + s;
    throw std::invalid_argument(all);
  }

  const Index n = p.states(), nk = k.states();
  const Index n_z = p.outputs() - n_meas, n_w = p.inputs() - n_ctrl;
  const MatrixXd B1 = p.b.leftCols(n_w), B2 = p.b.rightCols(n_ctrl);
  const MatrixXd C1 = p.c.topRows(n_z), C2 = p.c.bottomRows(n_meas);
  const MatrixXd D11 = p.d.topLeftCorner(n_z, n_w), D12 = p.d.topRightCorner(n_z, n_ctrl);
  const MatrixXd D21 = p.d.bottomLeftCorner(n_meas, n_w), D22 = p.d.bottomRightCorner(n_meas, n_ctrl);
  // R = (I - D22 Dk)^-1 and R~ = (I - Dk D22)^-1; the loop equations u = Dk y + Ck xk,
  // y = C2 x + D21 w + D22 u solve to u = R~ (Dk C2 x + Ck xk + Dk D21 w) and y = R (...).
  const MatrixXd R = (MatrixXd::Identity(n_meas, n_meas) - D22 * k.d).inverse();
  const MatrixXd Rt = (MatrixXd::Identity(n_ctrl, n_ctrl) - k.d * D22).inverse();

  StateSpace cl;
  cl.a.resize(n + nk, n + nk);
  cl.a << p.a + B2 * Rt * k.d * C2, B2 * Rt * k.c,  //
      k.b * R * C2, k.a + k.b * R * D22 * k.c;
  cl.b.resize(n + nk, n_w);
  cl.b << B1 + B2 * Rt * k.d * D21, k.b * R * D21;
  cl.c.resize(n_z, n + nk);
  cl.c << C1 + D12 * Rt * k.d * C2, D12 * Rt * k.c;
  cl.d = D11 + D12 * Rt * k.d * D21;
  return cl;
}

}  // namespace chaser::control
