#pragma once
// The capture's scenario section (`capture`): when the arm wakes, which combined controller flies
// the servicer's 13 degrees of freedom (COMRADE 2018, sec. 6), the tool's path to the pre-grasp
// pose, and the joints' rate. Read by io/capture_reader.cpp; flown by flight/reach.hpp; the plant
// becomes the multibody one at start_s (sim/simulation.cpp).
#include <optional>
#include <string>

#include "model/gnc.hpp"

namespace chaser::model {

enum class CaptureLaw { kCompliance, kHinf };

// The rigidisation's saturation of the joint torques (COMRADE 2018, sec. 6.2.2 and its Fig. 13):
// the paper's linear saturation (identity up to L, then approaching the limit M along a tanh) or a
// plain clip at M.
enum class RigidiseSaturation { kLinear, kClip };

// The rigidisation's joint law (COMRADE 2018 Table 7's two columns): the paper's saturated PD
// (its "nonlinear compliant" rigidisation, sec. 6.2.2), or H-infinity loops on the joints' angles
// behind the free-floating composite's joint inertia (flight/rigidise.hpp).
enum class RigidiseLaw { kCompliance, kHinf };

// The rigidisation (COMRADE 2018, sec. 4 and 6.2.2; the optional section capture.rigidise): once
// the capture is confirmed the thrusters are inhibited and the arm alone damps the relative motion,
// u = -s(K_d q' + K_p (q - q_d)) on every joint, q_d the joints' angles at the capture's
// confirmation, s saturating at the arm's repeated peak (chaser.arm.torque_repeated_peak_Nm); once
// every joint's rate has stayed below brake_rate_degps for brake_dwell_s the brakes engage and the
// drives are off (the brakes: chaser.arm.brake_holding_torque_Nm).
// The gains: K_p must hold the chaser's centripetal load (turning with ENVISAT at 2.5 deg/s, ~12 N
// about the composite's CoM, now carried by the arm: tens of N m at the shoulder) to a fraction of a
// degree; K_d is bounded by the arm's self-motion: seven joints close a chain of six degrees of
// freedom between hub and target, so one mode moves the links alone, with a link's small inertia.
// At K_d = 10,000 N m s/rad that mode outran the 1 kHz joint loop and the torque loop's lag (the
// roll joints limit-cycled at the drive's 176 N m after an H-infinity capture); 2,000 damps it.
struct RigidiseParams {
  RigidiseLaw law = RigidiseLaw::kCompliance;
  double stiffness_Nm_per_rad = 1000.0;     // [N m/rad] K_p, every joint
  double damping_Nms_per_rad = 2000.0;     // [N m s/rad] K_d, every joint (bounded: the comment above)
  RigidiseSaturation saturation = RigidiseSaturation::kLinear;
  double linear_limit_Nm = 88.0;            // [N m] L: the law's torque passes unchanged up to it (< M)
  double brake_rate_degps = 0.01;           // [deg/s] every joint's rate below this ...
  double brake_dwell_s = 1.0;               // [s] ... for this long: the brakes engage
  // kHinf: each joint's loop weights (error_scale in rad: an angle error this large may ask for the
  // joint's whole authority, the drive's repeated peak over its free-floating inertia).
  HinfLoopWeights hinf{0.3, 2.0, 1e-3, 0.01, 0.01};
};

// The stabilisation (COMRADE 2018, sec. 4 and 6.1.4; the optional section capture.stabilise, after
// a rigidisation): once the brakes hold, the thrusters detumble the composite of chaser, braked arm
// and target with a pure couple, following a reference for the composite's angular momentum that
// decays linearly from its value at the start to zero over duration_s (the paper's "decaying
// reference profile in terms of angular rate": the rate is the momentum through the inertia), the
// momentum's error removed at bandwidth_radps (flight/stabilise.hpp). The duration sets the couple
// (the momentum over the duration) and so the loads the braked joints carry.
// The couple's law: the momentum's error fed back at bandwidth_radps (kMomentum), or COMRADE's
// H-infinity loops (sec. 6.1.4; kHinf): one S/KS design per inertial axis on the angular impulse
// (the momentum's integral, a double integrator in the couple) behind the reference's couple
// (flight/stabilise.hpp, control/composite_design.hpp).
enum class StabiliseLaw { kMomentum, kHinf };

struct StabiliseParams {
  double duration_s = 300.0;       // [s] the reference's momentum from its start value to zero
  StabiliseLaw law = StabiliseLaw::kMomentum;
  double bandwidth_radps = 0.02;   // [rad/s] kMomentum: the momentum error's decay rate (low: flight/stabilise.hpp)
  // kHinf: the loops' weights (error_scale in N m s^2: an angular-impulse error this large may ask
  // for the couple's whole authority).
  HinfLoopWeights hinf{0.02, 2.0, 1e-3, 2000.0, 0.0};
  // [-] The composite inertia's relative error the loops' robustness is checked over (`chaser
  // control design`: the grid and the mu bound; control/composite_design.hpp): ENVISAT's inertia is
  // known from a catalogue, not measured.
  double inertia_uncertainty = 0.2;
};

// The escape (COMRADE 2018, sec. 4: "a trajectory planning part as well as a combined controller
// as the feed-back part"; the optional section capture.escape): commanded at command_s, or on a
// failed grasp (flight/grasp.hpp's abandoned step), while the jaws are open, the servicer withdraws
// along a planned trajectory tracked by the capture's combined controller (flight/escape.hpp):
//   retract       the tool from where it is to its stowed pose, the chaser holding the capture point;
//   withdraw      the chaser, turning with the target, from the capture point to the point the
//                 synchronised transfer started from (on the target's angular-momentum axis), backing
//                 away first (a curve bent withdraw_backoff_m outwards), its boresight kept on the
//                 target's centre;
//   desynchronise the chaser's turning brought to rest there;
//   retreat       along the line of sight to safe_distance_m from the target's centre, and a hold.
// The paper states no requirements for it; Chaser's (judged in the summary: sim/escape_result.hpp)
// are the synchronised flight's clearances (0.5 m turning with the target, 3 m once not: COMRADE
// Table 4), the tool point never inside the keep-out volume, the target's centre inside the arm
// camera's field of view throughout, and the hold within kEscapeDistanceTolM of safe_distance_m.
struct EscapeParams {
  std::optional<double> command_s;     // [s] commanded then (at or after capture.start_s); absent: never
  bool on_failed_grasp = true;         // the grasp abandoned (no closure within grasp_timeout_s): escape
  double retract_duration_s = 30.0;    // [s]
  double withdraw_duration_s = 300.0;  // [s] the synchronised transfer's length
  double withdraw_backoff_m = 4.0;     // [m] the withdrawal's curve bent outwards (flight/escape.hpp)
  double desynchronise_duration_s = 200.0;  // [s] the rotation's synchronisation's length, flown back
  double retreat_duration_s = 400.0;   // [s]
  double safe_distance_m = 30.0;       // [m] from the target's centre: the fly-around's radius
  // The arm braked once the retraction has ended and every joint turns slower than brake_rate_degps
  // (the brakes' catch of the joints' last motion is a load on them), the platform's own loops
  // flying the rest of the plan (flight/escape.hpp); false: the combined law holds the stowed tool
  // to the end.
  bool brake_when_stowed = true;
  double brake_rate_degps = 0.02;  // [deg/s]
  // [s] Braked for a control period, the chaser and its stowed arm move as one body, the target
  // free, and no joint law runs: the joint loop and MuJoCo step at this (a whole number of joint
  // periods, and a whole number of it per control period) instead of the scene's 1 ms, 6.5 x the
  // wall time of the braked flight (docs/performance.md). Not the stabilisation's composite: its
  // brakes' loads under the thrusters grow with the step (93, 139, 283 N m at 1, 2, 5 ms in
  // comrade_capture; at 10 ms they slip), as the brakes' and the grasp's constraints soften with it.
  double braked_step_s = 0.01;
  double total_s() const {
    return retract_duration_s + withdraw_duration_s + desynchronise_duration_s + retreat_duration_s;
  }
};

// Chaser's escape requirements (the paper gives none): the clearances are COMRADE Table 4's.
inline constexpr double kEscapeSynchronisedClearanceM = 0.5;    // [m] while turning with the target
inline constexpr double kEscapeUnsynchronisedClearanceM = 3.0;  // [m] from the desynchronisation on
inline constexpr double kEscapeDistanceTolM = 0.5;              // [m] the final hold from safe_distance_m

// ASSIST's berthing (COMRADE 2018, sec. 2.2; the optional section capture.berthing): a capture
// probe replaces the gripper on the arm's end and the target carries a berthing fixture, a drogue.
// The tool point is the probe's tip, a sphere; the drogue a cone open towards the chaser, its mouth
// drogue_depth_m before the socket at target.body.grasp_point_target_m along the tool's approach, its
// throat (at the socket) socket_clearance_m wider than the tip. The capture's path and approach fly
// the tip to the socket (the cone's walls guide a tip that arrives off the axis: MuJoCo's contact,
// with `friction`); once the tip's centre is within latch_radius_m of the socket the latches close
// on it (passive, in the plant): the soft dock, a compliant hold of the pose of that moment (a weld
// of time constant soft_dock_timeconst_s). The flight software then commands the probe's central
// mechanism to retract by retraction_m over retraction_duration_s (a quintic, rest to rest): the
// hold's pose is drawn from the latched one to the mated one (the probe's interface on the
// fixture's, their axes aligned), the aligning pins engaging on the way; at its end the hard dock, a
// rigid hold. The pins align only what lies inside their chamfers: a latch farther than
// pin_position_tol_m off the drogue's axis or pin_attitude_tol_deg off its attitude jams them, and
// the hard dock never comes (plant/multibody_motion.hpp).
struct BerthingParams {
  double probe_tip_radius_m = 0.02;       // [m]
  double drogue_mouth_radius_m = 0.12;    // [m]
  double drogue_depth_m = 0.15;           // [m] from the mouth to the socket, along the approach
  double socket_clearance_m = 0.003;      // [m] the throat's radius less the tip's
  double friction = 0.3;                  // [-] the tip on the drogue's walls (Coulomb)
  double latch_radius_m = 0.005;          // [m]
  double soft_dock_timeconst_s = 0.2;     // [s] the soft dock's compliance
  // [m] the insertion's path ends this far beyond the socket: the tool's stiffness presses the tip
  // home against the cone's walls when the camera's error puts it off the axis (flight/reach.hpp).
  double insertion_overtravel_m = 0.03;
  double retraction_m = 0.10;             // [m] the probe drawn in
  double retraction_duration_s = 20.0;    // [s]
  double pin_position_tol_m = 0.005;      // [m] the latch's offset from the drogue's axis the pins align
  double pin_attitude_tol_deg = 1.0;      // [deg] the latch's attitude error they align
  // [N] Chaser's bound on the contact force between tip and drogue (the paper gives none): the
  // force the drives' repeated peak holds at the tool at the arm's full reach (176 N m over ~3 m),
  // beyond which the contact back-drives the arm.
  double contact_force_limit_N = 50.0;
};

struct CaptureParams {
  double start_s = 0.0;            // [s] the arm wakes: the reach begins
  CaptureLaw law = CaptureLaw::kCompliance;
  double path_duration_s = 60.0;   // [s] the tool from its stowed pose to the pre-grasp pose
  double standoff_m = 0.15;        // [m] the pre-grasp pose: the tool this far short of the fixture along its approach
  double joint_rate_hz = 1000.0;   // [Hz] the combined law and the joints' torque commands (COMRADE: 1 kHz)
  // [Hz] the platform's command: the law's force and torque sampled for the thrusters at this rate
  // (COMRADE: 3 Hz), at the first control period at or after each tick, held in between; at most
  // the control rate.
  double platform_rate_hz = 10.0;
  // The tasks' natural frequencies and damping ratio (flight/arm/compliance_control.hpp,
  // compliance_gains; the H-infinity loops' omega_B).
  double hub_bandwidth_radps = 0.5;
  double tool_bandwidth_radps = 3.0;
  double joint_bandwidth_radps = 1.0;
  double damping_ratio = 3.0;
  // The grasp (COMRADE 2018, sec. 4): after pre_grasp_hold_s at the pre-grasp pose the tool moves
  // onto the fixture over approach_duration_s (a quintic, rest to rest); once it has arrived, the
  // jaws close when closure_samples camera samples in a row put the fixture inside the grappling
  // envelope (Table 2), and the gripper locks rigidly once both fingers have held the lip for
  // lock_dwell_s. No closure within grasp_timeout_s of the approach's end: the grasp is abandoned
  // (the jaws stay open). Captured: the rigidisation (below), or without it the combined controller
  // flies on, its tool held on the fixture.
  double pre_grasp_hold_s = 30.0;     // [s]
  double approach_duration_s = 30.0;  // [s] the standoff covered at 5 mm/s on average
  int closure_samples = 3;            // [-] consecutive arm camera samples
  double lock_dwell_s = 0.2;          // [s]
  double grasp_timeout_s = 30.0;      // [s]
  // The rigidisation after the capture; without it the combined controller flies on, its tool held
  // on the fixture.
  std::optional<RigidiseParams> rigidise;
  // The stabilisation once the rigidisation's brakes hold (needs rigidise); without it the
  // thrusters stay inhibited.
  std::optional<StabiliseParams> stabilise;
  // The escape, on command or a failed grasp; without it a failed grasp leaves the tool at the fixture.
  std::optional<EscapeParams> escape;
  // ASSIST's berthing in place of the grasp: the probe into the drogue, soft and hard dock.
  std::optional<BerthingParams> berthing;
  // [s] when the tool leaves the pre-grasp pose for the fixture: the reach ends, the capture begins.
  double approach_start_s() const { return start_s + path_duration_s + pre_grasp_hold_s; }
};

// COMRADE 2018 Table 2: the gripper's grappling envelope about the fixture (x the approach) and
// the relative motion allowed at the grasp.
inline constexpr double kGrapplingEnvelopeM[3] = {0.010, 0.022, 0.022};  // [m]
inline constexpr double kGrapplingEnvelopeDeg = 2.74;                     // [deg] about each axis
inline constexpr double kGraspRelativeVelocityMps = 0.005;                // [m/s] per axis
inline constexpr double kGraspRelativeRateDegps = 0.1;                    // [deg/s] per axis

// COMRADE 2018 Table 3: the stabilisation brings the composite's angular rate below this, the
// braked joints' loads within the drives' repeated and momentary peaks.
inline constexpr double kStabilisedRateDegps = 0.5;  // [deg/s]

inline const char* to_string(CaptureLaw law) { return law == CaptureLaw::kHinf ? "hinf" : "compliance"; }
inline const char* to_string(StabiliseLaw law) { return law == StabiliseLaw::kHinf ? "hinf" : "momentum"; }
inline const char* to_string(RigidiseLaw law) { return law == RigidiseLaw::kHinf ? "hinf" : "compliance"; }
inline const char* to_string(RigidiseSaturation s) { return s == RigidiseSaturation::kClip ? "clip" : "linear"; }

}  // namespace chaser::model
