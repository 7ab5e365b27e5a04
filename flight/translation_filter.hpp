#pragma once
// Translational navigation: steady-state Kalman filter on the discrete HCW model (MSR LVLH).
//
//   predict:  x- = Ad x+ + Bd F_cmd / m          x = [r_lvlh; v_lvlh], F_cmd the force commanded
//   correct:  x+ = x- + L (y_lidar - r-)          over the period just ended (a known input)
//
// Process noise: an unmodelled acceleration, 1-sigma sigma_a per axis, held over each period, so
// W = sigma_a^2 Bd Bd' (Bd of the acceleration input). Measurement noise V = sigma_lidar^2 I.
// L is the steady-state gain from the filter DARE (core/riccati.hpp, steady_state_kalman); the
// corrected covariance P+ that comes with it is the accuracy the filter claims.
#include "core/types.hpp"
#include "core/linear_models.hpp"

namespace chaser::flight {

struct TranslationFilterParams {
  Mat6 Ad = Mat6::Identity();       // HCW transition over one period
  Mat63 Bd_force = Mat63::Zero();   // [1/kg ...] response to a held force, Bd / m
  Mat63 L = Mat63::Zero();          // [-, 1/s] steady-state measurement-update gain
  Mat6 P_corrected = Mat6::Zero();  // [m^2, m^2/s, m^2/s^2] steady-state covariance after update
  bool design_converged = false;    // the filter Riccati solver converged
};

TranslationFilterParams design_translation_filter(double mean_motion_radps, double period_s, double mass_kg,
                                                  double accel_noise_sigma_mps2, double lidar_noise_sigma_m);

struct TranslationFilterState {
  Vec6 x = Vec6::Zero();  // [m, m/s] estimate [r_lvlh; v_lvlh]
};

void predict_translation(const TranslationFilterParams& params, TranslationFilterState& state,
                         const Vec3& force_cmd_lvlh_N);
void correct_translation(const TranslationFilterParams& params, TranslationFilterState& state,
                         const Vec3& r_measured_lvlh_m);

}  // namespace chaser::flight
