#pragma once
// Relative-navigation sensor geometry (Zhou 2018, eqs. 12-16), manual-RVD Hill frame.
//
// The chaser at p (Hill, from the target's centre of mass) sees the target through a sensor at
// p_s (body, from the chaser's centre of mass); the line of sight is p_t = -p - C_bh p_s (eq. 13),
// in body axes p_t_body = -C_hb p - p_s. The measurement frame looks along -x_body:
// x_r = -x_b, y_r = y_b, z_r = -z_b (a right-handed half turn about y_b; the paper's text gives
// a left-handed set). Eq. 12 then defines
//   rho = |p_t|, azimuth = atan2(y_t, x_t), elevation = asin(z_t / rho),
// which for small angles reduces to eq. 15:
//   azimuth   = psi   - atan((y + y_s) / rho)
//   elevation = theta + atan((z + z_s) / rho)
// (the paper prints -atan for the elevation: with z towards the Earth and its own pitch sign, the
// two terms of eq. 15 cannot both hold in one right-handed frame; only |elevation| is checked).
#include "core/types.hpp"

namespace chaser::invsim {

struct LineOfSight {
  double range_m;        // rho [m]
  double azimuth_rad;    // theta_az [rad]
  double elevation_rad;  // theta_el [rad]
};

// r_hill_m: chaser centre of mass from the target's; r_hill_from_body: attitude (Hill from body).
LineOfSight line_of_sight(const Vec3& r_hill_m, const Mat3& r_hill_from_body,
                          const Vec3& sensor_body_m);

// The target is inside the field of view (|azimuth| and |elevation| within their limits).
bool target_in_view(const LineOfSight& los, double azimuth_limit_rad, double elevation_limit_rad);

// Largest lateral offset that keeps the target in view at the largest attitude error (eq. 16,
// with the signs of |psi|max - |theta_az|max read as a margin: rho (|az|max - |psi|max) - |y_s|).
double max_lateral_offset_m(double range_m, double view_limit_rad, double attitude_limit_rad,
                            double sensor_offset_m);

// Euler angles (roll phi, pitch theta, yaw psi) of the 3-2-1 sequence R = Rz(psi) Ry(theta) Rx(phi)
// used by eq. 11, and back.
Vec3 euler321_from_matrix(const Mat3& r_hill_from_body);
Mat3 matrix_from_euler321(const Vec3& euler_rad);

}  // namespace chaser::invsim
