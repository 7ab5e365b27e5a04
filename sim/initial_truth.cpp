#include "sim/initial_truth.hpp"

#include "flight/flight_software.hpp"
#include "flight/sync_guidance.hpp"
#include "plant/orbit_plant.hpp"

namespace chaser::sim {

flight::GuidanceRef true_sync_reference(const model::Scenario& s, const model::TargetOrbit& orbit,
                                        const plant::TargetRotation& target, double t_s,
                                        const std::optional<Vec3>& start_target_m) {
  const Mat3& inertia = s.target.body->inertia_kgm2;
  flight::TargetEstimate truth;
  truth.t_s = t_s;
  truth.q_inertial_from_target = target.q_inertial_from_target;
  truth.omega_target_radps = target.omega_body_radps;
  truth.omega_dot_target_radps2 = -inertia.inverse() * target.omega_body_radps.cross(inertia * target.omega_body_radps);
  flight::SyncTransferParams transfer = *flight::make_sync_transfer(s);
  if (start_target_m) transfer.start_target_m = *start_target_m;
  return flight::sync_reference(transfer, truth, orbit.lvlh_at(t_s), t_s);
}

plant::RigidState initial_truth(const model::Scenario& s, const model::TargetOrbit& orbit) {
  const model::InitialState& init = s.initial;
  plant::RigidState x{};
  x.mass_kg = s.chaser.mass_kg;
  if (init.use_guidance_start) {
    plant::TargetRotation target;
    // With the synchronisation's approach steps the run starts on the line (flight/sync_approach.hpp).
    const bool synchronised_start = s.guidance.synchronised && !s.guidance.synchronised->approach;
    if (synchronised_start) {
      const plant::TargetSpin spin = plant::initial_target_spin(s.target);
      target = {spin.q_inertial_from_target, spin.omega_target_body_radps};
    }
    const flight::GuidanceRef ref = synchronised_start ? true_sync_reference(s, orbit, target, 0.0)
                                                       : flight::guidance_reference(s.guidance, orbit, 0.0);
    x.r_lvlh_m = ref.r_lvlh_m;
    x.v_lvlh_mps = ref.v_lvlh_mps;
    x.q_inertial_from_body = ref.q_inertial_from_body;
    x.omega_body_radps = ref.omega_body_radps;
  } else {
    x.r_lvlh_m = init.r_lvlh_m;
    x.v_lvlh_mps = init.v_lvlh_mps;
    x.q_inertial_from_body = orbit.q_inertial_from_lvlh(0.0) * init.q_lvlh_from_body;
    x.omega_body_radps = init.omega_body_radps;
  }
  // Only when dispersed: + 0.0 would turn the guidance start's -0.0 into +0.0 in telemetry.
  if (!init.offset_r_lvlh_m.isZero(0.0)) x.r_lvlh_m += init.offset_r_lvlh_m;
  if (!init.offset_v_lvlh_mps.isZero(0.0)) x.v_lvlh_mps += init.offset_v_lvlh_mps;
  return x;
}

}  // namespace chaser::sim
