#pragma once
// The perturbed-Earth-orbit plant built from a scenario: the propagator's parameters
// from orbit.earth, chaser and target.body, and the initial states, the target's spin cases
// included (COMRADE 2018, sec. 7.1). plant.cpp uses it when the scenario has orbit.earth.
#include "model/scenario.hpp"
#include "plant/orbit_propagator.hpp"

namespace chaser::plant {

struct OrbitPlantParams {
  OrbitDynamicsParams dynamics;
  double epoch_jd_tt = 0.0;  // [d] t = 0
};

// Requires scenario.orbit.earth and scenario.target.body (validated together, io/).
OrbitPlantParams make_orbit_plant_params(const model::Scenario& s);

// The target's attitude and body rate at t = 0: the scenario's own (spin case `given`: its inertial
// rate turned into target axes) or one of COMRADE's spin cases. Frames: the run's inertial axes
// are the target's LVLH at t = 0 (MSR LVLH: x zenith, y along-track, z along the orbital angular
// momentum h); the ESA H-bar is -z, R-bar (to the Earth's centre) is -x.
//   S1: spin about target +Y, +Y along +H-bar:  q = rotation about x by -90 deg.
//   S2: spin about (0, 1, 1)/sqrt(2) in target axes (45 deg from +Y and +Z), that axis along +H-bar.
//   S3: spin about target +Z, +Z along (R-bar + H-bar)/sqrt(2), 45 deg from the orbit normal in
//       the orbit-normal / radial plane; target +X along-track (+y).
struct TargetSpin {
  Quat q_inertial_from_target = Quat::Identity();
  Vec3 omega_target_body_radps = Vec3::Zero();  // [rad/s] inertial rate, target axes
};
TargetSpin initial_target_spin(const model::TargetParams& target);

// The orbit state at t = 0: the target on the circular orbit of the scenario's altitude in the
// plane of orbit.earth, the chaser at r_lvlh_m / v_lvlh_mps from it (rotating-frame velocity),
// the target spinning as above.
OrbitState initial_orbit_state(const model::Scenario& s, const OrbitPlantParams& p, const Vec3& r_lvlh_m,
                               const Vec3& v_lvlh_mps);

// The Sun, the Moon and the Earth's turn at run time t_s, each from its model (plant/earth/).
Ephemeris ephemeris_at_run_time(const OrbitPlantParams& p, double t_s);

// The same, as the plant asks it every period: the Earth's turn from its model, the Sun and the Moon
// interpolated linearly between their positions at whole multiples of kEphemerisSampleS of run
// time (so a period's answer depends on its time alone, not on the run's history). The chord of
// an arc turned by w dt misses it by (w dt)^2 / 8 of the radius: the Moon (w = 2.7e-6 rad/s) by
// 3e-9, 1.2 m of its 384,000 km, the Sun by 2e-11, where the Moon's own series is good to ~0.3 %
// (moon.hpp). The two series cost ~2,500 instructions, more than the rest of a period's plant.
inline constexpr double kEphemerisSampleS = 60.0;  // [s]
struct EphemerisSamples {
  std::int64_t index = -1;  // samples at index * kEphemerisSampleS and the next; -1: none yet
  Vec3 sun0_eci_m = Vec3::Zero(), sun1_eci_m = Vec3::Zero();
  Vec3 moon0_eci_m = Vec3::Zero(), moon1_eci_m = Vec3::Zero();
};
Ephemeris ephemeris_at_run_time(const OrbitPlantParams& p, double t_s, EphemerisSamples& samples);

// The slow terms of the current window of whole control periods (OrbitDynamicsParams::
// environment_step_s): window w covers periods [w n, (w + 1) n), n = environment_periods.
struct SlowEnvironmentSample {
  std::int64_t window = -1;  // -1: none yet
  SlowEnvironment env;
};

}  // namespace chaser::plant
