#include "invsim/measurement_link.hpp"

namespace chaser::invsim {

MeasurementLink::MeasurementLink(const model::InvSimMeasurementNoise& noise) : noise_(noise) {
  if (noise_.enabled()) rng_.emplace(noise_.seed, "invsim.measurement");
}

Vec3 MeasurementLink::measured_position_hill_m(const Vec3& r_hill_m, double range_m) {
  if (!rng_) return r_hill_m;
  const double d_range_m = noise_.range_sigma_m * rng_->normal();
  const double d_azimuth_rad = noise_.angle_sigma_rad * rng_->normal();
  const double d_elevation_rad = noise_.angle_sigma_rad * rng_->normal();
  // Eq. 14 to first order (header): along the line of sight, then across it at the range.
  return r_hill_m + Vec3(d_range_m, range_m * d_azimuth_rad, range_m * d_elevation_rad);
}

}  // namespace chaser::invsim
