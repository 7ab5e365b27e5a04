#pragma once
// The plant's motion as a multibody system on MuJoCo (plant/multibody/): the chaser's hub, its
// 7-DOF arm and the target, for the capture. One of the plant's motion models (plant/plant.hpp,
// "the seam"); it takes over from the perturbed Earth orbit by plant/handover.hpp.
//
// The frame (docs/dynamics.md, "The multibody plant"): MuJoCo's world is a non-rotating frame with
// ECI axes whose origin falls freely with a reference point on the target's orbit, propagated as a
// point under the Earth-orbit plant's target model: a_ref = g(r_ref) + S_t, g gravity to J2 at every
// step, S_t the target's slow terms (drag, solar pressure, the Sun and the Moon) held per window as
// that plant holds them (plant/orbit_propagator.hpp). The world is then an inertial frame for every
// body once each body b gets the applied force (at its CoM; as generalised forces, qfrc_applied)
//   f_b = m_b [g(r_ref + x_b) - g(r_ref)]                     the tide, Battin's difference
//       + m_b S_rel                                          chaser bodies: their differential slow terms
//       + (m_b / M_chaser) F_dist                            chaser bodies: the period's LVLH disturbance
// (S_rel: the chaser's drag and pressure less the target's, the third bodies' tide, held per window
// at the chaser's CoM exactly as the Earth-orbit plant's relative acceleration; spread by mass, as a
// cannonball's, so it does not turn the chaser), and the torques
//   hub:    thrust (piece by piece, body axes, moved to the hub's CoM) + the disturbance torque
//           + gravity gradient and magnetic torque with the hub's own inertia, held per period
//   target: gravity gradient and magnetic torque held per period (the Earth-orbit plant's own)
//   links:  gravity gradient of each link's own inertia (their point masses' share comes with the tide)
// evaluated at each MuJoCo step's midpoint (positions x + v h / 2, attitudes q + q' h / 2) and held
// over the step by MuJoCo's RK4: a force so placed is right to second order in h. The links' wrenches
// are mapped to the joints once per step, through the Jacobian at its start (the .cpp's apply_loads:
// off by ~5e-9 N on ~1e-4 N tides); the hub's and the target's enter their free joints exactly, the
// torques in body axes.
//
// The thrust profile's pieces are integrated exactly to their edges: a piece of dt is n =
// ceil(dt / h) equal MuJoCo steps (h the scene's timestep, opt.timestep set to dt / n).
//
// The chaser's RigidState is read from the hub after each advance: its position and velocity are
// those of the point of the hub where the whole chaser's CoM is with the arm stowed
// (chaser.com_body_m), its attitude and rate the hub's; its LVLH view is derived from them as the
// Earth-orbit plant derives its own. The target's attitude and rate are the target body's. No slosh.
#include <array>
#include <optional>
#include <span>
#include <string>

#include "core/time.hpp"
#include "model/arm.hpp"
#include "model/scenario.hpp"
#include "model/target_orbit.hpp"
#include "plant/earth_orbit_motion.hpp"
#include "plant/multibody/mujoco_model.hpp"
#include "plant/multibody/weld.hpp"
#include "plant/period_input.hpp"
#include "model/slosh.hpp"
#include "plant/target.hpp"

