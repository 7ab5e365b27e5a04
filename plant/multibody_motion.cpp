#include "plant/multibody_motion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>
#include <fmt/format.h>

#include "core/constants.hpp"
#include "core/rotation.hpp"
#include "plant/earth/gravity.hpp"
#include "plant/gravity_gradient.hpp"
#include "model/hub_mass_properties.hpp"
#include "plant/lvlh_eci.hpp"
#include "plant/multibody/mjcf.hpp"
#include "plant/multibody/weld.hpp"

namespace chaser::plant {

using model::BodyMassProperties;

namespace {

using multibody::guarded;
using multibody::MujocoModel;

Vec3 vec3_at(const mjtNum* p) { return Vec3(p[0], p[1], p[2]); }
void put_vec3(mjtNum* p, const Vec3& v) { p[0] = v.x(), p[1] = v.y(), p[2] = v.z(); }
Quat quat_at(const mjtNum* p) { return Quat(p[0], p[1], p[2], p[3]); }  // MuJoCo: w, x, y, z
void put_quat(mjtNum* p, const Quat& q) { p[0] = q.w(), p[1] = q.x(), p[2] = q.y(), p[3] = q.z(); }


// A free body's frame (its CoM): position and velocity in the world, attitude from body to world
// (ECI axes), rate in body axes (MuJoCo 2.2.2's free joint: qvel linear in world axes, angular in
// body axes).
struct FreeBody {
  Vec3 x_m, v_mps;
  Quat q_world_from_body;
  Vec3 omega_body_radps;
};
FreeBody free_body(const mjData& d, int qpos, int dof) {
  return {vec3_at(d.qpos + qpos), vec3_at(d.qvel + dof), quat_at(d.qpos + qpos + 3), vec3_at(d.qvel + dof + 3)};
}
void put_free_body(mjData& d, int qpos, int dof, const FreeBody& b) {
  put_vec3(d.qpos + qpos, b.x_m);
  put_quat(d.qpos + qpos + 3, b.q_world_from_body);
  put_vec3(d.qvel + dof, b.v_mps);
  put_vec3(d.qvel + dof + 3, b.omega_body_radps);
}

Quat attitude_ahead(const Quat& q, const Vec3& omega_body_radps, double dt_s) {  // first order, as period_environment
  Quat ahead;
  ahead.coeffs() = q.coeffs() + dt_s * quat_derivative(q, omega_body_radps);
  return ahead.normalized();
}

// The hub's point where the whole chaser's CoM is with the arm stowed: offset_body_m from the hub's CoM.
struct ChaserPoint {
  Vec3 x_m, v_mps;
};
ChaserPoint chaser_point(const FreeBody& hub, const Vec3& offset_body_m) {
  const Vec3 offset_world_m = hub.q_world_from_body * offset_body_m;
  return {hub.x_m + offset_world_m, hub.v_mps + hub.q_world_from_body * hub.omega_body_radps.cross(offset_body_m)};
}

Quat q_run_from_eci(const MultibodyMotionParams& p) {
  return Quat(p.earth.earth.dynamics.run_from_eci).normalized();
}

// The Earth-orbit view and the chaser's rigid state from the world now.
void read_back(const MultibodyMotionParams& p, MultibodyMotionState& s, RigidState& chaser) {
  const mjData& d = s.world.data();
  const FreeBody hub = free_body(d, p.index.hub_qpos, p.index.hub_dof);
  const FreeBody target = free_body(d, p.index.target_qpos, p.index.target_dof);
  const ChaserPoint c = chaser_point(hub, p.chaser_com_body_m - p.scene.hub_com_body_m);
  const Quat q_run = q_run_from_eci(p);
  OrbitState& o = s.earth.orbit;
  o.r_t_eci_m = s.r_ref_eci_m + target.x_m;
  o.v_t_eci_mps = s.v_ref_eci_mps + target.v_mps;
  o.dr_eci_m = c.x_m - target.x_m;
  o.dv_eci_mps = c.v_mps - target.v_mps;
  o.q_inertial_from_target = (q_run * target.q_world_from_body).normalized();
  o.omega_target_body_radps = target.omega_body_radps;
  chaser.q_inertial_from_body = (q_run * hub.q_world_from_body).normalized();
  chaser.omega_body_radps = hub.omega_body_radps;
  update_lvlh_view(p.earth.earth.dynamics, s.earth.env, o, chaser);
}

// The reference point's acceleration: the Earth-orbit plant's target model (gravity to J2 and the
// held slow terms, plant/orbit_propagator.cpp's accelerations()).
Vec3 reference_acceleration(const MultibodyMotionParams& p, const PeriodEnvironment& env, const Vec3& r_eci_m) {
  return earth::gravity_acceleration_eci(p.earth.earth.dynamics.perturbations.gravity, r_eci_m) + env.slow.target_eci_mps2;
}

// One classical RK4 step of the reference point over h.
void step_reference(const MultibodyMotionParams& p, const PeriodEnvironment& env, Vec3& r, Vec3& v, double h) {
  const Vec3 a1 = reference_acceleration(p, env, r);
  const Vec3 v2 = v + 0.5 * h * a1, a2 = reference_acceleration(p, env, r + 0.5 * h * v);
  const Vec3 v3 = v + 0.5 * h * a2, a3 = reference_acceleration(p, env, r + 0.5 * h * v2);
  const Vec3 v4 = v + h * a3, a4 = reference_acceleration(p, env, r + h * v3);
  r += (h / 6.0) * (v + 2.0 * v2 + 2.0 * v3 + v4);
  v += (h / 6.0) * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
}

// What one piece holds constant.
struct PieceLoads {
  Vec3 force_hub_body_N = Vec3::Zero();    // [N] thrust, body axes
  Vec3 torque_hub_body_Nm = Vec3::Zero();  // [N m] thrust + disturbance + environment, about the hub's CoM
  Vec3 force_dist_eci_N = Vec3::Zero();    // [N] the disturbance force, spread over the chaser by mass
  Vec3 slow_relative_eci_mps2 = Vec3::Zero();  // [m/s^2] the chaser's differential slow terms
  double mass_flow_kgps = 0.0;
};

PieceLoads piece_loads(const MultibodyMotionParams& p, const MultibodyMotionState& s, const PieceInput& u) {
  PieceLoads l;
  l.force_hub_body_N = u.force_body_N;
  // The thruster model's torque is about the chaser's CoM c; about the hub's, c_h: + (c - c_h) x F.
  l.torque_hub_body_Nm = u.torque_body_Nm + (p.chaser_com_body_m - p.scene.hub_com_body_m).cross(u.force_body_N) +
                         s.earth.env.torque_chaser_body_Nm;
  if (!u.force_lvlh_N.isZero(0.0))  // LVLH at the piece start, as propagate_orbit_piece rotates it
    l.force_dist_eci_N = lvlh_axes_from_eci(s.earth.orbit.r_t_eci_m, s.earth.orbit.v_t_eci_mps).transpose() * u.force_lvlh_N;
  l.slow_relative_eci_mps2 = s.earth.env.slow.relative_eci_mps2;
  l.mass_flow_kgps = u.mass_flow_kgps;
  return l;
}

// The applied wrench of every body for the step [t, t + h], each at the step's midpoint (the
// header's equations), as generalised forces held over the step (qfrc_applied). Needs the world's
// kinematics at t (MujocoModel::step_applying runs it where MuJoCo has evaluated them).
//
// Why not xfrc_applied: MuJoCo maps a body's world wrench through that body's Jacobian at each of
// RK4's four stages (mj_applyFT, 12 bodies: 11 % of a reach run). Here each link's wrench is mapped
// once, through the Jacobian at the step's start. The joints turn by w h in a step, so the mapping is
// off by ~w h / 2 relative: at 0.1 rad/s and h = 1 ms, 5e-5 of a link's tide (~1e-4 N), 5e-9 N. The
// hub and the target are free roots whose frames are their CoMs: a force there acts on the free
// joint's linear dofs (world axes) and a torque on its angular ones (body axes), exactly, with no
// Jacobian; so the thrusters' and the target's body-fixed torques enter in body axes as they are,
// and the hub's thrust at its midpoint attitude as before.
void apply_loads(const MultibodyMotionParams& p, MultibodyMotionState& s, const PieceLoads& l, double chaser_kg,
                 double h) {
  const mjModel& m = s.world.model();
  mjData& d = s.world.data();
  const MultibodyIndices& ix = p.index;
  const PeriodEnvironment& env = s.earth.env;
  const earth::GravityParams& gravity = p.earth.earth.dynamics.perturbations.gravity;
  const double half = 0.5 * h;
  const Vec3 r_ref_mid = s.r_ref_eci_m + half * s.v_ref_eci_mps + (0.5 * half * half) * reference_acceleration(p, env, s.r_ref_eci_m);
  mju_zero(d.qfrc_applied, m.nv);
  const auto add_to_root = [&d](int dof, const Vec3& force_world_N, const Vec3& torque_body_Nm) {
    for (int k = 0; k < 3; ++k) d.qfrc_applied[dof + k] += force_world_N[k], d.qfrc_applied[dof + 3 + k] += torque_body_Nm[k];
  };
  for (int b = 1; b < m.nbody; ++b) {
    mjtNum velocity[6];  // angular, linear at the body's CoM, world axes
    mj_objectVelocity(&m, &d, mjOBJ_BODY, b, velocity, 0);
    const Vec3 x_mid = vec3_at(d.xipos + 3 * b) + half * vec3_at(velocity + 3);
    const double mass_kg = m.body_mass[b];
    Vec3 force = mass_kg * earth::differential_gravity_eci(gravity, r_ref_mid, x_mid);
    if (b == ix.target) {
      add_to_root(ix.target_dof, force, Vec3::Zero());
      continue;
    }
    force += mass_kg * l.slow_relative_eci_mps2 + (mass_kg / chaser_kg) * l.force_dist_eci_N;
    if (b == ix.hub) {
      add_to_root(ix.hub_dof, force, Vec3::Zero());
      continue;
    }
    Vec3 torque = Vec3::Zero();
    if (p.earth.earth.dynamics.chaser.gravity_gradient) {
      const Vec3 r = r_ref_mid + x_mid;  // a link's own inertia, world axes, at the step's start
      const Eigen::Map<const Eigen::Matrix<mjtNum, 3, 3, Eigen::RowMajor>> world_from_inertial(d.ximat + 9 * b);
      const Mat3 inertia = world_from_inertial * vec3_at(m.body_inertia + 3 * b).asDiagonal() * world_from_inertial.transpose();
      torque = gravity_gradient_torque_body(gravity_gradient_gain(gravity.mu_m3ps2, r.squaredNorm()), r, inertia);
    }
    mj_applyFT(&m, &d, force.data(), torque.data(), d.xipos + 3 * b, b, d.qfrc_applied);
  }
  const FreeBody hub = free_body(d, ix.hub_qpos, ix.hub_dof);
  const Quat q_hub_mid = attitude_ahead(hub.q_world_from_body, hub.omega_body_radps, half);
  add_to_root(ix.hub_dof, q_hub_mid * l.force_hub_body_N, l.torque_hub_body_Nm);
  add_to_root(ix.target_dof, Vec3::Zero(), env.torque_target_body_Nm);
}

// The hub's mass while the thrusters burn: the chaser's less the arm's, and the subtree masses
// MuJoCo's mj_comPos divides by (compiled constants, kept consistent by hand).
void set_hub_mass(const MultibodyMotionParams& p, MultibodyMotionState& s, double hub_kg) {
  mjModel& m = s.world.mutable_model();
  const MultibodyIndices& ix = p.index;
  m.body_mass[ix.hub] = hub_kg;
  m.body_subtreemass[ix.hub] = hub_kg + m.body_subtreemass[ix.first_link];
  m.body_subtreemass[0] = m.body_subtreemass[ix.hub] + m.body_subtreemass[ix.target];
}

// Each braked joint's load at the step's start: its friction row's constraint force (a row per dof
// with frictionloss, Jacobian the unit vector: the force is the torque about the joint). Read from
// the step's first evaluation, whose state is the step's start: RK4's later stages leave their own
// intermediate evaluations in efc_force.
void read_brake_loads(const MultibodyMotionParams& p, const mjData& d, std::array<double, model::kArmJoints>& load_Nm) {
  load_Nm.fill(0.0);
  for (int i = 0; i < d.nefc; ++i) {
    const int j = d.efc_id[i] - p.index.joint1_dof;
    if (d.efc_type[i] == mjCNSTR_FRICTION_DOF && j >= 0 && j < model::kArmJoints)
      load_Nm[static_cast<std::size_t>(j)] = d.efc_force[i];
  }
}

// The berthing's loads at the step's start (as the brakes'): the tip's contact with the drogue, the
// sum of its contacts' normal forces, and the berth weld's force (its three translational rows),
// each kept at its largest.
void read_berth_loads(const MultibodyMotionParams& p, const mjModel& m, const mjData& d, BerthState& b) {
  double contact_N = 0.0;
  for (int c = 0; c < d.ncon; ++c) {
    if (d.contact[c].geom1 != p.index.probe_geom && d.contact[c].geom2 != p.index.probe_geom) continue;
    mjtNum force[6];
    mj_contactForce(&m, &d, c, force);
    contact_N += force[0];
  }
  b.peak_contact_N = std::max(b.peak_contact_N, contact_N);
  if (!b.latched) return;
  Vec3 hold = Vec3::Zero();
  int rows = 0;
  for (int i = 0; i < d.nefc && rows < 3; ++i)
    if (d.efc_type[i] == mjCNSTR_EQUALITY && d.efc_id[i] == p.index.berth) hold(rows++) = d.efc_force[i];
  b.peak_hold_N = std::max(b.peak_hold_N, hold.norm());
}

void integrate_piece(const MultibodyMotionParams& p, MultibodyMotionState& s, RigidState& chaser, TimeNs dt_ns,
                     const PieceInput& u) {
  const double dt_s = to_seconds(dt_ns);
  const double step_s = s.brakes_engaged && s.braked_step_s > 0.0 ? s.braked_step_s : p.scene.timestep_s;
  const int steps = std::max(1, static_cast<int>(std::ceil(dt_s / step_s * (1.0 - 1e-12))));
  const double h = dt_s / steps;
  s.world.mutable_model().opt.timestep = h;
  const PieceLoads loads = piece_loads(p, s, u);
  for (int k = 0; k < steps; ++k) {
    if (loads.mass_flow_kgps != 0.0) set_hub_mass(p, s, chaser.mass_kg - 0.5 * h * loads.mass_flow_kgps - p.arm_mass_kg);
    s.world.step_applying([&] { apply_loads(p, s, loads, chaser.mass_kg - 0.5 * h * loads.mass_flow_kgps, h); },
                          [&](const mjData& d) {
                            if (s.brakes_engaged) read_brake_loads(p, d, s.brake_load_Nm);
                            if (p.index.probe_geom >= 0) read_berth_loads(p, s.world.model(), d, s.berth);
                          });
    step_reference(p, s.earth.env, s.r_ref_eci_m, s.v_ref_eci_mps, h);
    chaser.mass_kg -= h * loads.mass_flow_kgps;
  }
}

}  // namespace

namespace {

// The tip against the socket now (positions of the current qpos): its centre from the socket and
// the tool's attitude from the fixture's (the angle), in the fixture's axes.
struct SocketView {
  Vec3 tip_from_socket_m = Vec3::Zero();
  double attitude_rad = 0.0;
};
SocketView socket_view(const MultibodyMotionParams& p, MultibodyMotionState& s) {
  const mjModel& m = s.world.model();
  mjData& d = s.world.data();
  multibody::guarded("the probe against the socket", [&m, &d] { mj_kinematics(&m, &d); });
  const Quat q_world_from_target = multibody::body_attitude(d, p.index.target).normalized();
  const Quat q_world_from_fixture = (q_world_from_target * p.scene.q_target_from_fixture).normalized();
  const Vec3 socket = multibody::body_position(d, p.index.target) + q_world_from_target * p.scene.fixture_target_m;
  Mat3 world_from_tool;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) world_from_tool(i, j) = d.site_xmat[9 * p.index.tool_site + 3 * i + j];
  SocketView v;
  v.tip_from_socket_m = q_world_from_fixture.conjugate() * (Vec3(d.site_xpos + 3 * p.index.tool_site) - socket);
  v.attitude_rad = Eigen::AngleAxisd(q_world_from_fixture.conjugate() * Quat(world_from_tool)).angle();
  return v;
}

// The berthing's mechanisms after each advance (t_s its end): the latches close on a tip within
// latch_radius_m of the socket (the soft dock: the weld engaged at that pose, with the soft dock's
// time constant); once the retraction is commanded the weld's pose is drawn from the latched one to
// the mated one along a quintic (the probe's tip drawn retraction_m into the end effector, the pins
// aligning the axes: the fixture's axes on the tool's), and at its end the weld stiffens to the
// locks' time constant: the hard dock. A latch outside the pins' envelope jams them: no retraction.
void update_berthing(const MultibodyMotionParams& p, MultibodyMotionState& s, double t_s) {
  BerthState& b = s.berth;
  if (!p.berthing || b.hard_docked) return;
  const model::BerthingParams& c = *p.berthing;
  if (!b.latched) {
    const SocketView v = socket_view(p, s);
    if (v.tip_from_socket_m.norm() > c.latch_radius_m) return;
    multibody::engage_weld_here(s.world, p.index.berth);
    multibody::set_weld_timeconst(s.world, p.index.berth, c.soft_dock_timeconst_s);
    // The latches carry the tip from now on and the probe's shaft slides into the end effector as
    // it retracts: the tip's contact with the drogue, internal to the mechanism, is switched off.
    s.world.mutable_model().opt.disableflags |= mjDSBL_CONTACT;
    b.latched = true;
    b.latch_s = t_s;
    b.latch_offset_m = v.tip_from_socket_m;
    b.latch_attitude_rad = v.attitude_rad;
    b.pins_jammed = v.tip_from_socket_m.tail<2>().norm() > c.pin_position_tol_m ||
                    v.attitude_rad > c.pin_attitude_tol_deg * kDegToRad;
    b.latched_pose = multibody::weld_pose(s.world, p.index.berth);
    // Mated: the tool's axes the fixture's, the socket retraction_m behind the tool point along x.
    const Quat q_fixture_from_target = p.scene.q_target_from_fixture.normalized().conjugate();
    b.mated_pose.p_m = p.scene.arm.gripper.position_link7_m - c.retraction_m * Vec3::UnitX() -
                       q_fixture_from_target * p.scene.fixture_target_m;
    b.mated_pose.q_rel = q_fixture_from_target;
    return;
  }
  if (b.pins_jammed || !b.retract_requested) return;
  if (b.retract_from_s < 0.0) b.retract_from_s = t_s;
  const double tau = std::clamp((t_s - b.retract_from_s) / c.retraction_duration_s, 0.0, 1.0);
  const double blend = tau * tau * tau * (10.0 - 15.0 * tau + 6.0 * tau * tau);  // rest to rest
  multibody::set_weld_pose(s.world, p.index.berth,
                           {(1.0 - blend) * b.latched_pose.p_m + blend * b.mated_pose.p_m,
                            b.latched_pose.q_rel.slerp(blend, b.mated_pose.q_rel)});
  if (tau >= 1.0) {
    // The pins lock the interfaces where the soft hold has drawn them (within its lag of the mated
    // pose): the weld engaged at the pose of this moment, stiff. Stiffened at the mated pose itself,
    // it would snap the lag shut in two steps (233 N on the latches for 1 ms in comrade_berth).
    multibody::engage_weld_here(s.world, p.index.berth);
    const multibody::WeldPose now = multibody::weld_pose(s.world, p.index.berth);
    b.mate_offset_m = (now.p_m - b.mated_pose.p_m).norm();
    b.mate_attitude_rad = Eigen::AngleAxisd(b.mated_pose.q_rel.conjugate() * now.q_rel).angle();
    multibody::set_weld_timeconst(s.world, p.index.berth, p.scene.lock_timeconst_s);
    b.hard_docked = true;
    b.hard_dock_s = t_s;
  }
}

}  // namespace

