#include "flight/translation_filter.hpp"

#include "core/riccati.hpp"

namespace chaser::flight {

TranslationFilterParams design_translation_filter(double mean_motion_radps, double period_s, double mass_kg,
                                                  double accel_noise_sigma_mps2, double lidar_noise_sigma_m) {
  const DiscreteLinear6 model = discrete_hcw(mean_motion_radps, period_s);
  const Mat6 process_cov = accel_noise_sigma_mps2 * accel_noise_sigma_mps2 * model.Bd * model.Bd.transpose();
  const Mat3 lidar_cov = lidar_noise_sigma_m * lidar_noise_sigma_m * Mat3::Identity();
  Mat36 c = Mat36::Zero();
  c.leftCols<3>().setIdentity();
  const KalmanDesign kf = steady_state_kalman(model.Ad, c, process_cov, lidar_cov);
  TranslationFilterParams params;
  params.Ad = model.Ad;
  params.Bd_force = model.Bd / mass_kg;
  params.L = kf.L;
  params.P_corrected = kf.P_corrected;
  params.design_converged = kf.converged;
  return params;
}

void predict_translation(const TranslationFilterParams& params, TranslationFilterState& state,
                         const Vec3& force_cmd_lvlh_N) {
  state.x = params.Ad * state.x + params.Bd_force * force_cmd_lvlh_N;
}

void correct_translation(const TranslationFilterParams& params, TranslationFilterState& state,
                         const Vec3& r_measured_lvlh_m) {
  const Vec3 innovation = r_measured_lvlh_m - state.x.head<3>();
  state.x += params.L * innovation;
}

}  // namespace chaser::flight
