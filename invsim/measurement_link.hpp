#pragma once
// The measurement link of Zhou 2018, Fig. 3: what the inverse model (the astronaut) sees of the
// relative state. Perfect unless the paper reading sets measurement noise
// (model::InvSimMeasurementNoise; docs/invsim.md, "Readings of App. B").
//
// The sensor measures the range rho and the azimuth and elevation of the target (eqs. 12-15);
// eq. 14 turns them into the position x = rho - x_s, y = rho tan(psi - az) - y_s,
// z = -rho tan(theta - el) - z_s. To first order an error d_rho, d_az, d_el of the measurement
// moves the position by (d_rho, -rho d_az, rho d_el) in Hill axes (attitude within its 1 deg
// limit); the signs do not matter for zero-mean white errors, so the link adds
// (d_rho, rho d_az, rho d_el): a fixed error along the line of sight and an error across it that
// shrinks with the range. The velocity is passed through: eqs. 12-15 measure no rates, and the
// paper says nothing of how the astronaut reads them.
#include <optional>

#include "core/random.hpp"
#include "core/types.hpp"
#include "model/invsim.hpp"

namespace chaser::invsim {

class MeasurementLink {
 public:
  // `noise` disabled (both sigmas 0): the truth, bit for bit, and no random draws.
  explicit MeasurementLink(const model::InvSimMeasurementNoise& noise);

  // The position the inverse model is given, for the truth r_hill_m at sensor range range_m.
  // Draws three normals per call when enabled (range, azimuth, elevation, in that order).
  Vec3 measured_position_hill_m(const Vec3& r_hill_m, double range_m);

 private:
  model::InvSimMeasurementNoise noise_;
  std::optional<RandomStream> rng_;
};

}  // namespace chaser::invsim
