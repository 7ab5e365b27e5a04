#include "invsim/sensor_geometry.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace chaser::invsim {

LineOfSight line_of_sight(const Vec3& r_hill_m, const Mat3& r_hill_from_body,
                          const Vec3& sensor_body_m) {
  const Vec3 p_t_body = -r_hill_from_body.transpose() * r_hill_m - sensor_body_m;  // eq. 13
  const Vec3 p_t_meas(-p_t_body.x(), p_t_body.y(), -p_t_body.z());
  const double rho = p_t_meas.norm();
  LineOfSight los{rho, 0.0, 0.0};
  if (rho > 0.0) {
    los.azimuth_rad = std::atan2(p_t_meas.y(), p_t_meas.x());               // eq. 12
    los.elevation_rad = std::asin(std::clamp(p_t_meas.z() / rho, -1.0, 1.0));
  }
  return los;
}

bool target_in_view(const LineOfSight& los, double azimuth_limit_rad, double elevation_limit_rad) {
  return std::abs(los.azimuth_rad) <= azimuth_limit_rad &&
         std::abs(los.elevation_rad) <= elevation_limit_rad;
}

double max_lateral_offset_m(double range_m, double view_limit_rad, double attitude_limit_rad,
                            double sensor_offset_m) {
  return range_m * (view_limit_rad - attitude_limit_rad) - std::abs(sensor_offset_m);
}

Vec3 euler321_from_matrix(const Mat3& r) {
  const double pitch = -std::asin(std::clamp(r(2, 0), -1.0, 1.0));
  return Vec3(std::atan2(r(2, 1), r(2, 2)), pitch, std::atan2(r(1, 0), r(0, 0)));
}

Mat3 matrix_from_euler321(const Vec3& e) {
  return (Eigen::AngleAxisd(e.z(), Vec3::UnitZ()) * Eigen::AngleAxisd(e.y(), Vec3::UnitY()) *
          Eigen::AngleAxisd(e.x(), Vec3::UnitX()))
      .toRotationMatrix();
}

}  // namespace chaser::invsim