MultibodyIndices indices_of(const multibody::MujocoModel& world) {
  const mjModel& m = world.model();
  MultibodyIndices i;
  i.hub = world.body("hub");
  i.target = world.body("target");
  i.first_link = world.body("link1");
  const int hub_free = world.joint("hub_free"), target_free = world.joint("target_free"), joint1 = world.joint("joint1");
  i.hub_qpos = m.jnt_qposadr[hub_free];
  i.hub_dof = m.jnt_dofadr[hub_free];
  i.target_qpos = m.jnt_qposadr[target_free];
  i.target_dof = m.jnt_dofadr[target_free];
  i.joint1_qpos = m.jnt_qposadr[joint1];
  i.joint1_dof = m.jnt_dofadr[joint1];
  i.lock1 = mj_name2id(&m, mjOBJ_EQUALITY, "lock1");
  i.grasp = mj_name2id(&m, mjOBJ_EQUALITY, "grasp");
  i.motor1 = mj_name2id(&m, mjOBJ_ACTUATOR, "motor1");
  i.fixture_geom = mj_name2id(&m, mjOBJ_GEOM, "fixture");
  i.probe_geom = mj_name2id(&m, mjOBJ_GEOM, "probe_tip");
  i.drogue_first_geom = mj_name2id(&m, mjOBJ_GEOM, "drogue0");
  i.berth = mj_name2id(&m, mjOBJ_EQUALITY, "berth");
  i.tool_site = mj_name2id(&m, mjOBJ_SITE, "tool");
  const char* fingers[2] = {"finger_a", "finger_b"};
  for (std::size_t f = 0; f < 2; ++f) {
    const int joint = mj_name2id(&m, mjOBJ_JOINT, fingers[f]);
    if (joint < 0) continue;
    i.finger_qpos[f] = m.jnt_qposadr[joint];
    i.finger_actuator[f] = mj_name2id(&m, mjOBJ_ACTUATOR, fingers[f]);
    i.finger_geom[f] = mj_name2id(&m, mjOBJ_GEOM, fingers[f]);
  }
  return i;
}