namespace chaser::plant {

// Where the scene's parts are in MuJoCo's arrays (from the compiled model's names).
struct MultibodyIndices {
  int hub = 0, target = 0, first_link = 0;  // body ids: hub, link1..link7, gripper in a row, target
  int hub_qpos = 0, hub_dof = 0, target_qpos = 0, target_dof = 0, joint1_qpos = 0, joint1_dof = 0;
  int lock1 = 0;  // equality ids of lock1..lock7 in a row
  int grasp = 0;  // equality id of the grasp's weld, gripper to target
  int motor1 = 0;  // actuator ids of the joints' torque loops motor1..motor7 in a row
  // The jaws (scene.grasp_contact; -1 without): the fingers' slide joints (qpos address), their
  // servos (actuator ids), their geoms and the fixture's.
  std::array<int, 2> finger_qpos{-1, -1}, finger_actuator{-1, -1}, finger_geom{-1, -1};
  int fixture_geom = -1;
  // The berthing (scene.berth_contact; -1 without): the probe's tip, the drogue's first plate (the
  // plates and the floor in a row after it), the weld "berth".
  int probe_geom = -1, drogue_first_geom = -1, berth = -1;
  int tool_site = -1;
};

// The indices of a scene compiled from plant/multibody/mjcf.hpp's text.
MultibodyIndices indices_of(const multibody::MujocoModel& world);

// ASSIST's berthing as the plant has it (model/capture.hpp's BerthingParams): the latches, the
// probe's retraction, the pins, and the loads they carry. Truth: the flight software reads only
// the latches' and the pins' switches (plant/arm_joints.hpp).
struct BerthState {
  bool latched = false;             // the latches hold the tip: the soft dock
  double latch_s = -1.0;            // [s] when
  Vec3 latch_offset_m = Vec3::Zero();  // [m] the tip's centre from the socket at the latch, the fixture's axes
  double latch_attitude_rad = 0.0;  // [rad] the tool's axes from the fixture's at the latch (the angle)
  bool pins_jammed = false;         // the latch outside the pins' envelope: no hard dock
  bool retract_requested = false;   // the flight software commanded the retraction
  double retract_from_s = -1.0;     // [s] the retraction began
  bool hard_docked = false;         // the retraction ended and the pins hold: the hard dock
  double hard_dock_s = -1.0;        // [s]
  double mate_offset_m = 0.0;       // [m] at the hard dock, the interfaces from their mated pose (the soft hold's lag)
  double mate_attitude_rad = 0.0;   // [rad]
  multibody::WeldPose latched_pose, mated_pose;  // the weld's relative pose at the latch, and mated
  double peak_contact_N = 0.0;      // [N] the tip's contact force on the drogue (the sum of its normal forces), largest
  double peak_hold_N = 0.0;         // [N] the latches' and pins' force (the weld's), largest
};

struct MultibodyMotionState {
  multibody::MujocoModel world;  // the scene and its state; a copy is a deep one
  // The Earth-orbit view of the bodies, refreshed after each advance: orbit.r_t_eci_m / v_t_eci_mps
  // the target's CoM, dr / dv the chaser's CoM point relative to it (world differences, no
  // cancellation), the target's attitude; and that plant's environment samples and period.
  EarthOrbitState earth;
  Vec3 r_ref_eci_m = Vec3::Zero();    // [m] the world's origin, ECI
  Vec3 v_ref_eci_mps = Vec3::Zero();  // [m/s]
  // [N m] the joint torques held over the next advance (the arm's inner loop sets them).
  std::array<double, model::kArmJoints> joint_torque_Nm{};
  bool brakes_engaged = false;  // the joints' brakes hold (engage_brakes)
  // [s] Braked, MuJoCo's step from now on in place of the scene's (set_braked_step; 0: the scene's).
  double braked_step_s = 0.0;
  // [N m] braked, each joint's load (the torque its brake carries) at the last MuJoCo step's start.
  std::array<double, model::kArmJoints> brake_load_Nm{};
  // The gripper locked on the fixture (engage_grasp): the fingers held at these slides [m], the
  // jaws' contact off (the weld carries the grasp).
  bool jaws_locked = false;
  std::array<double, 2> locked_finger_m{};
  BerthState berth{};
};

struct MultibodyMotionParams {
  using State = MultibodyMotionState;
  EarthOrbitParams earth;  // the environment; earth.dynamics.chaser's inertia is the hub's
  model::MultibodySceneParams scene;
  Vec3 chaser_com_body_m = Vec3::Zero();  // [m] the whole chaser's CoM, arm stowed (thrust torques are about it)
  double arm_mass_kg = 0.0;               // [kg] links and gripper
  std::optional<model::BerthingParams> berthing;  // capture.berthing: the probe, the drogue and their mechanisms
  // MuJoCo's integrator once the brakes hold. Braked, no joint law runs and the scene moves as one
  // body but for the brakes' and the welds' stiff constraint rows; MuJoCo's semi-implicit Euler at
  // the same step then gives the motion RK4 gives (tests/plant/arm_joints_test.cpp: the braked arm
  // under thrust, to 1e-5 of its rate and loads) at a fraction of the cost: COMRADE's stabilisation, 360 s
  // of a braked composite, takes half the wall time (docs/performance.md).
  int braked_integrator = mjINT_EULER;
  MultibodyIndices index;
};

// Why `scenario` cannot fly the multibody plant (naming the key): no chaser.arm, no orbit.earth,
// chaser.slosh (not coupled in this model), or a hub that is not a body (model/hub_mass_properties.hpp).
std::optional<std::string> multibody_problem(const model::Scenario& scenario);

// The scene of `scenario` (which multibody_problem accepts): the hub the chaser less its stowed
// arm, the arm locked at its stowed angles, the target's body, the grasp's weld inactive; MuJoCo's
// step scene_timestep_s.
struct MultibodyStart {
  MultibodyMotionParams params;
  MultibodyMotionState state;
};
// Takes over from the Earth-orbit plant's state (and chaser) as they are: the reference point at
// the target's CoM, the hub where the rigid chaser is, the arm stowed and at rest relative to it.
MultibodyStart start_multibody(const model::Scenario& scenario, const EarthOrbitState& from, const RigidState& chaser,
                               double scene_timestep_s = 1e-3);

// The Earth-orbit plant's state of the same bodies (for the hand-back), its environment carried on.
EarthOrbitState earth_orbit_state(const MultibodyMotionState& state);

// The arm: torque demands held over the next advance, the locks on or off, the joint angles and
// rates now, and the torques the drives apply now (their inner loops' outputs, which lag the demands).
void set_joint_torques(MultibodyMotionState& state, const std::array<double, model::kArmJoints>& torque_Nm);
void lock_arm(const MultibodyMotionParams& params, MultibodyMotionState& state, bool locked);
std::array<double, model::kArmJoints> joint_angles_rad(const MultibodyMotionParams& params,
                                                       const MultibodyMotionState& state);
std::array<double, model::kArmJoints> joint_rates_radps(const MultibodyMotionParams& params,
                                                        const MultibodyMotionState& state);
std::array<double, model::kArmJoints> joint_torques_applied_Nm(const MultibodyMotionParams& params,
                                                               const MultibodyMotionState& state);

// The jaws (with the scene's grasp contact): their servos commanded open (0) or closed (each
// finger to the tool point, pressing on what lies between with up to closing_force_N); what their
// sensors read: the fingers' inner faces apart [m], and whether both touch the fixture (a contact
// of each finger with the lip in MuJoCo's last collision pass: the jaws' switches).
void command_jaws(const MultibodyMotionParams& params, MultibodyMotionState& state, bool closed);
struct JawReading {
  double opening_m = 0.0;
  bool holding = false;
};
JawReading read_jaws(const MultibodyMotionParams& params, const MultibodyMotionState& state);

// The joints' brakes (the rigidisation): each joint's friction becomes the brake's holding torque
// (chaser.arm.brake_holding_torque_Nm, MuJoCo's frictionloss: the joint sticks while the torque it
// must carry stays below, and slips at that torque beyond). Engaged for good.
void engage_brakes(const MultibodyMotionParams& params, MultibodyMotionState& state);
// Braked, MuJoCo steps at step_s (> 0) instead of the scene's timestep from the next advance on:
// the chaser and its braked arm are one body but for the brakes' and the welds' stiff rows, whose
// time constants MuJoCo's refsafe keeps at least two steps (the brakes' 2 ms becomes 2 step_s).
// The drives, off, stop applying torque. Throws std::logic_error unless braked.
void set_braked_step(const MultibodyMotionParams& params, MultibodyMotionState& state, double step_s);
// Braked, the torque each brake carries [N m] (the joint's load: its friction constraint's force)
// at the start of the last MuJoCo step; zero before the brakes engage.
std::array<double, model::kArmJoints> brake_loads_Nm(const MultibodyMotionParams& params,
                                                     const MultibodyMotionState& state);

// The grasp: the gripper welded to the target at the pose they have now (plant/multibody/weld.hpp);
// the jaws then locked where they hold the lip, their contact off (the weld's forces replace it),
// and read as holding from then on.
void engage_grasp(const MultibodyMotionParams& params, MultibodyMotionState& state);
bool grasp_engaged(const MultibodyMotionParams& params, const MultibodyMotionState& state);

// The berthing: the probe's retraction commanded (it begins with the next advance, once the
// latches hold), and what the latches' and the pins' switches read.
void command_probe_retraction(const MultibodyMotionParams& params, MultibodyMotionState& state);
bool probe_latched(const MultibodyMotionState& state);
bool probe_hard_docked(const MultibodyMotionState& state);

// The grasp engaged, the joints' rates set to rates_radps, and the hub's and the target's velocities
// chosen so that the weld holds (link 7 and the target move as one body) and the scene's linear and
// angular momentum is what it was: a closed chain's velocities consistent with a start of given joint
// rates (COMRADE Table 7's rigidisation starts). Seven joints on a chain of six degrees of freedom
// between hub and target: any rates can be met. The fingers keep theirs. Throws std::logic_error
// without the grasp engaged.
void set_closed_chain_joint_rates(const MultibodyMotionParams& params, MultibodyMotionState& state,
                                  const std::array<double, model::kArmJoints>& rates_radps);

// The environment of the period at t_k: the Earth-orbit plant's (plant/earth_orbit_motion.hpp).
void begin_period(const MultibodyMotionParams& params, MultibodyMotionState& state, const RigidState& chaser,
                  TimeNs t_k, TimeNs period_ns);

// Each piece of the period's profile within [from_ns, to_ns] in whole MuJoCo steps, then the
// chaser's rigid state and LVLH view from the hub.
void advance(const MultibodyMotionParams& params, MultibodyMotionState& state, RigidState& chaser,
             const ThrustProfile& profile, const PeriodDisturbance& disturbance, TimeNs from_ns, TimeNs to_ns);

TargetRotation target_rotation(const MultibodyMotionParams& params, const MultibodyMotionState& state, double t_s);

Quat q_inertial_from_lvlh(const MultibodyMotionParams& params, const MultibodyMotionState& state,
                          const model::TargetOrbit& circle, double t_s);

// None: the multibody plant has no slosh (multibody_problem refuses chaser.slosh).
std::span<const model::SloshState> slosh_states(const MultibodyMotionParams& params, const MultibodyMotionState& state);

}  // namespace chaser::plant
