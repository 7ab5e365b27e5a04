#pragma once
// The chaser's propellant slosh as its dynamics carry it (model/slosh.hpp): the tanks' first lateral
// modes as spring-masses or pendulums coupled to the rest of the chaser, whose rotation they
// change. The truth (plant/orbit_propagator) flies it; a model of it on board can be built from
// the same nominal scenario. Translation is the whole chaser's centre of mass (slosh masses
// included), which internal forces do not move: F / m as without slosh. The thrusters' torque comes
// about com_body_m, the whole chaser's CoM at rest, and is moved to the body's (the chaser less
// its slosh masses) for the coupled equations.
#include <array>

#include "core/types.hpp"
#include "model/slosh.hpp"
#include "model/spacecraft.hpp"

namespace chaser::model {

struct ChaserSloshParams {
  int count = 0;  // tanks, 0..kMaxSloshTanks; 0: a rigid chaser
  std::array<SloshTankParams, kMaxSloshTanks> tanks{};
  double mass_kg = 0.0;                        // [kg] the slosh masses together
  Mat3 body_inertia_kgm2 = Mat3::Identity();   // [kg m^2] the chaser less them, about body_com_body_m
  Mat3 body_inertia_inv_kgm2 = Mat3::Identity();  // [1/(kg m^2)] its inverse
  Vec3 body_com_body_m = Vec3::Zero();         // [m] its centre of mass, from the reference point
  Vec3 com_body_m = Vec3::Zero();              // [m] the whole chaser's at rest
};

// The chaser's slosh (scenario chaser.slosh, validated by io/): each tank's first mode at the fill
// its liquid mass and density give (slosh_tank_from_fill; with model: pendulum, its
// pendulum_analogue, held by sigma / (rho R^2) at zero thrust), and the body the slosh masses
// leave, taken out of the scenario's mass, CoM and inertia, which are the whole chaser's at rest.
ChaserSloshParams chaser_slosh(const SpacecraftParams& chaser);

}  // namespace chaser::model
