#include "flight/target_estimator.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "core/rotation.hpp"

namespace chaser::flight {

TargetEstimator::TargetEstimator(const TargetEstimatorParams& params)
    : params_(params), inertia_inv_(params.inertia_kgm2.inverse()) {}

namespace {

// q' = 1/2 q (x) (0, omega), in Quat::coeffs() order (the flight software's own copy: it never
// includes the plant's).
Eigen::Vector4d quat_rate(const Eigen::Vector4d& q_coeffs, const Vec3& omega) {
  return 0.5 * (Quat(q_coeffs) * Quat(0.0, omega.x(), omega.y(), omega.z())).coeffs();
}

// omega' of torque-free Euler.
Vec3 euler_rate(const Mat3& inertia, const Mat3& inertia_inv, const Vec3& omega) {
  return -inertia_inv * omega.cross(inertia * omega);
}

}  // namespace

// RK4 of the torque-free body (quaternion and rate together), and with `covariance` the error
// state's transition Phi = exp(F dt) to third order per substep (|F dt| <= |omega| dt, ~2e-3 at
// ENVISAT's 2.5 deg/s and 20 substeps a second) and its process noise, the torque noise's rate
// random walk. F = [-[omega x], I; 0, J], J = I^-1 ([(I omega) x] - [omega x] I) the Jacobian of Euler.
void TargetEstimator::propagate(double dt_s, Quat& q, Vec3& omega, Mat6x6* covariance) const {
  if (dt_s <= 0.0) return;
  const int steps = std::max(1, static_cast<int>(std::ceil(dt_s * params_.substeps_per_second)));
  const double h = dt_s / steps;
  const Mat3& inertia = params_.inertia_kgm2;
  const Mat3 torque_to_rate = inertia_inv_ * params_.torque_noise_Nm;
  const Mat3 rate_noise = torque_to_rate * torque_to_rate.transpose() * h;  // per substep
  for (int k = 0; k < steps; ++k) {
    if (covariance) {
      Mat6x6 f = Mat6x6::Zero();
      f.topLeftCorner<3, 3>() = -skew(omega);
      f.topRightCorner<3, 3>() = Mat3::Identity();
      f.bottomRightCorner<3, 3>() = inertia_inv_ * (skew(inertia * omega) - skew(omega) * inertia);
      const Mat6x6 fh = f * h;
      const Mat6x6 phi = Mat6x6::Identity() + fh + fh * fh / 2.0 + fh * fh * fh / 6.0;
      *covariance = phi * *covariance * phi.transpose();
      covariance->bottomRightCorner<3, 3>() += rate_noise;
    }
    const auto stage = [&](const Eigen::Vector4d& qc, const Vec3& w, Eigen::Vector4d& dq, Vec3& dw) {
      dq = quat_rate(qc, w);
      dw = euler_rate(inertia, inertia_inv_, w);
    };
    const Eigen::Vector4d q0 = q.coeffs();
    Eigen::Vector4d k1q, k2q, k3q, k4q;
    Vec3 k1w, k2w, k3w, k4w;
    stage(q0, omega, k1q, k1w);
    stage(q0 + 0.5 * h * k1q, omega + 0.5 * h * k1w, k2q, k2w);
    stage(q0 + 0.5 * h * k2q, omega + 0.5 * h * k2w, k3q, k3w);
    stage(q0 + h * k3q, omega + h * k3w, k4q, k4w);
    q.coeffs() = q0 + h / 6.0 * (k1q + 2.0 * k2q + 2.0 * k3q + k4q);
    q.normalize();
    omega += h / 6.0 * (k1w + 2.0 * k2w + 2.0 * k3w + k4w);
  }
}

bool TargetEstimator::update(double t_s, const Quat& measured) {
  if (!std::isfinite(t_s) || !measured.coeffs().allFinite() || measured.norm() < 0.5) return false;
  const Quat z = measured.normalized();
  const double r = params_.attitude_noise_rad * params_.attitude_noise_rad;
  if (!initialised_) {
    q_ = z;
    omega_.setZero();
    p_.setZero();
    p_.topLeftCorner<3, 3>() = Mat3::Identity() * r;
    p_.bottomRightCorner<3, 3>() =
        Mat3::Identity() * (params_.initial_rate_sigma_radps * params_.initial_rate_sigma_radps);
    t_s_ = t_s;
    initialised_ = true;
    return true;
  }
  if (t_s < t_s_) return false;
  propagate(t_s - t_s_, q_, omega_, &p_);
  t_s_ = t_s;
  // Innovation: the small rotation from the estimate to the measurement, target axes (the sign of
  // q is irrelevant: rotation_vector_from_quat takes the short way).
  const Vec3 innovation = rotation_vector_from_quat(q_.conjugate() * z);
  const Mat3 s = p_.topLeftCorner<3, 3>() + Mat3::Identity() * r;  // H = [I 0]
  const Eigen::LLT<Mat3> s_llt(s);
  last_nis_ = innovation.dot(s_llt.solve(innovation));
  const Eigen::Matrix<double, 6, 3> gain = p_.leftCols<3>() * s_llt.solve(Mat3::Identity());
  const Eigen::Matrix<double, 6, 1> correction = gain * innovation;
  // Joseph form keeps P symmetric and positive through rounding.
  Mat6x6 i_kh = Mat6x6::Identity();
  i_kh.leftCols<3>() -= gain;
  p_ = i_kh * p_ * i_kh.transpose() + gain * r * gain.transpose();
  q_ = (q_ * quat_from_rotation_vector(correction.head<3>())).normalized();
  omega_ += correction.tail<3>();
  return true;
}

TargetEstimate TargetEstimator::predict(double t_s) const {
  TargetEstimate out;
  Quat q = q_;
  Vec3 omega = omega_;
  // The state alone: its covariance would cost five 6 x 6 products a substep, a quarter of a
  // synchronisation run, for the telemetry's sigma only (header).
  propagate(std::max(0.0, t_s - t_s_), q, omega, nullptr);
  out.t_s = std::max(t_s, t_s_);
  out.q_inertial_from_target = q;
  out.omega_target_radps = omega;
  out.omega_dot_target_radps2 = euler_rate(params_.inertia_kgm2, inertia_inv_, omega);
  out.attitude_sigma_rad = p_.diagonal().head<3>().cwiseSqrt();
  out.rate_sigma_radps = p_.diagonal().tail<3>().cwiseSqrt();
  return out;
}

}  // namespace chaser::flight