std::optional<std::string> multibody_problem(const model::Scenario& scenario) {
  if (!scenario.chaser.arm) return "chaser.arm: the multibody plant flies the arm, and the scenario has none";
  if (!scenario.orbit.earth || !scenario.target.body)
    return "orbit.earth and target.body: the multibody plant flies the perturbed Earth orbit's bodies";
  if (scenario.chaser.slosh)
    return "chaser.slosh: the multibody plant has no slosh yet (its tanks are not coupled to the hub): fly it "
           "without chaser.slosh";
  return hub_problem(scenario.chaser, hub_mass_properties(scenario.chaser, *scenario.chaser.arm));
}

MultibodyStart start_multibody(const model::Scenario& scenario, const EarthOrbitState& from, const RigidState& chaser,
                               double scene_timestep_s) {
  const model::ArmParams& arm = *scenario.chaser.arm;
  const BodyMassProperties hub = hub_mass_properties(scenario.chaser, arm);
  MultibodyMotionParams p;
  p.earth = make_earth_orbit_params(scenario);
  p.earth.earth.dynamics.hold_slow_environment = true;  // the forces are held per step: see the header
  p.earth.earth.dynamics.chaser.inertia_kgm2 = hub.inertia_kgm2;  // its gravity gradient: the hub's own
  p.earth.earth.dynamics.chaser.inertia_inv = hub.inertia_kgm2.inverse();
  p.chaser_com_body_m = scenario.chaser.com_body_m;
  p.arm_mass_kg = scenario.chaser.mass_kg - hub.mass_kg;
  model::MultibodySceneParams& scene = p.scene;
  scene.hub_mass_kg = chaser.mass_kg - p.arm_mass_kg;  // the propellant used so far is the hub's
  scene.hub_inertia_kgm2 = hub.inertia_kgm2;
  scene.hub_com_body_m = hub.com_body_m;
  scene.arm = arm;
  scene.target_mass_kg = scenario.target.body->mass_kg;
  scene.target_inertia_kgm2 = scenario.target.body->inertia_kgm2;
  scene.target_position_m = Vec3::Zero();
  scene.target_shape = scenario.target.body->keep_out;
  scene.timestep_s = scene_timestep_s;
  scene.arm_locks = true;
  scene.grasp_weld = true;
  if (scenario.capture && scenario.guidance.synchronised) {
    scene.fixture_target_m = scenario.target.body->grasp_point_target_m;
    scene.q_target_from_fixture = scenario.guidance.synchronised->q_target_from_body.normalized();
    if (const auto& berthing = scenario.capture->berthing) {  // ASSIST: the probe and the drogue, in contact
      scene.berth_contact = true;
      scene.drogue = {.tip_radius_m = berthing->probe_tip_radius_m,
                      .mouth_radius_m = berthing->drogue_mouth_radius_m,
                      .throat_radius_m = berthing->probe_tip_radius_m + berthing->socket_clearance_m,
                      .depth_m = berthing->drogue_depth_m,
                      .friction = berthing->friction};
      p.berthing = *berthing;
    } else {  // the jaws and the fixture's lip, in contact: the capture's grasp
      scene.grasp_contact = true;
      scene.fixture = scenario.target.body->fixture;
    }
  }
  // The locks as stiff as MuJoCo's step allows (time constant 2 h, MuJoCo's stated limit) and 99 %
  // enforced: the stowed arm then gives under the chaser's spin by (1 - d) a0 / (d k), 1.7e-7 rad at
  // 0.5 rad/s (the defaults, 0.02 s and 0.9, gave 2e-4 rad, and the hub 4e-4 m off the rigid plant).
  scene.lock_timeconst_s = 2.0 * scene_timestep_s;
  scene.lock_impedance = 0.99;
  MultibodyMotionState s{.world = MujocoModel(multibody::mjcf_of(scene)), .earth = from};
  p.index = indices_of(s.world);

  // The reference point at the target's CoM: the target at the world's origin, at rest in it.
  const OrbitState& o = from.orbit;
  s.r_ref_eci_m = o.r_t_eci_m;
  s.v_ref_eci_mps = o.v_t_eci_mps;
  const Quat q_eci_from_run = q_run_from_eci(p).conjugate();
  mjData& d = s.world.data();
  put_free_body(d, p.index.target_qpos, p.index.target_dof,
                {Vec3::Zero(), Vec3::Zero(), (q_eci_from_run * o.q_inertial_from_target).normalized(),
                 o.omega_target_body_radps});
  // The hub where the rigid chaser is: its CoM point at dr, moving at dv, turning at omega.
  const Quat q_hub = (q_eci_from_run * chaser.q_inertial_from_body).normalized();
  const Vec3 offset_body_m = p.chaser_com_body_m - p.scene.hub_com_body_m;
  put_free_body(d, p.index.hub_qpos, p.index.hub_dof,
                {o.dr_eci_m - q_hub * offset_body_m,
                 o.dv_eci_mps - q_hub * chaser.omega_body_radps.cross(offset_body_m), q_hub, chaser.omega_body_radps});
  for (int j = 0; j < model::kArmJoints; ++j) {
    d.qpos[p.index.joint1_qpos + j] = arm.stowed_rad[static_cast<std::size_t>(j)];
    d.qvel[p.index.joint1_dof + j] = 0.0;
  }
  s.world.forward();
  return {std::move(p), std::move(s)};
}

