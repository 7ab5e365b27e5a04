#pragma once
// What every motion model is given for one control period besides the thrust profile: the
// disturbances drawn for it (bias plus white noise, held over the period).
#include "core/types.hpp"
#include "plant/propagator.hpp"
#include "plant/thruster_hardware.hpp"

namespace chaser::plant {

struct PeriodDisturbance {
  Vec3 force_lvlh_N = Vec3::Zero();    // [N] LVLH axes
  Vec3 torque_body_Nm = Vec3::Zero();  // [N m] chaser body axes
};

// One thrust piece with the period's disturbances added.
inline PieceInput piece_input(const ThrustPiece& piece, const PeriodDisturbance& disturbance) {
  return PieceInput{
      .force_body_N = piece.force_body_N,
      .torque_body_Nm = piece.torque_body_Nm + disturbance.torque_body_Nm,
      .force_lvlh_N = disturbance.force_lvlh_N,
      .mass_flow_kgps = piece.mass_flow_kgps,
  };
}

}  // namespace chaser::plant
