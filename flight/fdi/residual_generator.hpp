#pragma once
// On-board residual generator (Fonod 2015, eq. 30), evaluated every control period:
//   r(k)       = Q (y(k) - C x_hat(k))
//   x_hat(k+1) = (A_bar - L C) x_hat(k) + B_bar u_c(k) + L y(k)
// with the matrices of the offline design (residual_design.hpp). Fixed sizes: n_x = 6, n_y = 3,
// n_u = 3, n_r <= 3 held in an int; rows of Q at and beyond n_r are zero, so r has zeros there.
//
// u_c(k) is the input of the design model: position model, the commanded force in LVLH [N]
// (R(Q_tgt, Q_chs) M_F T_on, eq. 20; the caller rotates with its estimated attitude); attitude
// model, the commanded torque M_C T_on [N m]. The observer assumes no delay (l = 0): the delay is
// the unknown input the design attenuates.
//
// Start: the first call sets x_hat = C^+ y(0) (C^+ = C^T (C C^T)^-1; for C = [I 0] the position or
// angle part is y(0) and the rate part 0), so r(0) = 0 and the start transient is only the
// unknown rate, which decays with the observer eigenvalues.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace chaser::flight::fdi {

struct ResidualDesign;  // residual_design.hpp, the offline design

inline constexpr int kFdiStateDim = 6;   // n_x
inline constexpr int kFdiOutputDim = 3;  // n_y
inline constexpr int kFdiInputDim = 3;   // n_u

using Mat63 = Eigen::Matrix<double, kFdiStateDim, kFdiOutputDim>;
using Mat36 = Eigen::Matrix<double, kFdiOutputDim, kFdiStateDim>;

struct ResidualGeneratorParams {
  Mat6 A_c = Mat6::Zero();      // [-] A_bar - L C
  Mat63 B_bar = Mat63::Zero();  // [state unit per input unit] eq. 22
  Mat63 L = Mat63::Zero();      // [-] observer gain, eq. 38
  Mat36 C = Mat36::Zero();      // [-] output matrix
  Mat3 Q = Mat3::Zero();        // [-] residual weighting, rows >= residual_dim are zero (eq. 33)
  Mat63 x_from_y = Mat63::Zero();  // [-] C^+, the initial estimate from the first measurement
  int residual_dim = 1;         // n_r, 1..3
};

struct ResidualGeneratorState {
  Vec6 x_hat = Vec6::Zero();  // state estimate x_hat(k) (position or angle, then rate)
  bool started = false;       // false until the first measurement has set x_hat
};

// Converts the offline design (dynamic sizes) to runtime parameters. Throws std::invalid_argument
// if the design is not 6 states, 3 outputs, 3 inputs and 1..3 residuals (offline only).
ResidualGeneratorParams make_residual_generator(const ResidualDesign& design);

// Problems with hand-made parameters (empty when valid), each naming the field.
std::vector<std::string> validate(const ResidualGeneratorParams& params);

// One period of eq. 30: returns r(k) (entries >= n_r are zero) and advances x_hat to k + 1.
// y: measurement of period k [m or rad]; u_c: model input of period k [N or N m].
Vec3 step_residual(const ResidualGeneratorParams& params, ResidualGeneratorState& state,
                   const Vec3& y, const Vec3& u_c);

}  // namespace chaser::flight::fdi
