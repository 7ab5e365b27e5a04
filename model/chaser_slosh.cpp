#include "model/chaser_slosh.hpp"

#include <cstddef>

#include <Eigen/LU>

#include "core/point_inertia.hpp"

namespace chaser::model {

ChaserSloshParams chaser_slosh(const SpacecraftParams& chaser) {
  const SloshParams& slosh = *chaser.slosh;
  ChaserSloshParams out;
  out.count = static_cast<int>(slosh.tanks.size());
  out.com_body_m = chaser.com_body_m;
  Vec3 moment_kgm = Vec3::Zero();
  for (int i = 0; i < out.count; ++i) {
    const SloshTankSpec& t = slosh.tanks[static_cast<std::size_t>(i)];
    const CylindricalTank tank{.bottom_centre_body_m = t.bottom_centre_body_m, .axis_body = t.axis_body,
                               .radius_m = t.radius_m};
    const SloshTankFill fill =
        slosh_tank_from_fill(tank, t.liquid_mass_kg, fill_height_m(t), slosh.g_eff_mps2, t.damping_ratio);
    out.tanks[static_cast<std::size_t>(i)] =
        slosh.model == SloshModel::pendulum ? pendulum_analogue(fill, tank, slosh.g_eff_mps2, capillary_accel_mps2(t))
                                            : fill.slosh;
    out.mass_kg += fill.slosh.mass_kg;
    moment_kgm += fill.slosh.mass_kg * fill.slosh.anchor_body_m;
  }
  // The scenario's mass, CoM and inertia are the whole chaser's at rest; the body is what is left.
  const double body_kg = chaser.mass_kg - out.mass_kg;
  out.body_com_body_m = (chaser.mass_kg * chaser.com_body_m - moment_kgm) / body_kg;
  out.body_inertia_kgm2 = chaser.inertia_kgm2 - point_inertia(body_kg, out.body_com_body_m - chaser.com_body_m);
  for (int i = 0; i < out.count; ++i) {
    const SloshTankParams& t = out.tanks[static_cast<std::size_t>(i)];
    out.body_inertia_kgm2 -= point_inertia(t.mass_kg, t.anchor_body_m - chaser.com_body_m);
  }
  out.body_inertia_inv_kgm2 = out.body_inertia_kgm2.inverse();
  return out;
}

}  // namespace chaser::model