EarthOrbitState earth_orbit_state(const MultibodyMotionState& state) { return state.earth; }

void set_joint_torques(MultibodyMotionState& state, const std::array<double, model::kArmJoints>& torque_Nm) {
  state.joint_torque_Nm = torque_Nm;
}

// A brake's friction is a stiffer constraint than the drives' (MuJoCo's default, 0.02 s and
// impedance 0.9, lets a joint carrying 80 % of its friction creep at ~0.4 deg/s: in its soft
// model a sticking row resists only d of the load, and damps the rest at b = 2 / (d_max T)).
// Impedance 0.999 and a time constant of two 1 ms steps (the least MuJoCo's refsafe allows) make
// the creep (1 - d) / (d b) of it: ~1e3 x smaller.
constexpr double kBrakeTimeconstS = 0.002;
constexpr double kBrakeImpedance = 0.999;

void engage_brakes(const MultibodyMotionParams& params, MultibodyMotionState& state) {
  mjModel& m = state.world.mutable_model();
  for (int j = 0; j < model::kArmJoints; ++j) {
    const int dof = params.index.joint1_dof + j;
    m.dof_frictionloss[dof] = params.scene.arm.brake_holding_torque_Nm;
    m.dof_solref[mjNREF * dof] = kBrakeTimeconstS;
    m.dof_solref[mjNREF * dof + 1] = 1.0;
    m.dof_solimp[mjNIMP * dof] = kBrakeImpedance;
    m.dof_solimp[mjNIMP * dof + 1] = kBrakeImpedance;
  }
  state.brakes_engaged = true;
  m.opt.integrator = params.braked_integrator;
}

