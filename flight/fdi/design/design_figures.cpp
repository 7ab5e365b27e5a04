#include "flight/fdi/design/design_figures.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>

#include "core/constants.hpp"

namespace chaser::flight::fdi {

using Eigen::Index;
using Eigen::MatrixXcd;
using Eigen::MatrixXd;
using Eigen::VectorXd;

MatrixXcd residual_resolvent(const MatrixXd& A_c, const MatrixXd& QC, std::complex<double> z) {
  const Index n = A_c.rows();
  const MatrixXcd m = z * MatrixXcd::Identity(n, n) - A_c.cast<std::complex<double>>();
  // R (zI - A_c) = QC  <=>  (zI - A_c)^T R^T = QC^T
  return m.transpose().partialPivLu().solve(QC.transpose().cast<std::complex<double>>()).transpose();
}

VectorXd dc_fault_gains(const MatrixXd& A_c, const MatrixXd& QC, const MatrixXd& E_f_bar) {
  const Index n = A_c.rows();
  const MatrixXd R = (MatrixXd::Identity(n, n) - A_c).transpose().partialPivLu().solve(QC.transpose()).transpose();
  return (R * E_f_bar).colwise().norm().transpose();
}

namespace {

double max_singular_value(const MatrixXcd& m) {
  if (m.size() == 0) return 0.0;
  return Eigen::JacobiSVD<MatrixXcd>(m).singularValues()(0);
}

std::vector<std::complex<double>> sorted_eigenvalues(const MatrixXd& A_c) {
  const Eigen::VectorXcd ev = Eigen::EigenSolver<MatrixXd>(A_c, false).eigenvalues();
  std::vector<std::complex<double>> v(ev.data(), ev.data() + ev.size());
  std::sort(v.begin(), v.end(), [](const auto& a, const auto& b) {
    return a.real() != b.real() ? a.real() < b.real() : a.imag() < b.imag();
  });
  return v;
}

}  // namespace

DesignFigures compute_design_figures(const ObserverUnderTest& o, const FigureOptions& options) {
  const MatrixXd A_c = o.A_bar - o.L * o.C;
  const MatrixXd QC = o.Q * o.C;
  const int nf = std::max(options.frequency_points, 1);
  const Index n_faults = o.E_f_bar.cols();
  const bool per_thruster = o.fault_inputs.size() > 0;
  DesignFigures fig;
  fig.achieved_eigenvalues = sorted_eigenvalues(A_c);
  fig.unknown_input_gain.resize(nf);
  fig.designed_input_gain.resize(nf);
  fig.delay_gain.resize(nf);
  fig.fault_gain.resize(nf, n_faults);
  fig.command_delay_gain_max = VectorXd::Zero(per_thruster ? o.fault_inputs.cols() : 0);
  for (int j = 0; j < nf; ++j) {
    const double f_hz = nf > 1 ? j / (nf - 1.0) / (2.0 * o.period_s) : 0.0;
    fig.frequency_hz.push_back(f_hz);
    const std::complex<double> z = std::polar(1.0, 2.0 * kPi * f_hz * o.period_s);
    const MatrixXcd R = residual_resolvent(A_c, QC, z);
    const double difference = std::abs(1.0 - 1.0 / z);  // u(k-1) - u(k), eq. 21
    fig.unknown_input_gain(j) = max_singular_value(R * o.E_d);
    fig.designed_input_gain(j) = max_singular_value(R * o.E_d_star);
    fig.fault_gain.row(j) = (R * o.E_f_bar).colwise().norm();
    fig.delay_gain(j) = 0.0;
    for (const MatrixXd& gamma : o.gamma1_samples) {
      const MatrixXcd Rg = difference * (R * gamma);
      fig.delay_gain(j) = std::max(fig.delay_gain(j), max_singular_value(Rg));
      if (per_thruster)
        fig.command_delay_gain_max = fig.command_delay_gain_max.cwiseMax((Rg * o.fault_inputs).colwise().norm().transpose());
    }
  }
  fig.fault_gain_dc = fig.fault_gain.row(0).transpose();
  fig.unknown_input_gain_max = fig.unknown_input_gain.maxCoeff();
  fig.designed_input_gain_max = fig.designed_input_gain.maxCoeff();
  fig.delay_gain_max = fig.delay_gain.maxCoeff();
  return fig;
}

}  // namespace chaser::flight::fdi
