#pragma once
// The servicer's 7-DOF arm and gripper as parameters, and the multibody scene (hub, arm, target)
// built from them. COMRADE 2018 (sec. 4) gives the arm's joint count, its torque limits (Table 3's
// footnote: 176 N m repeated peak, 314 N m momentary) and the gripper's envelope (Table 2), but no
// geometry or masses: default_arm() is a plausible space arm, each number's origin stated there.
//
// Frames: every link frame is parallel to its parent's at q = 0 (the arm stretched along the
// mounting frame's +x), so a joint's axis and its child's offset are written in the parent's axes.
// Link 1's parent is the chaser's body frame: joint 1 sits at mount_body_m (from the body's
// reference point, as the thrusters do) plus links[0].joint_position_parent_m.
#include <array>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "model/keep_out.hpp"

namespace chaser::model {

inline constexpr int kArmJoints = 7;
inline constexpr double kArmDegToRad = 3.14159265358979323846 / 180.0;

struct ArmLinkParams {
  Vec3 joint_position_parent_m = Vec3::Zero();  // [m] the joint's origin in the parent link's frame
  Vec3 joint_axis = Vec3::UnitX();              // [-] unit, the parent's (= this link's at q = 0) axes
  double mass_kg = 1.0;                         // [kg] the link with its joint's drive
  Vec3 com_link_m = Vec3::Zero();               // [m] centre of mass in the link frame
  Vec3 inertia_kgm2 = Vec3::Ones();             // [kg m^2] principal moments about the CoM, link axes
  double lower_rad = -3.0;                      // [rad] joint limit
  double upper_rad = 3.0;                       // [rad]
  double friction_Nm = 0.0;                     // [N m] Coulomb friction of the drive (MuJoCo frictionloss)
  double damping_Nms = 0.0;                     // [N m s/rad] viscous friction of the drive
  double armature_kgm2 = 0.0;                   // [kg m^2] rotor inertia reflected through the gear
};

// The gripper's jaws (COMRADE 2018, sec. 4: at the grasping point the gripper "closes rapidly
// establishing a form closure assuring that the LAR cannot escape", then "closes rigidly"): two
// fingers either side of the tool point that slide towards it along the tool's z, each a plate
// driven by a position servo with a force limit, and a palm behind them; the lip of the adapter
// ring enters between the fingers along the tool's x. Sized for COMRADE Table 2's envelope: a
// fixture up to 22 mm off along z still lies between the open fingers.
struct JawParams {
  double open_half_gap_m = 0.040;                          // [m] each finger's inner face from the tool point, open
  Vec3 finger_half_extents_m = Vec3(0.03, 0.04, 0.004);    // [m] tool axes: x along the approach, z the closing
  double finger_mass_kg = 0.3;                             // [kg] each, part of the gripper's mass_kg
  double closing_force_N = 60.0;                           // [N] each finger's drive at most
  double servo_stiffness_Npm = 2000.0;                     // [N/m] the fingers' position servo
  double servo_damping_Nspm = 50.0;                        // [N s/m] critically damped with the finger's mass
  double palm_setback_m = 0.04;                            // [m] the palm's face behind the tool point along x
};

struct GripperParams {
  Vec3 position_link7_m = Vec3(0.3, 0.0, 0.0);  // [m] the gripper's tool point in link 7's frame
  double mass_kg = 10.0;                         // [kg] with its jaws
  Vec3 com_link7_m = Vec3(0.15, 0.0, 0.0);       // [m] with the jaws open
  Vec3 inertia_kgm2 = Vec3(0.05, 0.1, 0.1);      // [kg m^2] principal, about its CoM, with the jaws open
  JawParams jaws;
};

// The grasping fixture: the launcher adapter ring's lip at the grasp point, a plate in the grasp
// pose's axes (x the tool's approach, z across the lip, the jaws' closing direction), centred on
// the grasp point. ENVISAT's ring is 1.2 m across; its lip a 10 mm flange standing 60 mm proud.
struct FixtureParams {
  Vec3 half_extents_m = Vec3(0.03, 0.10, 0.005);  // [m] grasp pose axes
};

// ASSIST's berthing fixture and the arm's capture probe as the multibody scene has them
// (model/capture.hpp's BerthingParams): the probe's tip, a sphere at the tool point; the drogue, a
// cone in the fixture's axes (x the approach, into the target) from its mouth at x = -depth_m to its
// throat at the socket (x = 0), drawn as `plates` flat plates round its axis, and a floor behind the
// socket that the tip rests on with its centre at the socket.
struct DrogueParams {
  double tip_radius_m = 0.02;
  double mouth_radius_m = 0.12;
  double throat_radius_m = 0.023;
  double depth_m = 0.15;
  double friction = 0.3;
  int plates = 12;
};

struct ArmParams {
  Vec3 mount_body_m = Vec3(1.05, 0.0, 0.0);  // [m] the arm's base in the chaser's body frame, from its reference point
  std::array<ArmLinkParams, kArmJoints> links{};
  GripperParams gripper;
  double torque_repeated_peak_Nm = 176.0;  // [N m] COMRADE 2018, Table 3 footnote
  double torque_momentary_Nm = 314.0;      // [N m] the drive's hard limit (the motors' control range)
  // [rad/s] the inner joint-torque loop's bandwidth: each joint's torque follows its demand through
  // 1 / (s / w + 1) (a first-order lag, MuJoCo's filter actuator). A torque-sensed drive closes
  // this loop at several kHz in its own electronics; its closed-loop bandwidth is of the order of
  // tens of Hz (ours: 300 rad/s, 48 Hz, an assumption). The loop's gain also divides the drive's
  // friction, which is why a scenario gives the joints' friction as what is left of it.
  double torque_loop_bandwidth_radps = 300.0;
  // [N m] each joint's brake (the rigidisation's, model/capture.hpp): engaged, it holds its joint
  // by friction up to this torque and slips beyond (MuJoCo's frictionloss). Above the momentary
  // limit, so that no drive can back-drive it; an assumption, the paper gives none.
  double brake_holding_torque_Nm = 500.0;
  // [rad] the joint angles of the stowed arm, the configuration the rigid chaser's mass properties
  // (chaser.mass_kg, inertia_kgm2, com_body_m) include it in: shoulder pitched 90 deg to +y, the
  // elbow folded back 110 deg, the wrist 70 deg, a Z folded in front of the +x face; inside every
  // default limit (pitches +/-120 deg).
  std::array<double, kArmJoints> stowed_rad{0.0, 90.0 * kArmDegToRad, 0.0, -110.0 * kArmDegToRad, 0.0,
                                            -70.0 * kArmDegToRad, 0.0};
};

// A thin-walled tube of length L [m] and radius r [m] about its centre, axis along x: the link
// inertias of default_arm() (I_xx = m r^2, I_yy = I_zz = m (r^2 / 2 + L^2 / 12)).
Vec3 tube_inertia_kgm2(double mass_kg, double length_m, double radius_m);

// A plausible 7-DOF space arm (shoulder roll-pitch-roll, elbow pitch, wrist roll-pitch-roll, the
// S-R-S layout of the light-weight arms built for on-orbit servicing), 3.1 m from the shoulder to
// the tool point so that, mounted on the hub's +x face 1.05 m ahead of its reference point, it
// reaches a fixture 3.5 m ahead (comrade_sync's capture point) with its elbow bent; 80 kg in all.
ArmParams default_arm();

// The scene flown by the multibody plant: the hub (the chaser's bus), the arm mounted on it, the
// target; each free body's frame at its centre of mass, gravity and contact off (the orbit's forces
// are applied per body by the plant).
struct MultibodySceneParams {
  double hub_mass_kg = 1600.0;
  Mat3 hub_inertia_kgm2 = Mat3::Identity();     // [kg m^2] about the hub's CoM, body axes
  Vec3 hub_com_body_m = Vec3::Zero();           // [m] the hub's CoM from the body's reference point
  ArmParams arm = default_arm();
  double target_mass_kg = 7828.0;
  Mat3 target_inertia_kgm2 = Mat3::Identity();  // [kg m^2] about the target's CoM, target axes
  Vec3 target_position_m = Vec3(8.0, 0.0, 0.0); // [m] the target's CoM at q = 0, scene frame
  // The target's outer shape (target.body.keep_out: ENVISAT's bus and solar array), boxes "shape0",
  // "shape1", ... on the target without contact or mass (its mass and inertia are the <inertial>'s):
  // the scene's geometry, for reading distances and drawing; empty: none.
  std::vector<KeepOutBox> target_shape;
  double timestep_s = 1e-3;                     // [s] MuJoCo's step
  std::string integrator = "RK4";               // "Euler", "RK4" or "implicit"
  // Each joint locked at arm.stowed_rad by an <equality><joint> constraint ("lock1".."lock7"),
  // active from the start (a plant switches them with mjModel::eq_active); false: no such
  // constraint in the model (the text is then what it was without this field).
  bool arm_locks = false;
  double lock_timeconst_s = 0.02;               // [s] the locks' solref time constant (critically damped)
  double lock_impedance = 0.9;                  // [-] the locks' solimp d (constant over the violation), < 1
  // The grasp: a weld "grasp" of the gripper to the target, inactive until engaged at the relative
  // pose the two have then (plant/multibody/weld.hpp), with the locks' stiffness; false: none.
  bool grasp_weld = false;
  // The grasp's contact: the gripper's jaws (arm.gripper.jaws: two slide joints "finger_a" and
  // "finger_b", their position servos before the joints' torque loops) and the fixture's lip on the target
  // at fixture_target_m with the axes q_target_from_fixture, contact on between jaws and lip only;
  // false: no jaws, contact off (the text is then what it was without these fields).
  bool grasp_contact = false;
  Vec3 fixture_target_m = Vec3::Zero();            // [m] the grasp point, target axes from its CoM
  Quat q_target_from_fixture = Quat::Identity();   // the grasp pose's axes (x the approach)
  FixtureParams fixture;
  // The berthing's contact (exclusive with grasp_contact): the probe's tip (a sphere "probe_tip" on
  // the gripper's body at the tool point) and the drogue on the target at fixture_target_m with the
  // axes q_target_from_fixture (boxes "drogue0".. and "drogue_floor"), contact between tip and drogue
  // only; a weld "berth" of the gripper to the target, inactive until the latches close. false: none.
  bool berth_contact = false;
  DrogueParams drogue;
};

}  // namespace chaser::model