void set_braked_step(const MultibodyMotionParams& params, MultibodyMotionState& state, double step_s) {
  if (!state.brakes_engaged) throw std::logic_error("set_braked_step: the brakes do not hold");
  if (!(step_s > 0.0)) throw std::invalid_argument("set_braked_step: the step must be > 0 s");
  if (state.braked_step_s == step_s) return;
  state.braked_step_s = step_s;
  // The drives are off, braked: their torque loops' states are zeroed and their lag made at least a
  // step. MuJoCo 2.2 integrates a filter's activation by explicit Euler, which diverges for a step
  // over twice its time constant (the drives' 1 / 300 rad/s = 3.3 ms against 10 ms).
  mjModel& m = state.world.mutable_model();
  const int act1 = multibody::activation_index(m, params.index.motor1);
  for (int j = 0; j < model::kArmJoints; ++j) {
    double& timeconst_s = m.actuator_dynprm[mjNDYN * (params.index.motor1 + j)];
    timeconst_s = std::max(timeconst_s, step_s);
    state.world.data().act[act1 + j] = 0.0;
  }
}

void lock_arm(const MultibodyMotionParams& params, MultibodyMotionState& state, bool locked) {
  for (int j = 0; j < model::kArmJoints; ++j) state.world.mutable_model().eq_active[params.index.lock1 + j] = locked;
}

void command_jaws(const MultibodyMotionParams& params, MultibodyMotionState& state, bool closed) {
  if (params.index.fixture_geom < 0) return;
  for (std::size_t f = 0; f < 2; ++f)  // locked: each finger held where it was at the lock
    state.world.data().ctrl[params.index.finger_actuator[f]] =
        state.jaws_locked ? state.locked_finger_m[f] : closed ? params.scene.arm.gripper.jaws.open_half_gap_m : 0.0;
}

JawReading read_jaws(const MultibodyMotionParams& params, const MultibodyMotionState& state) {
  JawReading r;
  if (params.index.fixture_geom < 0) return r;
  const mjData& d = state.world.data();
  const model::JawParams& jaws = params.scene.arm.gripper.jaws;
  r.opening_m = 2.0 * jaws.open_half_gap_m - d.qpos[params.index.finger_qpos[0]] - d.qpos[params.index.finger_qpos[1]];
  std::array<bool, 2> touching{};
  for (int c = 0; c < d.ncon; ++c) {
    const mjContact& contact = d.contact[c];
    for (std::size_t f = 0; f < 2; ++f) {
      const int finger = params.index.finger_geom[f], fixture = params.index.fixture_geom;
      if ((contact.geom1 == finger && contact.geom2 == fixture) || (contact.geom1 == fixture && contact.geom2 == finger))
        touching[f] = true;
    }
  }
  r.holding = state.jaws_locked || (touching[0] && touching[1]);
  return r;
}

// The rigid closure: the weld carries the grasp from now on, so the jaws' contact with the lip,
// whose forces are internal to gripper and target once they are welded, is switched off (it
// doubled a step's constraint solve: 68 against 36 ms per simulated second) and each finger is held
// by its servo where it was at the lock.
void engage_grasp(const MultibodyMotionParams& params, MultibodyMotionState& state) {
  multibody::engage_weld_here(state.world, params.index.grasp);
  mjData& d = state.world.data();
  for (std::size_t f = 0; f < 2; ++f) state.locked_finger_m[f] = d.qpos[params.index.finger_qpos[f]];
  state.jaws_locked = true;
  state.world.mutable_model().opt.disableflags |= mjDSBL_CONTACT;
  command_jaws(params, state, true);
}

void command_probe_retraction(const MultibodyMotionParams& params, MultibodyMotionState& state) {
  if (params.berthing && state.berth.latched) state.berth.retract_requested = true;
}

bool probe_latched(const MultibodyMotionState& state) { return state.berth.latched; }
bool probe_hard_docked(const MultibodyMotionState& state) { return state.berth.hard_docked; }

void set_closed_chain_joint_rates(const MultibodyMotionParams& params, MultibodyMotionState& state,
                                  const std::array<double, model::kArmJoints>& rates_radps) {
  if (!grasp_engaged(params, state)) throw std::logic_error("set_closed_chain_joint_rates: the grasp is not engaged");
  state.world.forward();  // the bodies' poses and inertias at the state now
  const mjModel& m = state.world.model();
  mjData& d = state.world.data();
  const int nv = m.nv;
  using Rows = Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor>;
  Rows jacp(3, nv), jacr(3, nv), jacp_t(3, nv), jacr_t(3, nv);
  // The momentum's map, p = A v: each body's m v_com and, about the world's origin, I w + r x m v_com.
  Eigen::MatrixXd momentum = Eigen::MatrixXd::Zero(6, nv);
  for (int b = 1; b < m.nbody; ++b) {
    const Vec3 com(d.xipos + 3 * b);
    mj_jac(&m, &d, jacp.data(), jacr.data(), com.data(), b);
    const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> world_from_principal(d.ximat + 9 * b);
    const Mat3 inertia = world_from_principal * Vec3(m.body_inertia + 3 * b).asDiagonal() * world_from_principal.transpose();
    momentum.topRows(3) += m.body_mass[b] * jacp;
    momentum.bottomRows(3) += inertia * jacr + m.body_mass[b] * skew(com) * jacp;
  }
  // The weld: link 7's (the gripper's) motion at the target's CoM less the target's.
  const int gripper = params.index.first_link + model::kArmJoints, target = params.index.target;
  const Vec3 target_com(d.xipos + 3 * target);
  mj_jac(&m, &d, jacp.data(), jacr.data(), target_com.data(), gripper);
  mj_jac(&m, &d, jacp_t.data(), jacr_t.data(), target_com.data(), target);
  Eigen::MatrixXd weld(6, nv);
  weld << jacp - jacp_t, jacr - jacr_t;

  Eigen::Map<Eigen::VectorXd> qvel(d.qvel, nv);
  const Eigen::VectorXd momentum_before = momentum * qvel;
  for (int j = 0; j < model::kArmJoints; ++j) qvel(params.index.joint1_dof + j) = rates_radps[static_cast<std::size_t>(j)];
  // Unknowns: the hub's 6 and the target's 6 velocities; the rest as set.
  std::array<int, 12> unknown{};
  for (int k = 0; k < 6; ++k) unknown[static_cast<std::size_t>(k)] = params.index.hub_dof + k;
  for (int k = 0; k < 6; ++k) unknown[static_cast<std::size_t>(6 + k)] = params.index.target_dof + k;
  Eigen::VectorXd known = qvel;
  for (const int i : unknown) known(i) = 0.0;
  Eigen::Matrix<double, 12, 12> lhs;
  Eigen::Matrix<double, 12, 1> rhs;
  for (std::size_t c = 0; c < unknown.size(); ++c) {
    lhs.block<6, 1>(0, static_cast<int>(c)) = weld.col(unknown[c]);
    lhs.block<6, 1>(6, static_cast<int>(c)) = momentum.col(unknown[c]);
  }
  rhs.head<6>() = -weld * known;
  rhs.tail<6>() = momentum_before - momentum * known;
  const Eigen::Matrix<double, 12, 1> x = lhs.fullPivLu().solve(rhs);
  for (std::size_t c = 0; c < unknown.size(); ++c) qvel(unknown[c]) = x(static_cast<int>(c));
  state.world.forward();
}

bool grasp_engaged(const MultibodyMotionParams& params, const MultibodyMotionState& state) {
  return multibody::weld_engaged(state.world, params.index.grasp);
}

std::array<double, model::kArmJoints> joint_angles_rad(const MultibodyMotionParams& params,
                                                       const MultibodyMotionState& state) {
  std::array<double, model::kArmJoints> q{};
  for (int j = 0; j < model::kArmJoints; ++j) q[static_cast<std::size_t>(j)] = state.world.data().qpos[params.index.joint1_qpos + j];
  return q;
}

std::array<double, model::kArmJoints> joint_rates_radps(const MultibodyMotionParams& params,
                                                        const MultibodyMotionState& state) {
  std::array<double, model::kArmJoints> w{};
  for (int j = 0; j < model::kArmJoints; ++j) w[static_cast<std::size_t>(j)] = state.world.data().qvel[params.index.joint1_dof + j];
  return w;
}

std::array<double, model::kArmJoints> brake_loads_Nm(const MultibodyMotionParams&, const MultibodyMotionState& state) {
  return state.brake_load_Nm;
}

std::array<double, model::kArmJoints> joint_torques_applied_Nm(const MultibodyMotionParams& params,
                                                               const MultibodyMotionState& state) {
  std::array<double, model::kArmJoints> tau{};
  const int act1 = multibody::activation_index(state.world.model(), params.index.motor1);
  for (int j = 0; j < model::kArmJoints; ++j) tau[static_cast<std::size_t>(j)] = state.world.data().act[act1 + j];
  return tau;
}

void begin_period(const MultibodyMotionParams& params, MultibodyMotionState& state, const RigidState& chaser,
                  TimeNs t_k, TimeNs period_ns) {
  begin_period(params.earth, state.earth, chaser, t_k, period_ns);
}

void advance(const MultibodyMotionParams& params, MultibodyMotionState& state, RigidState& chaser,
             const ThrustProfile& profile, const PeriodDisturbance& disturbance, TimeNs from_ns, TimeNs to_ns) {
  for (int j = 0; j < model::kArmJoints; ++j)
    state.world.data().ctrl[params.index.motor1 + j] = state.joint_torque_Nm[static_cast<std::size_t>(j)];
  for (int i = 0; i < profile.count; ++i) {
    const ThrustPiece& piece = profile.pieces[i];
    const TimeNs begin_ns = std::max(piece.t_begin_ns, from_ns), end_ns = std::min(piece.t_end_ns, to_ns);
    if (end_ns <= begin_ns) continue;
    integrate_piece(params, state, chaser, end_ns - begin_ns, piece_input(piece, disturbance));
    read_back(params, state, chaser);  // the next piece's LVLH (disturbance) at its start
  }
  read_back(params, state, chaser);
  update_berthing(params, state, to_seconds(to_ns));
}

TargetRotation target_rotation(const MultibodyMotionParams&, const MultibodyMotionState& state, double) {
  return {state.earth.orbit.q_inertial_from_target, state.earth.orbit.omega_target_body_radps};
}

Quat q_inertial_from_lvlh(const MultibodyMotionParams& params, const MultibodyMotionState& state,
                          const model::TargetOrbit&, double) {
  return q_inertial_from_lvlh(params.earth.earth.dynamics, state.earth.orbit);
}

std::span<const model::SloshState> slosh_states(const MultibodyMotionParams&, const MultibodyMotionState&) {
  return {};
}

}  // namespace chaser::plant
